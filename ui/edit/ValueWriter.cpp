#include "ValueWriter.h"

#include "ReplyWatch.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"
#include "parameters/ParameterId.h"

namespace DriveDesk {

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
    sendStep(change);
}

void ValueWriter::sendStep(const ChangePtr &change)
{
    if (change->nextStep >= change->steps.size()) {
        readBack(change);
        return;
    }
    const WriteStep step = change->steps.at(change->nextStep++);
    const QFuture<Reply> reply = step.reset
        ? m_client->resetToDefault(change->address, step.setMask)
        : m_client->writeValue(change->address, step.raw, step.setMask);
    whenReplied(this, reply, [this, change, step](const Reply &answer) {
        WriteOutcome &outcome = change->outcome;
        if (answer.ok()) {
            outcome.acknowledgedMask |= step.setMask;
        } else {
            const QString reason = answer.message(m_client->settings().language);
            outcome.refusedMask |= step.setMask;
            if (outcome.error.isEmpty())
                outcome.error = reason;
            outcome.connectionFailed = outcome.connectionFailed || isConnectionFailure(answer);
            if (!isSuperseded(*change))
                m_model->markFailed(change->address, step.setMask, reason);
        }
        sendStep(change);
    });
}

void ValueWriter::readBack(const ChangePtr &change)
{
    const quint8 mask = change->outcome.acknowledgedMask;
    for (int set = 0; set < kParameterSets; ++set) {
        if (!(mask & (1u << set)))
            continue;
        ++change->readsOnTheWay;
        whenReplied(this, m_client->readValue(change->address, quint8(1u << set)),
                    [this, change, set](const Reply &answer) {
                        --change->readsOnTheWay;
                        const bool superseded = isSuperseded(*change);
                        if (const auto *value = answer.data<ParameterValue>()) {
                            if (superseded)
                                m_model->setValue(change->address, set, value->value);
                            else
                                m_model->confirmReadBack(change->address, set, value->value);
                        } else {
                            if (change->outcome.readBackError.isEmpty()) {
                                change->outcome.readBackError
                                    = answer.message(m_client->settings().language);
                            }
                            // The drive acknowledged the write; only the confirmation is missing.
                            if (!superseded)
                                m_model->markWritten(change->address, quint8(1u << set));
                        }
                        if (change->readsOnTheWay == 0)
                            finish(change);
                    });
    }
    if (change->readsOnTheWay == 0)
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
