#pragma once

#include <QDateTime>
#include <QString>

#include <optional>

namespace DriveDesk {

// What became of a value written. Unknown until the drive's answer came, and for good when it
// never came: whether the drive took it cannot be said.
enum class JournalOutcome : quint8 { Unknown, Written, Refused };

// "written", "refused", "unknown": the words the journal file, JSON and CSV keep, in any
// language; nothing for another word.
QString journalOutcomeName(JournalOutcome outcome);
std::optional<JournalOutcome> journalOutcomeFromName(const QString &name);

// One value of a parameter: the raw integer the drive holds and how the drive shows it (scaled
// with its unit, or its plaintext). Either may be missing: a value never read has neither.
struct JournalValue
{
    std::optional<qint32> raw;
    QString text;

    bool isEmpty() const { return !raw && text.isEmpty(); }
    bool operator==(const JournalValue &) const = default;
};

// The drive a value was written to: how it was reached and what it said it is.
struct JournalDrive
{
    QString link; // as the user gave it: "serial:/dev/ttyUSB0", "tcp:10.0.0.5:5020", "sim"
    QString protocol; // "hsp5", "din66019ii", "din66019"
    std::optional<int> address; // on a DIN66019(II) bus; none on HSP5
    QString kind; // the identification: inverter type and power unit
    QString softwareVersion;
    QString serialNumber; // empty for a drive that has none

    // How the journal command names the drive: its serial number, else "LINK@ADDRESS" (or the
    // link alone without an address).
    QString name() const;
    // Whether `other` is this drive: the same identification (kind, software, serial number);
    // where there is no serial number to tell two drives of a kind apart, on the same link and
    // bus address too.
    bool isSameDrive(const JournalDrive &other) const;
    bool operator==(const JournalDrive &) const = default;
};

// One value written to one set of one parameter of one drive, with what the drive held before,
// what it held after, and what became of the write. Stored before the telegram is sent
// (outcome Unknown) and completed when the answer came (Journal).
struct JournalEntry
{
    qint64 id = 0; // given by the journal, counting up in the order entries begin
    QDateTime time; // UTC: when the entry was begun, before the telegram went out
    QDateTime completedTime; // UTC: when the answer came; invalid while there is none
    QString user; // login name
    QString host;
    QString program; // "drivedesk 0.1.0" (the window), "drivedesk-cli 0.1.0"
    qint64 jobId = 0; // Journal::beginJob(); 0: none
    QString jobDescription; // "edit", "download of f5.json", "revert of entries 12..15"
    JournalDrive drive;
    QString parameterId; // "op.28", or "0A1Ch" where the drive names no group
    quint16 parameterAddress = 0;
    QString parameterName;
    std::optional<int> set; // 0..7; none: the active set, or a parameter without sets
    // A password entered (ud.01): the entry says so, its values are never stored.
    bool password = false;
    JournalValue before;
    JournalValue written;
    JournalValue readBack;
    JournalOutcome outcome = JournalOutcome::Unknown;
    QString reason; // refused: the drive's reason in words; unknown: why, if known

    // "written", "refused: <reason>", "unknown" (": <reason>" where one is known), in the
    // installed language: the one text the window, the reports and the command line show.
    QString outcomeText() const;
    // The change as a value's tooltip names it: "7.50 s since 10:42 by anna, was 5.00 s" (the
    // date too where the change was not on `now`'s day), in the installed language.
    QString changeText(const QDateTime &now = QDateTime::currentDateTime()) const;
};

} // namespace DriveDesk
