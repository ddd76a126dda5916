#include "ValueEdits.h"

#include "client/DriveClient.h"
#include "client/ReplyCheck.h"
#include "parameters/ParameterAccess.h"
#include "parameters/ParameterId.h"
#include "parameters/SetList.h"
#include "session/WriteChangesJob.h"
#include "state/DriveState.h"

#include <QFutureWatcher>

#include <algorithm>

namespace DriveDesk {

namespace {

// The sets an edit's steps write, the active set counted as set 0.
quint8 setsOf(const QList<WriteStep> &steps)
{
    quint8 mask = 0;
    for (const WriteStep &step : steps)
        mask |= step.setMask ? step.setMask : quint8(1);
    return mask;
}

} // namespace

ValueEdits::ValueEdits(DriveClient *client, DriveState *state, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_state(state)
{ }

ValueEdits::~ValueEdits() = default;

void ValueEdits::restore(const ParameterDescription &parameter, quint8 setMask,
                         const Values &before, Done done)
{
    apply(parameter, restoringSteps(setMask, before), false, std::move(done));
}

void ValueEdits::apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
                       Done done)
{
    const EditPtr edit = prepare(parameter, std::move(steps), reset);
    edit->done = std::move(done);
    setRunning(m_running + 1);
    if (enqueue(edit))
        begin(edit);
}

quint64 ValueEdits::applyAll(const QList<BatchItem> &items, ItemDone written, BatchDone done)
{
    auto owned = std::make_unique<Batch>();
    Batch *batch = owned.get();
    batch->number = ++m_lastBatch;
    batch->written = std::move(written);
    batch->done = std::move(done);
    for (qsizetype index = 0; index < items.size(); ++index) {
        const EditPtr edit = prepare(items.at(index).parameter, items.at(index).steps, false);
        edit->batch = batch;
        edit->done = [batch, index](const EditOutcome &outcome) {
            if (batch->written)
                batch->written(index, outcome);
        };
        batch->edits << edit;
    }
    m_batches.push_back(std::move(owned));
    setRunning(m_running + int(items.size()));
    for (const EditPtr &edit : std::as_const(batch->edits))
        enqueue(edit);
    const quint64 number = batch->number;
    if (batch->edits.isEmpty())
        endBatch(batch);
    else
        startFirst(batch->edits.constFirst());
    return number;
}

void ValueEdits::stopBatch(quint64 number, const QString &reason)
{
    const auto found
        = std::find_if(m_batches.begin(), m_batches.end(),
                       [number](const auto &batch) { return batch->number == number; });
    if (found == m_batches.end())
        return;
    Batch &batch = **found;
    if (batch.stopReason.isEmpty())
        batch.stopReason = reason;
    // One that has not started ends unsent when its turn comes: its items hold their places in
    // the queues until then.
    if (batch.job)
        batch.job->requestStop();
}

ValueEdits::EditPtr ValueEdits::prepare(const ParameterDescription &parameter,
                                        QList<WriteStep> steps, bool reset)
{
    auto edit = std::make_shared<Edit>();
    for (WriteStep &step : steps) {
        step.setMask = SetList::setsWritten(parameter, step.setMask);
        if (step.reset)
            step.raw = parameter.defaultValue;
    }
    edit->parameter = parameter;
    edit->change.address = parameter.address;
    edit->change.setProgrammable = parameter.isSetProgrammable();
    edit->change.steps = steps;
    edit->judgeReadBack = !readBackMayDiffer(parameter);
    edit->change.readBackShowsWrite = edit->judgeReadBack;
    // A parameter known only by its address (DIN66019 has no metadata) has no limits to judge
    // a value by.
    if (!parameter.name.isEmpty()) {
        edit->change.implausible = [parameter](qint32 value) {
            return implausibleValue(parameter, value);
        };
    }
    edit->outcome.address = parameter.address;
    edit->outcome.reset = reset;
    edit->outcome.steps = std::move(steps);
    for (const WriteStep &step : std::as_const(edit->outcome.steps)) {
        if (m_state)
            m_state->markPending(parameter.address, step.setMask, step.raw);
        emit pending(parameter.address, step.setMask, step.raw);
    }
    return edit;
}

bool ValueEdits::enqueue(const EditPtr &edit)
{
    QList<EditPtr> &queue = m_queues[edit->change.address];
    queue << edit;
    return queue.size() == 1;
}

void ValueEdits::startFirst(const EditPtr &edit)
{
    Batch *batch = edit->batch;
    if (!batch)
        return begin(edit);
    const bool ready
        = std::all_of(batch->edits.begin(), batch->edits.end(), [this](const EditPtr &item) {
              return m_queues.value(item->change.address).value(0) == item;
          });
    if (ready && !batch->started)
        beginBatch(batch);
}

void ValueEdits::takeBefore(Edit &edit) const
{
    // Taken as the edit begins, not when queued: the edit before it may have changed them.
    if (!m_state)
        return;
    for (int set = 0; set < kParameterSets; ++set)
        edit.outcome.before[std::size_t(set)] = m_state->value(edit.change.address, set);
}

void ValueEdits::begin(const EditPtr &edit)
{
    takeBefore(*edit);
    if (m_journal && !journal({ edit }))
        return;
    auto *watcher = new QFutureWatcher<WriteOutcome>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, edit] {
        const QFuture<WriteOutcome> future = watcher->future();
        watcher->deleteLater();
        if (future.resultCount() > 0)
            return finish(edit, future.result());
        // The client went away before the job ran: nothing was sent.
        WriteOutcome outcome;
        outcome.address = edit->change.address;
        outcome.error = tr("the connection to the drive was closed");
        outcome.connectionFailed = true;
        outcome.connectionError = outcome.error;
        for (const WriteStep &step : std::as_const(edit->change.steps))
            outcome.refusedMask |= step.setMask;
        finish(edit, outcome);
    });
    watcher->setFuture(m_client->run(
        std::make_shared<WriteValueJob>(m_client->settings().protocol, edit->change)));
}

