#pragma once

#include "session/EditJournal.h"
#include "state/EditOutcome.h"
#include "state/StateEditor.h"

#include <QFuture>
#include <QHash>
#include <QList>
#include <QObject>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace DriveDesk {

class DriveClient;
class DriveState;
class WriteChangesJob;

// A drive's pending edits, the one path a value edit takes to the drive and back for the
// window and the command line alike. Each edit is queued behind the earlier ones of the same
// parameter, applies the set-0 rule (SetList::setsWritten), is written and read back as a
// WriteValueJob in the client's thread, and ends in one EditOutcome (EditText says it in
// words). Many parameters written together (copy set, the scope's channels) are one batch
// (applyAll): one WriteChangesJob, queued per parameter like single edits. The drive's
// DriveState, where one is given, shows it all: the cells pending at once, then the outcome.
// Lives in the thread that made it; the client and the state outlive it.
class ValueEdits : public QObject, public StateEditor
{
    Q_OBJECT
public:
    // `state`: the drive's state, which takes the edits' pending values and outcomes and gives
    // EditOutcome::before; none where nothing else keeps the drive's values.
    explicit ValueEdits(DriveClient *client, DriveState *state = nullptr,
                        QObject *parent = nullptr);
    ~ValueEdits() override;

    DriveClient *client() const { return m_client; }
    DriveState *state() const override { return m_state; }
    // Any steps, as undo and redo give them; a step with mask 0 writes the active set
    // (service 1). `done` runs once, after the read-back.
    void apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
               Done done = {}) override;
    // Writes each known earlier value back; a set whose earlier value is unknown stays as it is
    // (the outcome leaves it out).
    void restore(const ParameterDescription &parameter, quint8 setMask, const Values &before,
                 Done done = {}) override;

    // One parameter of a batch, planned and checked by the caller.
    struct BatchItem
    {
        ParameterDescription parameter;
        QList<WriteStep> steps;
    };
    // An item's outcome as it comes, for each item the drive was asked: `index` in the items.
    using ItemDone = std::function<void(qsizetype index, const EditOutcome &outcome)>;
    // Every item's outcome, in the items' order, once the last is in; an item never sent says
    // why (notSentMask).
    using BatchDone = std::function<void(const QList<EditOutcome> &outcomes)>;

    // Writes the items, each parameter at most once, as one job of many requests
    // (WriteChangesJob: over HSP5 several on the line at once), each read back. The cells are
    // pending at once; the entries of all items are journaled together before anything is
    // sent. The batch starts once no earlier edit of any of its parameters is on its way, and
    // a later edit of one of them waits for the batch's write of that parameter. Gives the
    // batch's number for stopBatch(); `done` may have run by then.
    quint64 applyAll(const QList<BatchItem> &items, ItemDone written = {}, BatchDone done = {});
    // Sends nothing more of the batch; what is on its way is still reported. The items never
    // sent end not sent for `reason`, their cells showing again what they held.
    void stopBatch(quint64 batch, const QString &reason);

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
    struct Batch;
    struct Edit
    {
        ValueChange change;
        ParameterDescription parameter;
        QList<EditJournal::Entry> journaled;
        bool judgeReadBack = true; // not for a parameter whose read-back may differ
        Done done;
        EditOutcome outcome;
        Batch *batch = nullptr; // the batch it belongs to, owned by m_batches
    };
    using EditPtr = std::shared_ptr<Edit>;
    struct Batch
    {
        quint64 number = 0;
        QList<EditPtr> edits; // the items' edits, in their order
        ItemDone written;
        BatchDone done;
        std::shared_ptr<WriteChangesJob> job; // once started
        QString stopReason; // stopBatch()'s, or the connection's when it failed
        bool started = false;
    };

    // The edit as queued: the set-0 rule applied, its cells pending.
    EditPtr prepare(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset);
    // Puts the edit at the end of its parameter's queue; true when it is first there.
    bool enqueue(const EditPtr &edit);
    // The first edit of a queue goes: alone, or with its batch once every item of it is first.
    void startFirst(const EditPtr &edit);
    void takeBefore(Edit &edit) const;
    void begin(const EditPtr &edit);
    void beginBatch(Batch *batch);
    void batchAnswered(Batch *batch, const QFuture<WriteOutcome> &future, int begin, int end);
    void endBatch(Batch *batch);
    // Ends the edit; `unsent`: it never went out, and its cells show again what they held.
    void finish(const EditPtr &edit, const WriteOutcome &outcome, bool unsent = false);
    // Begins the edits' journal entries together; false when the journal could not take them:
    // the edits are then finished unsent.
    bool journal(const QList<EditPtr> &edits);
    void setRunning(int count);

    DriveClient *m_client = nullptr;
    DriveState *m_state = nullptr;
    EditJournal *m_journal = nullptr;
    // Per parameter; the first one is on its way, or its batch waits for its other parameters.
    QHash<quint16, QList<EditPtr>> m_queues;
    std::vector<std::unique_ptr<Batch>> m_batches; // given and not done
    quint64 m_lastBatch = 0;
    int m_running = 0;
};

} // namespace DriveDesk
