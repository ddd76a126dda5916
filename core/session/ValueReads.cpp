#include "ValueReads.h"

#include "client/ValueRequests.h"
#include "parameters/ParameterAccess.h"

namespace DriveDesk {

void ReadingsSummary::add(const ValueReading &reading)
{
    if (reading.value)
        return;
    if (!reading.connectionFailed)
        failures << reading;
    else if (stopReason.isEmpty())
        stopReason = reading.reason;
}

QList<ValueRead> valueReadsOf(const ParameterDescription &parameter)
{
    if (!parameter.isSetProgrammable())
        return {ValueRead{parameter.address, 0, false}};
    QList<ValueRead> reads;
    reads.reserve(kParameterSets);
    for (int set = 0; set < kParameterSets; ++set)
        reads << ValueRead{parameter.address, set, true};
    return reads;
}

QList<ValueRead> readableValues(const GroupDescription &group, PasswordLevel level)
{
    QList<ValueRead> reads;
    for (const ParameterDescription &parameter : group.parameters) {
        if (isReadable(parameter, level))
            reads << valueReadsOf(parameter);
    }
    return reads;
}

QList<ValueRead> readableValues(const DriveDescription &drive, PasswordLevel level)
{
    QList<ValueRead> reads;
    for (const GroupDescription &group : drive.groups)
        reads << readableValues(group, level);
    return reads;
}

QList<ValueRead> valuesOpenedBy(const DriveDescription &drive, PasswordLevel from,
                                PasswordLevel to)
{
    QList<ValueRead> reads;
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (isReadable(parameter, to) && !isReadable(parameter, from))
                reads << valueReadsOf(parameter);
        }
    }
    return reads;
}

ReadValuesJob::ReadValuesJob(Protocol protocol, QList<ValueRead> reads)
    : m_protocol(protocol)
    , m_reads(std::move(reads))
{
    promise().setProgressRange(0, total());
}

void ReadValuesJob::start()
{
    sendMore();
}

void ReadValuesJob::stopping()
{
    // Reads change nothing on the drive: what is still queued can go.
    sink().cancelPending();
    sendMore();
}

void ReadValuesJob::sendMore()
{
    // A request that cannot be sent answers at once, from within submit(): no recursion.
    if (m_sending || hasEnded())
        return;
    m_sending = true;
    while (!isCancelled() && !m_stopped && m_onTheWay < kJobRequestWindow
           && m_next < m_reads.size()) {
        const int index = int(m_next++);
        const ValueRead &read = m_reads.at(index);
        const Telegram request = read.perSet
                                     ? ValueRequests::read(read.address, quint8(1u << read.set))
                                     : ValueRequests::readStandard(m_protocol, read.address);
        ++m_onTheWay;
        sink().submit(request, [this, index](const Reply &reply) { handle(index, reply); });
    }
    m_sending = false;
    if (m_onTheWay == 0 && (isCancelled() || m_stopped || m_next >= m_reads.size()))
        end();
}

void ReadValuesJob::handle(int index, const Reply &reply)
{
    --m_onTheWay;
    ++m_done;
    ValueReading reading;
    reading.read = m_reads.at(index);
    if (const auto *value = reply.data<ParameterValue>()) {
        reading.value = value->value;
    } else {
        reading.reason = reply.message();
        reading.connectionFailed = reply.isConnectionFailure();
        // A read cancelled by the job's own cancel is no news for anybody.
        if (reading.connectionFailed && isCancelled())
            return sendMore();
        m_stopped = m_stopped || reading.connectionFailed;
    }
    promise().addResult(reading, index);
    promise().setProgressValue(m_done);
    sendMore();
}

} // namespace DriveDesk