void ValueEdits::beginBatch(Batch *batch)
{
    batch->started = true;
    if (!batch->stopReason.isEmpty())
        return endBatch(batch);
    for (const EditPtr &edit : std::as_const(batch->edits))
        takeBefore(*edit);
    if (m_journal && !journal(batch->edits))
        return endBatch(batch);
    QList<ValueChange> changes;
    for (const EditPtr &edit : std::as_const(batch->edits))
        changes << edit->change;
    batch->job = std::make_shared<WriteChangesJob>(m_client->settings().protocol, changes);
    auto *watcher = new QFutureWatcher<WriteOutcome>(this);
    connect(watcher, &QFutureWatcherBase::resultsReadyAt, this,
            [this, watcher, batch](int begin, int end) {
                batchAnswered(batch, watcher->future(), begin, end);
            });
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, batch] {
        watcher->deleteLater();
        endBatch(batch);
    });
    watcher->setFuture(m_client->run(batch->job));
}

void ValueEdits::batchAnswered(Batch *batch, const QFuture<WriteOutcome> &future, int begin,
                               int end)
{
    for (int index = begin; index < end; ++index) {
        const WriteOutcome outcome = future.resultAt(index);
        if (outcome.connectionFailed && batch->stopReason.isEmpty())
            batch->stopReason = outcome.error;
        finish(batch->edits.at(index), outcome);
    }
}

void ValueEdits::endBatch(Batch *batch)
{
    // An item still queued never went out: stopped, or the connection failed or went away
    // first. One the journal refused has its outcome already.
    const QString reason = batch->stopReason.isEmpty()
        ? tr("the connection to the drive was closed")
        : batch->stopReason;
    QList<EditOutcome> outcomes;
    for (const EditPtr &edit : std::as_const(batch->edits)) {
        if (m_queues.value(edit->change.address).contains(edit)) {
            edit->done = {};
            finish(edit, EditJournal::notSent(edit->change.address, setsOf(edit->change.steps),
                                              reason),
                   true);
        }
        outcomes << edit->outcome;
    }
    const BatchDone done = std::move(batch->done);
    std::erase_if(m_batches, [batch](const auto &owned) { return owned.get() == batch; });
    if (done)
        done(outcomes);
}

void ValueEdits::finish(const EditPtr &edit, const WriteOutcome &written, bool unsent)
{
    EditOutcome &outcome = edit->outcome;
    static_cast<WriteOutcome &>(outcome) = written;
    if (edit->judgeReadBack) {
        for (int set = 0; set < kParameterSets; ++set) {
            const std::optional<qint32> held = outcome.readBack[std::size_t(set)];
            if (held && held != outcome.asked(set))
                outcome.differingMask |= quint8(1u << set);
        }
    }
    QList<EditPtr> &queue = m_queues[outcome.address];
    outcome.superseded = queue.size() > 1;
    queue.removeOne(edit);
    const EditPtr next = queue.value(0);
    if (queue.isEmpty())
        m_queues.remove(outcome.address);
    setRunning(m_running - 1);
    if (m_journal && !edit->journaled.isEmpty())
        m_journal->complete(edit->parameter, edit->journaled, outcome);
    if (m_state && unsent && !outcome.superseded)
        m_state->clearEditState(outcome.address, outcome.askedMask());
    else if (m_state)
        m_state->showOutcome(outcome, outcome.superseded);
    emit edited(outcome);
    if (edit->done)
        edit->done(outcome);
    if (next)
        startFirst(next);
}

bool ValueEdits::journal(const QList<EditPtr> &edits)
{
    QList<EditJournal::Write> writes;
    for (const EditPtr &edit : edits) {
        const quint16 address = edit->change.address;
        const QString id
            = m_state ? m_state->editText(address).id() : ParameterId::hexAddress(address);
        writes << EditJournal::Write { id, &edit->parameter, edit->change.steps,
                                       edit->outcome.before };
    }
    QString error;
    const std::optional<QList<QList<EditJournal::Entry>>> entries
        = m_journal->begin(m_journal->drive(), writes, &error);
    if (entries) {
        for (qsizetype index = 0; index < edits.size(); ++index)
            edits.at(index)->journaled = entries->at(index);
        return true;
    }
    // Nothing is written that the journal could not record.
    for (const EditPtr &edit : edits) {
        edit->done = edit->batch ? Done() : edit->done;
        finish(edit, EditJournal::notJournaled(edit->change.address, setsOf(edit->change.steps),
                                               error));
    }
    return false;
}

void ValueEdits::setRunning(int count)
{
    if (count == m_running)
        return;
    m_running = count;
    emit runningCountChanged(count);
}

} // namespace DriveDesk
