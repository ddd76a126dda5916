// The EditController's long jobs: copying one set to another and re-reading every value.
#include "EditController.h"

#include "model/ParameterModel.h"

#include <QUndoStack>

namespace DriveDesk {

bool EditController::refuseWhileJobRuns()
{
    if (m_copy) {
        emit message(tr("Still copying set %1 to set %2").arg(m_copy->from).arg(m_copy->to));
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
    job->from = fromSet;
    job->to = toSet;
    const DriveDescription drive = m_model->description();
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (!parameter.isSetProgrammable())
                continue;
            const std::optional<qint32> source = parameter.values[std::size_t(fromSet)];
            if (!source) {
                ++job->unknown;
                continue;
            }
            if (parameter.values[std::size_t(toSet)] == source)
                continue;
            if (!m_model->isEditable(parameter.address)) {
                ++job->locked;
                continue;
            }
            job->items << CopyJob::Item { parameter.address, *source };
        }
    }
    job->macro
        = std::make_unique<QUndoCommand>(tr("Copy set %1 to set %2").arg(fromSet).arg(toSet));
    m_copy = std::move(job);
    updateBusy();
    emit progress(0, int(m_copy->items.size()));
    copyNext();
}

void EditController::copyNext()
{
    CopyJob &job = *m_copy;
    if (job.cancelled || !job.stopReason.isEmpty() || job.next >= job.items.size()) {
        copyFinished();
        return;
    }
    const CopyJob::Item item = job.items.at(job.next++);
    const quint8 mask = quint8(1u << job.to);
    m_writer->apply(item.address, { WriteStep { mask, item.raw, false } },
                    [this, item](const WriteOutcome &outcome) {
                        CopyJob &copy = *m_copy;
                        if (outcome.acknowledgedMask) {
                            new WriteValueCommand(
                                this, WriteValueCommand::Kind::Write, item.address,
                                outcome.acknowledgedMask, item.raw, outcome.before,
                                tr("Write %1 = %2%3")
                                    .arg(idOf(item.address), valueText(item.address, item.raw),
                                         inSets(item.address, outcome.acknowledgedMask)),
                                copy.macro.get());
                            ++copy.written;
                        } else if (outcome.connectionFailed) {
                            copy.stopReason = outcome.error;
                        } else {
                            copy.refusals << tr("%1: %2").arg(idOf(item.address), outcome.error);
                        }
                        emit progress(int(copy.next), int(copy.items.size()));
                        copyNext();
                    });
}

void EditController::copyFinished()
{
    const std::unique_ptr<CopyJob> job = std::move(m_copy);
    if (job->macro->childCount() > 0)
        m_undoStack->push(job->macro.release());

    QStringList parts;
    if (job->items.isEmpty()) {
        parts << tr("Set %2 holds the values of set %1 already").arg(job->from).arg(job->to);
    } else {
        parts << tr("Set %1 copied to set %2: %n value(s) written", nullptr, job->written)
                     .arg(job->from)
                     .arg(job->to);
    }
    if (!job->refusals.isEmpty()) {
        parts << tr("%n refused (%1)", nullptr, int(job->refusals.size()))
                     .arg(job->refusals.join(QStringLiteral("; ")));
    }
    if (!job->stopReason.isEmpty())
        parts << tr("stopped: %1").arg(job->stopReason);
    else if (job->cancelled && job->next < job->items.size())
        parts << tr("cancelled, %n value(s) not copied", nullptr,
                    int(job->items.size() - job->next));
    if (job->locked > 0) {
        parts << tr("%n parameter(s) left as they are: read-only or above the password level",
                    nullptr, job->locked);
    }
    if (job->unknown > 0)
        parts << tr("%n parameter(s) left out: the value in set %1 was never read", nullptr,
                    job->unknown)
                     .arg(job->from);
    emit message(parts.join(QStringLiteral("; ")));
    updateBusy();
}

void EditController::refresh()
{
    if (refuseWhileJobRuns())
        return;
    QList<ValueRead> reads;
    const PasswordLevel level = m_model->passwordLevel();
    const DriveDescription drive = m_model->description();
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (isReadable(parameter, level))
                reads << valueReadsOf(parameter);
        }
    }
    m_refresh = new ValueReadBatch(m_client, m_model, reads, this);
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
    for (const ValueReadBatch::Failure &failure : batch->failures())
        m_readFailures.insert(quint32(failure.address) << 8 | quint32(failure.set), failure.reason);

    QStringList parts;
    parts << tr("%n value(s) read", nullptr, batch->done() - int(batch->failures().size()));
    if (!batch->failures().isEmpty()) {
        const ValueReadBatch::Failure &first = batch->failures().constFirst();
        parts << tr("%n could not be read (first: %1%2: %3)", nullptr,
                    int(batch->failures().size()))
                     .arg(idOf(first.address), inSets(first.address, quint8(1u << first.set)),
                          first.reason);
    }
    if (!batch->stopReason().isEmpty())
        parts << tr("stopped: %1").arg(batch->stopReason());
    else if (batch->wasCancelled() && batch->done() < batch->total())
        parts << tr("cancelled, %n value(s) not read", nullptr, batch->total() - batch->done());
    emit message(parts.join(QStringLiteral("; ")));
    updateBusy();
}

void EditController::cancel()
{
    if (m_copy)
        m_copy->cancelled = true;
    if (m_refresh)
        m_refresh->cancel();
}

} // namespace DriveDesk
