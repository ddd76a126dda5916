// The EditController's long jobs: copying one set to another and re-reading every value.
#include "EditController.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"

#include <QUndoStack>

namespace DriveDesk {

bool EditController::refuseWhileJobRuns()
{
    if (m_copy) {
        emit message(tr("Still copying set %1 to set %2").arg(m_copy->plan.from).arg(m_copy->plan.to));
        return true;
    }
    if (m_refresh) {
        emit message(tr("Still reading the values"));
        return true;
    }
    return false;
}

void EditController::copySet(int fromSet, int toSet)
{
    if (fromSet < 0 || fromSet >= kParameterSets || toSet < 0 || toSet >= kParameterSets) {
        emit message(tr("Cannot copy set %1 to set %2: the sets are 0 to %3")
                         .arg(fromSet)
                         .arg(toSet)
                         .arg(kParameterSets - 1));
        return;
    }
    if (fromSet == toSet) {
        emit message(tr("Cannot copy set %1 onto itself").arg(fromSet));
        return;
    }
    if (refuseWhileJobRuns())
        return;
    auto job = std::make_unique<CopyJob>();
    job->plan = planCopySet(m_model->state()->description(), fromSet, toSet, m_model->state()->passwordLevel());
    job->macro
        = std::make_unique<QUndoCommand>(tr("Copy set %1 to set %2").arg(fromSet).arg(toSet));
    for (const CopySetPlan::Item &item : std::as_const(job->plan.items)) {
        ValueCommand::Values before{};
        before[std::size_t(toSet)] = m_model->state()->value(item.address, toSet);
        job->before << before;
    }
    if (!journalCopy(*job))
        return;
    for (const CopySetPlan::Item &item : std::as_const(job->plan.items))
        m_model->state()->markPending(item.address, quint8(1u << toSet), item.raw);
    connect(&job->watcher, &QFutureWatcherBase::resultsReadyAt, this, &EditController::copyTake);
    connect(&job->watcher, &QFutureWatcherBase::progressValueChanged, this,
            [this](int done) { emit progress(done, int(m_copy->plan.items.size())); });
    connect(&job->watcher, &QFutureWatcherBase::finished, this, &EditController::copyFinished);
    m_copy = std::move(job);
    updateBusy();
    emit progress(0, int(m_copy->plan.items.size()));
    m_copy->job = std::make_shared<CopySetJob>(m_client->settings().protocol, m_copy->plan);
    m_copy->watcher.setFuture(m_client->run(m_copy->job));
}

bool EditController::journalCopy(CopyJob &job)
{
    EditJournal *journal = m_edits->journal();
    if (!journal)
        return true;
    const quint8 mask = quint8(1u << job.plan.to);
    for (qsizetype index = 0; index < job.plan.items.size(); ++index) {
        const CopySetPlan::Item &item = job.plan.items.at(index);
        const ParameterDescription *parameter = m_model->state()->parameter(item.address);
        QString error;
        const std::optional<QList<EditJournal::Entry>> entries
            = parameter ? journal->begin(m_model->state()->editText(item.address).id(), *parameter,
                                         { WriteStep { mask, item.raw, false } },
                                         job.before.at(index), &error)
                        : std::nullopt;
        if (!entries) {
            // What was begun stays in the journal as not sent: nothing went out.
            const WriteOutcome unsent = EditJournal::notJournaled(item.address, mask, error);
            for (qsizetype begun = 0; begun < index; ++begun)
                completeJournal(job, begun, unsent);
            emit message(tr("Set %1 not copied to set %2: %3")
                             .arg(job.plan.from)
                             .arg(job.plan.to)
                             .arg(unsent.error));
            return false;
        }
        job.journaled << *entries;
    }
    return true;
}

void EditController::completeJournal(const CopyJob &job, qsizetype index,
                                     const WriteOutcome &written)
{
    EditJournal *journal = m_edits->journal();
    const ParameterDescription *parameter
        = m_model->state()->parameter(job.plan.items.at(index).address);
    if (!journal || !parameter || index >= job.journaled.size())
        return;
    EditOutcome outcome;
    static_cast<WriteOutcome &>(outcome) = written;
    outcome.steps = { WriteStep { quint8(1u << job.plan.to), job.plan.items.at(index).raw, false } };
    journal->complete(*parameter, job.journaled.at(index), outcome);
}

void EditController::copyTake(int begin, int end)
{
    CopyJob &copy = *m_copy;
    const QFuture<WriteOutcome> future = copy.watcher.future();
    for (int index = begin; index < end; ++index) {
        const WriteOutcome outcome = future.resultAt(index);
        const CopySetPlan::Item &item = copy.plan.items.at(index);
        completeJournal(copy, index, outcome);
        m_model->state()->showOutcome(outcome);
        if (outcome.acknowledgedMask) {
            new ValueCommand(this, ValueCommand::Kind::Write, item.address,
                                  outcome.acknowledgedMask, item.raw, copy.before.at(index),
                                  commandText(ValueCommand::Kind::Write, item.address,
                                              outcome.acknowledgedMask, item.raw),
                                  copy.macro.get());
            ++copy.written;
        } else if (outcome.connectionFailed) {
            copy.stopReason = outcome.error;
        } else {
            copy.refusals << tr("%1: %2").arg(m_model->state()->editText(item.address).id(), outcome.error);
        }
    }
}

void EditController::copyFinished()
{
    const std::unique_ptr<CopyJob> job = std::move(m_copy);
    if (job->macro->childCount() > 0)
        m_undoStack->push(job->macro.release());
    // An item without an outcome was never sent: its cell shows again what it held.
    for (qsizetype index = 0; index < job->plan.items.size(); ++index) {
        if (job->watcher.future().isResultReadyAt(int(index)))
            continue;
        m_model->state()->clearEditState(job->plan.items.at(index).address, quint8(1u << job->plan.to));
        completeJournal(*job, index,
                        EditJournal::notSent(job->plan.items.at(index).address,
                                             quint8(1u << job->plan.to),
                                             job->stopReason.isEmpty() ? tr("the copy was cancelled")
                                                                       : job->stopReason));
    }

    const int from = job->plan.from;
    const int to = job->plan.to;
    const int notCopied = int(job->plan.items.size()) - job->watcher.future().resultCount();
    QStringList parts;
    if (job->plan.items.isEmpty()) {
        parts << tr("Set %2 holds the values of set %1 already").arg(from).arg(to);
    } else {
        parts << tr("Set %1 copied to set %2: %n value(s) written", nullptr, job->written)
                     .arg(from)
                     .arg(to);
    }
    if (!job->refusals.isEmpty()) {
        parts << tr("%n refused (%1)", nullptr, int(job->refusals.size()))
                     .arg(job->refusals.join(QStringLiteral("; ")));
    }
    if (!job->stopReason.isEmpty())
        parts << tr("stopped: %1").arg(job->stopReason);
    else if (job->cancelled && notCopied > 0)
        parts << tr("cancelled, %n value(s) not copied", nullptr, notCopied);
    if (job->plan.locked > 0) {
        parts << tr("%n parameter(s) left as they are: read-only or above the password level",
                    nullptr, job->plan.locked);
    }
    if (job->plan.unknown > 0)
        parts << tr("%n parameter(s) left out: the value in set %1 was never read", nullptr,
                    job->plan.unknown)
                     .arg(from);
    emit message(parts.join(QStringLiteral("; ")));
    updateBusy();
    startQueuedReads();
}

void EditController::forgetWrites()
{
    m_undoStack->clear();
    m_model->state()->clearEditStates();
}

void EditController::refresh()
{
    if (refuseWhileJobRuns())
        return;
    startReads(readableValues(m_model->state()->description(), m_model->state()->passwordLevel()));
}

void EditController::readAgain(const QList<ValueRead> &reads)
{
    if (reads.isEmpty())
        return;
    if (m_refresh || m_copy) {
        m_queuedReads << reads;
        return;
    }
    startReads(reads);
}

void EditController::startQueuedReads()
{
    if (!m_queuedReads.isEmpty() && !m_refresh && !m_copy)
        startReads(std::exchange(m_queuedReads, {}));
}

void EditController::startReads(const QList<ValueRead> &reads)
{
    m_refresh = new ValueReadBatch(m_client, m_model->state(), reads, this);
    connect(m_refresh, &ValueReadBatch::progress, this, &EditController::progress);
    connect(m_refresh, &ValueReadBatch::finished, this, &EditController::refreshFinished);
    updateBusy();
    m_refresh->start();
}

void EditController::refreshFinished()
{
    ValueReadBatch *batch = m_refresh;
    m_refresh = nullptr;
    batch->deleteLater();
    m_readFailures.clear();
    for (const ValueReading &failure : batch->failures()) {
        m_readFailures.insert(quint32(failure.read.address) << 8 | quint32(failure.read.set),
                              failure.reason);
    }

    QStringList parts;
    parts << tr("%n value(s) read", nullptr, batch->done() - int(batch->failures().size()));
    if (!batch->failures().isEmpty()) {
        const ValueReading &first = batch->failures().constFirst();
        const EditText text = m_model->state()->editText(first.read.address);
        parts << tr("%n could not be read (first: %1%2: %3)", nullptr,
                    int(batch->failures().size()))
                     .arg(text.id(), text.inSets(quint8(1u << first.read.set)), first.reason);
    }
    if (!batch->stopReason().isEmpty())
        parts << tr("stopped: %1").arg(batch->stopReason());
    else if (batch->wasCancelled() && batch->done() < batch->total())
        parts << tr("cancelled, %n value(s) not read", nullptr, batch->total() - batch->done());
    emit message(parts.join(QStringLiteral("; ")));
    updateBusy();
    startQueuedReads();
}

void EditController::cancel()
{
    if (m_copy) {
        // Stopped, not cancelled: the write on its way is still reported, so that what the
        // drive took reaches the undo history.
        m_copy->cancelled = true;
        m_copy->job->requestStop();
    }
    m_queuedReads.clear();
    if (m_refresh)
        m_refresh->cancel();
}

} // namespace DriveDesk
