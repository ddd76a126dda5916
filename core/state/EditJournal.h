#pragma once

#include "journal/JournalEntry.h"
#include "state/StateEditor.h"

#include <QCoreApplication>
#include <QList>

#include <optional>

namespace DriveDesk {

class Journal;
struct ConnectionSettings;

// Where a drive's value edits are journaled (docs/journal.md): the journal, the drive as its
// entries name it, and the job the edits belong to. ValueEdits begins one entry per set a
// change writes before anything is sent, and completes them with the change's outcome: an
// entry that cannot be begun stops the change unsent. Lives in the thread that made it; the
// journal outlives it.
class EditJournal
{
    Q_DECLARE_TR_FUNCTIONS(EditJournal)
public:
    struct Entry
    {
        qint64 id = 0;
        std::optional<int> set; // none: the active set, or a parameter without sets
        qint32 written = 0;
    };

    // `job`: what the edits are ("edit", "write op.28"); made in the journal with the first
    // entry.
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

    const JournalDrive &drive() const { return m_drive; }
    void setDrive(const JournalDrive &drive) { m_drive = drive; }

    // One entry per set the steps write (a step with mask 0: the active set), each with the
    // value held before and the value written. The entries, or nothing with why in `error`.
    std::optional<QList<Entry>> begin(const QString &id, const ParameterDescription &parameter,
                                      const QList<WriteStep> &steps,
                                      const StateEditor::Values &before, QString *error);
    // What became of each entry's write: written (with the value read back), refused with the
    // drive's reason, unknown where no answer came, or not sent.
    void complete(const ParameterDescription &parameter, const QList<Entry> &entries,
                  const EditOutcome &outcome);

private:
    Journal *m_journal = nullptr;
    JournalDrive m_drive;
    QString m_job;
    qint64 m_jobId = 0;
    QString m_unavailable;
};

} // namespace DriveDesk
