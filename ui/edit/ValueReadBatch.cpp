#include "ValueReadBatch.h"

#include "ReplyWatch.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"
#include "parameters/ParameterProperties.h"

namespace DriveDesk {

QList<ValueRead> valueReadsOf(const ParameterDescription &parameter)
{
    if (!parameter.isSetProgrammable())
        return { ValueRead { parameter.address, 0, false } };
    QList<ValueRead> reads;
    reads.reserve(kParameterSets);
    for (int set = 0; set < kParameterSets; ++set)
        reads << ValueRead { parameter.address, set, true };
    return reads;
}

bool isReadable(const ParameterDescription &parameter, PasswordLevel level)
{
    return ParameterProperties(parameter.properties1, parameter.properties2).readLevel() <= level;
}

ValueReadBatch::ValueReadBatch(DriveClient *client, ParameterModel *model, QList<ValueRead> reads,
                               QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_model(model)
    , m_reads(std::move(reads))
{ }

void ValueReadBatch::start()
{
    if (m_running)
        return;
    m_running = true;
    emit progress(0, total());
    sendMore();
}

void ValueReadBatch::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    sendMore();
}

void ValueReadBatch::sendMore()
{
    const bool stopping = m_cancelled || !m_stopReason.isEmpty();
    while (!stopping && m_onTheWay < kWindow && m_next < m_reads.size()) {
        const ValueRead read = m_reads.at(m_next++);
        const QFuture<Reply> reply = read.perSet
            ? m_client->readValue(read.address, quint8(1u << read.set))
            : m_client->readValueStandard(read.address, 0);
        ++m_onTheWay;
        whenReplied(this, reply, [this, read](const Reply &answer) { handle(read, answer); });
    }
    if (m_onTheWay == 0 && (stopping || m_next >= m_reads.size())) {
        m_running = false;
        emit finished();
    }
}

void ValueReadBatch::handle(const ValueRead &read, const Reply &reply)
{
    --m_onTheWay;
    ++m_done;
    if (const auto *value = reply.data<ParameterValue>()) {
        m_model->setValue(read.address, read.set, value->value);
    } else if (isConnectionFailure(reply)) {
        if (m_stopReason.isEmpty() && !m_cancelled)
            m_stopReason = reply.message(m_client->settings().language);
    } else {
        m_failures << Failure { read.address, read.set,
                                reply.message(m_client->settings().language) };
    }
    emit progress(m_done, total());
    sendMore();
}

} // namespace DriveDesk
