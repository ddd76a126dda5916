#pragma once

#include "journal/JournalEntry.h"
#include "session/ValueChange.h"

#include <QCoreApplication>
#include <QList>

#include <array>
#include <functional>
#include <optional>

namespace DriveDesk {

class Journal;
struct ConnectionSettings;

// Where the values a job writes to a drive are journaled (docs/journal.md): the journal, the
// drive as its entries name it, and the job the writes belong to. The edit path (ValueEdits),
// copy set and the download begin one entry per parameter and set before anything is sent,
// and complete each with the write's outcome: an entry that cannot be begun stops the write
// unsent. Lives in the thread that made it; the journal outlives it.
class EditJournal
{
    Q_DECLARE_TR_FUNCTIONS(EditJournal)
public:
    // What each set held before the write ([0] alone without sets).
    using Values = std::array<std::optional<qint32>, kParameterSets>;

    struct Entry
    {
        qint64 id = 0;
        std::optional<int> set; // none: the active set, or a parameter without sets
        qint32 written = 0;
        bool activeSet = false; // written by a step with set mask 0
    };

    // One parameter's write: its steps as sent (after SetList::setsWritten()) and the values
    // held before.
    struct Write
    {
        QString id; // "op.28"
        const ParameterDescription *parameter = nullptr;
        QList<WriteStep> steps;
        Values before {};
    };

    // `job`: what the writes are ("edit", "write op.28", "download of f5.json"); made in the
    // journal with the first entry.
    EditJournal(Journal *journal, JournalDrive drive, QString job);

    // The drive as the journal names it: the link as given, the protocol, the bus address, and
    // what the description says of its kind (In.00), software (In.06) and serial number (In.10).
    static JournalDrive driveOf(const ConnectionSettings &settings,
                                const DriveDescription &drive);

    // The outcome of writes to the sets of the mask that never went out: `reason` why.
    static WriteOutcome notSent(quint16 address, quint8 setMask, const QString &reason);
    // ... because the journal could not take their entries (`error`, from begin()).
    static WriteOutcome notJournaled(quint16 address, quint8 setMask, const QString &error);

    // The journal could not be opened: every begin() fails with `reason`, so nothing is sent.
    void setUnavailable(const QString &reason) { m_unavailable = reason; }
    // How to write without the journal ("--no-journal writes without it"), said after the
    // reason of every begin() that fails; none: the reason alone.
    void setRemedy(const QString &remedy) { m_remedy = remedy; }

    const JournalDrive &drive() const { return m_drive; }
    void setDrive(const JournalDrive &drive) { m_drive = drive; }

    // One entry per set the steps write (a step with mask 0: the active set), each with the
    // value held before and the value written. The entries, or nothing with why in `error`.
    std::optional<QList<Entry>> begin(const QString &id, const ParameterDescription &parameter,
                                      const QList<WriteStep> &steps, const Values &before,
                                      QString *error);
    // The entries of many parameters' writes to `drive`, stored together: all of them, per
    // write, or none with why in `error`. One transaction for the lot, not one per entry.
    std::optional<QList<QList<Entry>>> begin(const JournalDrive &drive,
                                             const QList<Write> &writes, QString *error);
    // What became of each entry's write: written (with the value read back), refused with the
    // drive's reason, unknown where no answer came, or not sent.
    void complete(const ParameterDescription &parameter, const QList<Entry> &entries,
                  const WriteOutcome &outcome);
    // Several parameters' outcomes at once, in one transaction: `completions` runs the
    // complete() calls.
    void completeTogether(const std::function<void()> &completions);

private:
    bool fail(const QString &reason, QString *error) const;

    Journal *m_journal = nullptr;
    JournalDrive m_drive;
    QString m_job;
    qint64 m_jobId = 0;
    QString m_unavailable;
    QString m_remedy;
};

} // namespace DriveDesk
