#pragma once

#include "journal/JournalEntry.h"
#include "parameters/ChosenValues.h"
#include "parameters/DriveDescription.h"

#include <QCoreApplication>
#include <QList>
#include <QStringList>

namespace DriveDesk {

// What reverting journal entries writes: each entry's value before, back into its parameter
// and set of the connected drive, through the download (its checks, last look, read-back and
// report) as a selection. Where several entries touch one parameter and set, the oldest
// entry's value before wins: it is what the drive held before all of them.
struct JournalRevertPlan
{
    QList<ChosenValue> values; // one per parameter and set
    QList<qint64> entries; // the entries reverted, oldest first
    // Why the revert is refused, each naming its entry: nothing is written while any is here.
    QStringList refusals;
    // Entries a revert by time leaves out (password entries), each naming its entry.
    QStringList leftOut;

    bool isRefused() const { return !refusals.isEmpty() || values.isEmpty(); }
    // The job its writes are journaled as: "revert of entries 12..15", "revert of entry 12".
    QString job() const;
    // What the download's last look says it writes: "the values before entries 12..15".
    QString what() const;
    // What the download writes: the drive's description with only the values to revert
    // (ChosenValues::selectionFor).
    DriveDescription selection(const DriveDescription &drive) const;
};

class JournalRevert
{
    Q_DECLARE_TR_FUNCTIONS(JournalRevert)
public:
    // The entries named by id (`asked`), of which the journal found `found`: refused for an id
    // the journal does not have, an entry of another drive than `connected`, a password entry,
    // an entry without a value before, one of the active set of a parameter with sets, one of a
    // parameter `drive` (its description, as read) lacks.
    static JournalRevertPlan ofEntries(const QList<qint64> &asked,
                                       const QList<JournalEntry> &found,
                                       const JournalDrive &connected,
                                       const DriveDescription &drive);
    // The entries since a time (`found`, of any drive): those of the connected drive, password
    // entries left out (and said so), refused as ofEntries() for the others.
    static JournalRevertPlan since(const QList<JournalEntry> &found, const JournalDrive &connected,
                                   const DriveDescription &drive);
    // "12", "12..15" (both ends included), each a list of ids; nothing and *error otherwise.
    static std::optional<QList<qint64>> parseIds(const QStringList &words, QString *error);

private:
    enum class Asked : quint8 { ById, ByTime };
    static JournalRevertPlan plan(const QList<JournalEntry> &found, const JournalDrive &connected,
                                  const DriveDescription &drive, Asked asked);
};

} // namespace DriveDesk
