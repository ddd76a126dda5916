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
    QList<ValueEdits::BatchItem> items;
    for (const CopySetPlan::Item &item : std::as_const(job->plan.items)) {
        // The plan is made of the state's own description: every parameter is there.
        const ParameterDescription *parameter = m_model->state()->parameter(item.address);
        Q_ASSERT(parameter);
        items << ValueEdits::BatchItem { *parameter,
                                         { WriteStep { quint8(1u << toSet), item.raw, false } } };
    }
    m_copy = std::move(job);
    updateBusy();
    emit progress(0, int(items.size()));
    const quint64 batch = m_edits->applyAll(
        items, [this](qsizetype index, const EditOutcome &outcome) { copyTake(index, outcome); },
        [this](const QList<EditOutcome> &outcomes) { copyFinished(outcomes); });
    if (m_copy)
        m_copy->batch = batch;
}

void EditController::copyTake(qsizetype index, const EditOutcome &outcome)
{
    CopyJob &copy = *m_copy;
    const CopySetPlan::Item &item = copy.plan.items.at(index);
    emit progress(++copy.answered, int(copy.plan.items.size()));
    if (outcome.acknowledgedMask) {
        new ValueCommand(this, ValueCommand::Kind::Write, item.address, outcome.acknowledgedMask,
                         item.raw, outcome.before,
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

void EditController::copyFinished(const QList<EditOutcome> &outcomes)
{
    const std::unique_ptr<CopyJob> job = std::move(m_copy);
    if (job->macro->childCount() > 0)
        m_undoStack->push(job->macro.release());
    if (job->answered == 0 && !outcomes.isEmpty() && !job->cancelled) {
        // Nothing went out: the journal could not take the entries, or the connection went.
        emit message(tr("Set %1 not copied to set %2: %3")
                         .arg(job->plan.from)
                         .arg(job->plan.to)
                         .arg(outcomes.constFirst().error));
        updateBusy();
        return startQueuedReads();
    }

    const int from = job->plan.from;
    const int to = job->plan.to;
    const int notCopied = int(job->plan.items.size()) - job->answered;
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
        m_edits->stopBatch(m_copy->batch, tr("the copy was cancelled"));
    }
    m_queuedReads.clear();
    if (m_refresh)
        m_refresh->cancel();
}

} // namespace DriveDesk
