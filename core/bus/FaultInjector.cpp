#include "FaultInjector.h"

#include "SimulatedBus.h"

namespace DriveDesk {

FaultInjector::FaultInjector(const SimulationOptions &options, int dataBits, BusCounters *counters)
    : m_corruptRate(options.corruptByteRate)
    , m_dropRate(options.dropByteRate)
    , m_dataBits(dataBits)
    , m_counters(counters)
    , m_random(options.seed)
{
}

bool FaultInjector::draw(double rate)
{
    if (rate <= 0)
        return false;
    return m_random.generateDouble() < rate;
}

bool FaultInjector::pass(char *byte)
{
    if (draw(m_dropRate)) {
        ++m_counters->droppedBytes;
        return false;
    }
    if (draw(m_corruptRate)) {
        ++m_counters->corruptedBytes;
        *byte = char(quint8(*byte) ^ quint8(1u << m_random.bounded(m_dataBits)));
    }
    return true;
}

QByteArray FaultInjector::pass(const QByteArray &bytes)
{
    if (m_dropRate <= 0 && m_corruptRate <= 0)
        return bytes;
    QByteArray out;
    out.reserve(bytes.size());
    for (char byte : bytes) {
        if (pass(&byte))
            out.append(byte);
    }
    return out;
}

} // namespace DriveDesk
