// How the simulated bus answers what it could not decode: the error acknowledge a real drive
// sends for a broken request, where the broken bytes name enough to address one.
#include "SimulatedBus.h"

#include "DinFraming.h"

namespace DriveDesk {

using namespace DinFraming;

// What the decoder gave up on, from its first byte through everything fed since: a decoder
// may report only the first byte of a broken telegram and look at the rest again.
QByteArray SimulatedBus::brokenBytes(const DecodeError &error) const
{
    if (error.bytes.size() > 1)
        return error.bytes;
    const qint64 start = m_fed - m_decoder->buffered() - error.bytes.size();
    if (start < m_historyStart || start > m_fed)
        return error.bytes;
    return m_history.mid(start - m_historyStart);
}

void SimulatedBus::handleError(const DecodeError &error, const QByteArray &broken, qint64 endNs)
{
    if (error.answer() == Ack::Ok)
        return; // garbage between telegrams: a drive stays silent
    // DIN: only an individually selected drive may answer.
    if (m_protocol != Protocol::Hsp5
        && (m_selection < 0 || m_selection >= kFirstGroupAddress || !station(m_selection)))
        return;
    const std::optional<Telegram> reply = errorAnswer(error, broken);
    if (!reply)
        return;
    const QByteArray sent = transmit(*reply, readyTime(endNs));
    if (sent.isEmpty())
        return;
    ++m_counters.replies;
    if (m_protocol != Protocol::Hsp5 && sent.endsWith(kEot))
        m_selection = -1;
}

// The error acknowledge for a broken request, as a response telegram of the service the
// broken bytes name. Nothing where the invoke id is unknown (a DIN66019 telegram has none) or
// the codec cannot express the answer (e.g. an unknown service).
std::optional<Telegram> SimulatedBus::errorAnswer(const DecodeError &error,
                                                  const QByteArray &bytes) const
{
    Telegram reply;
    reply.direction = Direction::Response;
    reply.ack = error.answer();
    reply.operatorInvoke = error.operatorInvoke;
    std::optional<int> service;
    if (m_protocol == Protocol::Hsp5) {
        // Byte 1: service in bits 0-5, bit 6 write.
        if (bytes.size() >= 2) {
            service = bytes[1] & 0x3F;
            reply.access = (bytes[1] & 0x40) ? Access::Write : Access::Read;
        }
    } else {
        // [EOT a a] [STX] service character (service + 47h) or, legacy, a hex digit.
        qsizetype at = bytes.startsWith(kEot) ? 3 : 0;
        reply.access = bytes.contains(kStx) ? Access::Write : Access::Read;
        if (at < bytes.size() && bytes[at] == kStx)
            ++at;
        if (at < bytes.size()) {
            const char c = bytes[at];
            const bool hexDigit = (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F');
            if (hexDigit)
                service = int(Service::Legacy);
            else if (c >= 0x47)
                service = c - 0x47;
        }
    }
    const bool legacy = service == int(Service::Legacy);
    if (error.operatorInvoke == 0 && !legacy)
        return std::nullopt;
    QList<Service> candidates;
    if (service && m_codec->supports(Service(*service), reply.access))
        candidates.append(Service(*service));
    if (m_protocol != Protocol::Hsp5 && !legacy)
        candidates.append(Service::Unspecified);
    for (Service candidate : candidates) {
        reply.service = candidate;
        reply.data = emptyDataFor(candidate);
        if (!m_codec->encode(reply).isEmpty())
            return reply;
    }
    return std::nullopt;
}

// The answer to the status interrogation ENQ: `ACK` or `code NAK`, naming no service.
Telegram SimulatedBus::statusAnswer(Ack result)
{
    Telegram reply;
    reply.service = Service::Unspecified;
    reply.access = Access::Write;
    reply.direction = Direction::Response;
    reply.ack = result;
    return reply;
}

} // namespace DriveDesk
