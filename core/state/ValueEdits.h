#pragma once

#include "session/EditJournal.h"
#include "state/EditOutcome.h"
#include "state/StateEditor.h"

#include <QHash>
#include <QList>
#include <QObject>

#include <array>
#include <functional>
#include <memory>
#include <optional>

namespace DriveDesk {

class DriveClient;
class DriveState;

// A drive's pending edits, the one path a value edit takes to the drive and back for the
// window and the command line alike. Each edit is queued behind the earlier ones of the same
// parameter, applies the set-0 rule (SetList::setsWritten), is written and read back as a
// WriteValueJob in the client's thread, and ends in one EditOutcome (EditText says it in
// words). The drive's DriveState, where one is given, shows it all: the cells pending at once,
// then the outcome. Lives in the thread that made it; the client and the state outlive it.
class ValueEdits : public QObject, public StateEditor
{
    Q_OBJECT
public:
    // `state`: the drive's state, which takes the edits' pending values and outcomes and gives
    // EditOutcome::before; none where nothing else keeps the drive's values.
    explicit ValueEdits(DriveClient *client, DriveState *state = nullptr,
                        QObject *parent = nullptr);
    ~ValueEdits() override;

    DriveState *state() const override { return m_state; }
    // Any steps, as undo and redo give them; a step with mask 0 writes the active set
    // (service 1). `done` runs once, after the read-back.
    void apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
               Done done = {}) override;
    // Writes each known earlier value back; a set whose earlier value is unknown stays as it is
    // (the outcome leaves it out).
    void restore(const ParameterDescription &parameter, quint8 setMask, const Values &before,
                 Done done = {}) override;

    // Every edit from now on is journaled there (docs/journal.md); none: not journaled. An
    // edit whose entries the journal cannot take is not sent, and its outcome says why. The
    // journal outlives this object.
    void setJournal(EditJournal *journal) { m_journal = journal; }
    EditJournal *journal() const { return m_journal; }

    // Edits given and not yet done.
    int runningCount() const { return m_running; }

signals:
    // An edit was queued: the cells of the mask show `raw` until its outcome comes.
    void pending(quint16 address, quint8 setMask, qint32 raw);
    // What became of an edit; emitted before its `done` runs.
    void edited(const DriveDesk::EditOutcome &outcome);
    void runningCountChanged(int count);

private:
    struct Edit
    {
        ValueChange change;
        ParameterDescription parameter;
        QList<EditJournal::Entry> journaled;
        bool judgeReadBack = true; // not for a parameter whose read-back may differ
        Done done;
        EditOutcome outcome;
    };
    using EditPtr = std::shared_ptr<Edit>;

    void begin(const EditPtr &edit);
    void finish(const EditPtr &edit, const WriteOutcome &outcome);
    // Begins the edit's journal entries; false when the journal could not take them: the edit
    // is then finished unsent.
    bool journal(const EditPtr &edit);
    void setRunning(int count);

    DriveClient *m_client = nullptr;
    DriveState *m_state = nullptr;
    EditJournal *m_journal = nullptr;
    QHash<quint16, QList<EditPtr>> m_queues; // per parameter; the first one is on its way
    int m_running = 0;
};

} // namespace DriveDesk
