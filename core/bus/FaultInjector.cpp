#include "FaultInjector.h"

#include "SimulatedBus.h"

namespace DriveDesk {

FaultInjector::FaultInjector(const SimulationOptions &options, int dataBits, BusCounters *counters)
    : m_corruptRate(options.corruptByteRate)
    , m_dropRate(options.dropByteRate)
    , m_flipRate(options.flipByteRate)
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

FaultInjector::Fate FaultInjector::pass(char *byte)
{
    if (draw(m_dropRate)) {
        ++m_counters->droppedBytes;
        return Fate::Lost;
    }
    if (draw(m_corruptRate)) {
        // Every character carries even parity (8E1, 7E1), so one flipped bit never reaches a
        // decoder unseen: the receiving UART flags the parity error (ack 10's "transmission
        // error") and the character is not taken. Delivering the flipped byte instead would
        // model a line without parity, on which the XOR BCC lets two flips of the same bit
        // through.
        ++m_counters->corruptedBytes;
        *byte = char(quint8(*byte) ^ quint8(1u << m_random.bounded(m_dataBits)));
        return Fate::ParityError;
    }
    if (draw(m_flipRate)) {
        ++m_counters->flippedBytes;
        *byte = char(quint8(*byte) ^ quint8(1u << m_random.bounded(m_dataBits)));
        return Fate::Flipped;
    }
    return Fate::Passed;
}

QByteArray FaultInjector::pass(const QByteArray &bytes, QList<qsizetype> *lineErrors)
{
    if (m_dropRate <= 0 && m_corruptRate <= 0 && m_flipRate <= 0)
        return bytes;
    QByteArray out;
    out.reserve(bytes.size());
    for (char byte : bytes) {
        switch (pass(&byte)) {
        case Fate::Passed:
        case Fate::Flipped:
            out.append(byte);
            break;
        case Fate::ParityError:
            if (lineErrors)
                lineErrors->append(out.size());
            break;
        case Fate::Lost:
            break;
        }
    }
    return out;
}

} // namespace DriveDesk
