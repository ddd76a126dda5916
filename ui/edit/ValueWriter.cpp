#include "ValueWriter.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"
#include "parameters/ParameterId.h"

#include <QFutureWatcher>

namespace DriveDesk {

void showOutcome(ParameterModel &model, const WriteOutcome &outcome, bool superseded)
{
    const quint16 address = outcome.address;
    if (outcome.refusedMask && !superseded)
        model.markFailed(address, outcome.refusedMask, outcome.error);
    for (int set = 0; set < kParameterSets; ++set) {
        if (!(outcome.acknowledgedMask & (1u << set)))
            continue;
        if (const std::optional<qint32> value = outcome.readBack[std::size_t(set)]) {
            if (superseded)
                model.setValue(address, set, *value);
            else
                model.confirmReadBack(address, set, *value);
        } else if (!superseded) {
            // The drive acknowledged the write; only the confirmation is missing.
            model.markWritten(address, quint8(1u << set));
        }
    }
}

ValueWriter::ValueWriter(DriveClient *client, ParameterModel *model, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_model(model)
{ }

ValueWriter::~ValueWriter() = default;

void ValueWriter::apply(quint16 address, QList<WriteStep> steps, Done done)
{
    auto change = std::make_shared<Change>();
    change->address = address;
    change->done = std::move(done);
    change->outcome.address = address;
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter) {
        change->outcome.error
            = tr("this drive has no parameter %1").arg(ParameterId::hexAddress(address));
        change->done(change->outcome);
        return;
    }
    for (WriteStep &step : steps) {
        if (!parameter->isSetProgrammable())
            step.setMask = 0x01;
        if (step.reset)
            step.raw = parameter->defaultValue;
    }
    change->steps = std::move(steps);
    markPending(*change);
    QList<ChangePtr> &queue = m_queues[address];
    queue << change;
    setRunning(m_running + 1);
    if (queue.size() == 1)
        begin(change);
}

void ValueWriter::markPending(const Change &change)
{
    for (const WriteStep &step : change.steps)
        m_model->markPending(change.address, step.setMask, step.raw);
}

void ValueWriter::begin(const ChangePtr &change)
{
    for (int set = 0; set < kParameterSets; ++set)
        change->outcome.before[std::size_t(set)] = m_model->value(change->address, set);
    markPending(*change);
    const ParameterDescription *parameter = m_model->parameter(change->address);
    ValueChange request;
    request.address = change->address;
    request.setProgrammable = parameter && parameter->isSetProgrammable();
    request.steps = change->steps;
    auto *watcher = new QFutureWatcher<WriteOutcome>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, change] {
        const QFuture<WriteOutcome> future = watcher->future();
        watcher->deleteLater();
        WriteOutcome outcome;
        outcome.address = change->address;
        if (future.resultCount() > 0) {
            outcome = future.result();
        } else {
            // The client went away before the job ran: nothing was sent.
            outcome.error = tr("the connection to the drive was closed");
            outcome.connectionFailed = true;
            for (const WriteStep &step : change->steps)
                outcome.refusedMask |= step.setMask;
        }
        written(change, outcome);
    });
    watcher->setFuture(m_client->run(
        std::make_shared<WriteValueJob>(m_client->settings().protocol, std::move(request))));
}

void ValueWriter::written(const ChangePtr &change, const WriteOutcome &outcome)
{
    static_cast<WriteOutcome &>(change->outcome) = outcome;
    showOutcome(*m_model, outcome, isSuperseded(*change));
    finish(change);
}

void ValueWriter::finish(const ChangePtr &change)
{
    QList<ChangePtr> &queue = m_queues[change->address];
    queue.removeOne(change);
    const ChangePtr next = queue.value(0);
    if (queue.isEmpty())
        m_queues.remove(change->address);
    setRunning(m_running - 1);
    change->done(change->outcome);
    if (next)
        begin(next);
}

bool ValueWriter::isSuperseded(const Change &change) const
{
    const QList<ChangePtr> queue = m_queues.value(change.address);
    return !queue.isEmpty() && queue.constLast().get() != &change;
}

void ValueWriter::setRunning(int count)
{
    if (count == m_running)
        return;
    m_running = count;
    emit runningCountChanged(count);
}

} // namespace DriveDesk
