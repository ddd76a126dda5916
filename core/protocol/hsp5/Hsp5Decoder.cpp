#include "Hsp5Decoder.h"

#include "Hsp5Codec.h"
#include "Hsp5Fields.h"
#include "Hsp5Layout.h"

namespace DriveDesk {

namespace {

QString hexByte(quint8 byte)
{
    return QString::number(byte, 16).toUpper().rightJustified(2, QLatin1Char('0'))
           + QLatin1Char('h');
}

QString hexBytes(QByteArrayView bytes)
{
    return QString::fromLatin1(bytes.toByteArray().toHex(' ').toUpper());
}

QString kindOf(Service service, bool write, bool response)
{
    return QStringLiteral("service %1 (%2) %3 %4")
        .arg(int(service))
        .arg(serviceName(service),
             write ? QStringLiteral("write") : QStringLiteral("read"),
             response ? QStringLiteral("response") : QStringLiteral("request"));
}

} // namespace

// The verdict on the bytes from one position on, using only those bytes.
struct Hsp5Decoder::Check
{
    enum class Verdict : quint8 { NeedMore, Good, Bad };
    Verdict verdict = Verdict::NeedMore;
    qsizetype length = -1; // of the candidate telegram, once known
    qsizetype decidedAt = 0; // how many bytes the verdict needed
    DecodeError::Kind kind = DecodeError::Kind::UnexpectedByte;
    QString detail;        // only when asked to explain
    Telegram telegram;     // when good
};

void Hsp5Decoder::feed(QByteArrayView bytes)
{
    if (m_start > 0) {
        m_buffer.remove(0, m_start);
        m_start = 0;
    }
    m_buffer.append(bytes);
}

void Hsp5Decoder::reset()
{
    m_buffer.clear();
    m_start = 0;
    m_skipped.clear();
    m_skippedReason.clear();
    m_inStep = true;
}

qsizetype Hsp5Decoder::buffered() const
{
    return m_buffer.size() - m_start + m_skipped.size();
}

Hsp5Decoder::Check Hsp5Decoder::check(qsizetype at, bool explain) const
{
    using Verdict = Check::Verdict;
    using Kind = DecodeError::Kind;
    Check c;
    const auto bad = [&](qsizetype decidedAt, Kind kind, auto &&detail) {
        c.verdict = Verdict::Bad;
        c.decidedAt = decidedAt;
        c.kind = kind;
        if (explain)
            c.detail = detail();
        return c;
    };
    const qsizetype available = m_buffer.size() - at;
    if (available < 1)
        return c;
    const auto byte = [&](qsizetype i) { return quint8(m_buffer[at + i]); };

    const quint8 operatorInvoke = byte(0) >> 4;
    const quint8 inverterInvoke = byte(0) & 0x0F;
    if ((operatorInvoke == 0) == (inverterInvoke == 0)) {
        return bad(1, Kind::UnexpectedByte, [&] {
            return QStringLiteral("%1 starts no telegram: INV-ID-OP and INV-ID-FU are both %2")
                .arg(hexByte(byte(0)),
                     operatorInvoke == 0 ? QStringLiteral("0") : QStringLiteral("set"));
        });
    }
    if (available < 2)
        return c;

    const quint8 serviceByte = byte(1);
    const bool response = serviceByte & 0x80;
    const bool write = serviceByte & 0x40;
    const int number = serviceByte & 0x3F;
    // The operator takes responses to its requests and requests the inverter starts; the drive
    // the other two.
    const bool fromOperatorCycle = operatorInvoke != 0;
    const bool wanted = m_role == Role::Operator ? response == fromOperatorCycle
                                                 : response != fromOperatorCycle;
    if (!wanted) {
        return bad(2, Kind::UnexpectedByte, [&] {
            return QStringLiteral("%1 %2 is a %3 in a cycle the %4 started (INV-ID-%5 %6), "
                                  "no input for the %7")
                .arg(hexByte(byte(0)), hexByte(serviceByte),
                     response ? QStringLiteral("response") : QStringLiteral("request"),
                     fromOperatorCycle ? QStringLiteral("operator") : QStringLiteral("inverter"),
                     fromOperatorCycle ? QStringLiteral("OP") : QStringLiteral("FU"))
                .arg(fromOperatorCycle ? operatorInvoke : inverterInvoke)
                .arg(m_role == Role::Operator ? QStringLiteral("operator")
                                              : QStringLiteral("drive"));
        });
    }
    const auto service = hsp5Service(number, m_services);
    if (!service) {
        return bad(2, Kind::UnknownService, [&] {
            return QStringLiteral("service %1 (byte 1 = %2) is not defined in HSP5")
                .arg(number)
                .arg(hexByte(serviceByte));
        });
    }
    const Access access = write ? Access::Write : Access::Read;
    const Direction direction = response ? Direction::Response : Direction::Request;
    const auto layout = hsp5Layout(*service, access, direction, m_services);
    if (!layout) {
        return bad(2, Kind::UnknownService, [&] {
            return QStringLiteral("HSP5 has no %1 (byte 1 = %2)")
                .arg(kindOf(*service, write, response), hexByte(serviceByte));
        });
    }
    qsizetype length = layout->length;
    if (layout->isVariable()) {
        if (available <= layout->countByte)
            return c;
        const int count = byte(layout->countByte);
        if (count > layout->maxCount) {
            return bad(layout->countByte + 1, Kind::Framing, [&] {
                return QStringLiteral("%1 length %2 exceeds %3 in %4")
                    .arg(layout->maxCount == kHsp5MaxText ? QStringLiteral("text")
                                                          : QStringLiteral("data"))
                    .arg(count)
                    .arg(layout->maxCount)
                    .arg(kindOf(*service, write, response));
            });
        }
        length += count;
    }
    c.length = length;
    if (available < length)
        return c;

    const QByteArrayView telegram = QByteArrayView(m_buffer).sliced(at, length);
    const quint8 expected = hsp5Bcc(telegram.first(length - 1));
    const quint8 sent = byte(length - 1);
    if (sent != expected) {
        return bad(length, Kind::ChecksumMismatch, [&] {
            return QStringLiteral("BCC %1, expected %2 in %3")
                .arg(hexByte(sent), hexByte(expected), hexBytes(telegram));
        });
    }
    if (response && byte(length - 2) > 15) {
        return bad(length, Kind::Framing, [&] {
            return QStringLiteral("acknowledge %1 is beyond 15 in %2")
                .arg(byte(length - 2))
                .arg(kindOf(*service, write, response));
        });
    }

    Telegram &t = c.telegram;
    t.service = *service;
    t.access = access;
    t.direction = direction;
    t.operatorInvoke = operatorInvoke;
    t.inverterInvoke = inverterInvoke;
    t.data = emptyDataFor(*service);
    if (!readHsp5Fields(telegram.sliced(2, length - 3), t)) {
        return bad(length, Kind::Framing, [&] {
            return QStringLiteral("the fields of %1 do not fill its %2 bytes")
                .arg(kindOf(*service, write, response))
                .arg(length);
        });
    }
    c.verdict = Verdict::Good;
    c.decidedAt = length;
    return c;
}

bool Hsp5Decoder::goodTelegramInside(qsizetype at, qsizetype limit) const
{
    const qsizetype end = limit < 0 ? m_buffer.size() : qMin(at + limit, m_buffer.size());
    for (qsizetype inner = at + 1; inner < end; ++inner) {
        const Check c = check(inner, false);
        if (c.verdict == Check::Verdict::Good && (limit < 0 || inner + c.length < at + limit))
            return true;
    }
    return false;
}

std::optional<DecodeError> Hsp5Decoder::skip(const QString &why)
{
    if (m_skipped.isEmpty())
        m_skippedReason = why;
    m_skipped.append(m_buffer[m_start]);
    ++m_start;
    m_inStep = false;
    if (m_skipped.size() >= kMaxSkippedRun)
        return takeSkipped();
    return std::nullopt;
}

DecodeError Hsp5Decoder::takeSkipped()
{
    DecodeError error;
    error.kind = DecodeError::Kind::UnexpectedByte;
    error.bytes = m_skipped;
    error.detail = QStringLiteral("%1 byte(s) skipped that start no HSP5 telegram; the first: %2")
                       .arg(m_skipped.size())
                       .arg(m_skippedReason);
    m_skipped.clear();
    m_skippedReason.clear();
    return error;
}

std::optional<Decoded> Hsp5Decoder::next()
{
    using Verdict = Check::Verdict;
    while (m_start < m_buffer.size()) {
        const bool explain = m_inStep || m_skipped.isEmpty();
        Check c = check(m_start, explain);
        // Out of step, a good telegram that starts inside this candidate and is complete
        // before the candidate is decided wins: the outcome depends only on the bytes.
        const qsizetype limit = c.verdict == Verdict::Bad ? c.decidedAt : c.length;
        if (!m_inStep && goodTelegramInside(m_start, limit)) {
            const QString why = explain ? QStringLiteral("%1 begins a telegram cut short by the "
                                                         "next one")
                                              .arg(hexByte(quint8(m_buffer[m_start])))
                                        : QString();
            if (auto error = skip(why))
                return *error;
            continue;
        }
        switch (c.verdict) {
        case Verdict::NeedMore:
            return std::nullopt;
        case Verdict::Good:
            if (!m_skipped.isEmpty())
                return takeSkipped(); // the telegram follows on the next call
            m_start += c.length;
            m_inStep = true;
            return std::move(c.telegram);
        case Verdict::Bad:
            if (m_inStep && c.kind != DecodeError::Kind::UnexpectedByte) {
                DecodeError error;
                error.kind = c.kind;
                error.bytes = m_buffer.mid(m_start, 1);
                error.detail = c.detail;
                error.operatorInvoke = quint8(m_buffer[m_start]) >> 4;
                ++m_start;
                m_inStep = false;
                return error;
            }
            if (auto error = skip(c.detail))
                return *error;
            continue;
        }
    }
    return std::nullopt;
}

} // namespace DriveDesk
