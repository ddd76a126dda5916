#include "DinFrameDecoder.h"

#include "DinCharacters.h"
#include "DinTelegramReader.h"

namespace DriveDesk {

namespace {

// The longest telegram between STX and ETX: service 13 written with 64 bytes of data.
constexpr qsizetype MaxCharacters = 140;
// A longer run of garbage is reported in pieces, so that it never grows without bound.
constexpr qsizetype MaxGarbage = 256;

// End of the run of line characters (20h..7Fh) that starts at `from`.
qsizetype lineRunEnd(QByteArrayView bytes, qsizetype from)
{
    qsizetype end = from;
    while (end < bytes.size() && isDinLineCharacter(bytes[end]))
        ++end;
    return end;
}

bool isShortAnswerEnd(char c)
{
    return c == DinControl::Ack || c == DinControl::Nak || c == DinControl::Eot;
}

DecodeError framingError(QByteArrayView bytes, const QString &detail)
{
    DecodeError error;
    error.kind = DecodeError::Kind::Framing;
    error.bytes = bytes.toByteArray();
    error.detail = detail;
    error.operatorInvoke
        = dinInvokeIdOf(!bytes.isEmpty() && bytes[0] == DinControl::Stx ? bytes.sliced(1) : bytes);
    return error;
}

// One piece of the stream: its kind and how many bytes it spans.
struct Unit
{
    enum Kind : quint8 {
        Incomplete, // wait for more bytes
        Garbage, // belongs to no telegram
        Selection, // EOT a a
        BrokenSelection, // EOT without two hex characters
        Broken, // a telegram cut off or too long
        Frame, // STX ... ETX BCC
        ReadRequest, // Svc IID ... ENQ BCC or aaaa ENQ
        ShortAnswer, // [IID] [code] ACK / NAK / EOT
        StatusInterrogation, // ENQ
    };
    Kind kind = Incomplete;
    qsizetype length = 0;
    QString detail; // Broken, BrokenSelection
};

Unit frameUnit(QByteArrayView bytes)
{
    const qsizetype end = lineRunEnd(bytes, 1);
    if (end - 1 > MaxCharacters) {
        return { Unit::Broken, MaxCharacters + 2,
                 QStringLiteral("no ETX within %1 characters after STX").arg(MaxCharacters) };
    }
    if (end == bytes.size())
        return {};
    if (bytes[end] != DinControl::Etx) {
        return {
            Unit::Broken, end,
            QStringLiteral("telegram cut off by %1 before ETX").arg(dinCharacterName(bytes[end]))
        };
    }
    if (end + 1 == bytes.size())
        return {};
    if (!isDinLineCharacter(bytes[end + 1]))
        return { Unit::Broken, end + 1, QStringLiteral("BCC missing after ETX") };
    return { Unit::Frame, end + 2, {} };
}

Unit readRequestUnit(QByteArrayView bytes)
{
    const qsizetype end = lineRunEnd(bytes, 0);
    if (end > MaxCharacters) {
        return { Unit::Broken, MaxCharacters + 1,
                 QStringLiteral("no ENQ within %1 characters").arg(MaxCharacters) };
    }
    if (end == bytes.size())
        return {};
    if (bytes[end] != DinControl::Enq) {
        return { Unit::Broken, end,
                 QStringLiteral("read request cut off by %1 before ENQ")
                     .arg(dinCharacterName(bytes[end])) };
    }
    if (isDinHexDigit(bytes[0])) // DIN66019 `aaaa ENQ` has no BCC
        return { Unit::ReadRequest, end + 1, {} };
    if (end + 1 == bytes.size())
        return {};
    if (!isDinLineCharacter(bytes[end + 1]))
        return { Unit::Broken, end + 1, QStringLiteral("BCC missing after ENQ") };
    return { Unit::ReadRequest, end + 2, {} };
}

Unit selectionUnit(QByteArrayView bytes)
{
    for (qsizetype i = 1; i <= 2; ++i) {
        if (i == bytes.size())
            return {};
        if (!isDinLineCharacter(bytes[i])) {
            return { Unit::BrokenSelection, i,
                     QStringLiteral("selection cut off by %1: EOT needs two hex characters")
                         .arg(dinCharacterName(bytes[i])) };
        }
    }
    if (isDinHexDigit(bytes[1]) && isDinHexDigit(bytes[2]))
        return { Unit::Selection, 3, {} };
    return { Unit::BrokenSelection, 3,
             QStringLiteral("selection %1 %2 is not an address 00..FF in upper-case hex")
                 .arg(dinCharacterName(bytes[1]), dinCharacterName(bytes[2])) };
}

Unit requestUnit(QByteArrayView bytes)
{
    const char first = bytes[0];
    if (first == DinControl::Stx)
        return frameUnit(bytes);
    if (first == DinControl::Eot)
        return selectionUnit(bytes);
    if (first == DinControl::Enq)
        return { Unit::StatusInterrogation, 1, {} };
    if (isDinHexDigit(first) || isDinServiceCharacter(first))
        return readRequestUnit(bytes);
    return { Unit::Garbage, 1, {} };
}

// Short answers are told apart by their character count alone: ACK, IID ACK, code NAK,
// IID code NAK, code EOT, IID code EOT. Line characters that lead up to none of them are
// garbage.
Unit answerUnit(QByteArrayView bytes)
{
    const char first = bytes[0];
    if (first == DinControl::Stx)
        return frameUnit(bytes);
    if (first == DinControl::Ack)
        return { Unit::ShortAnswer, 1, {} };
    if (!isDinLineCharacter(first))
        return { Unit::Garbage, 1, {} };
    if (bytes.size() < 2)
        return {};
    if (isShortAnswerEnd(bytes[1]))
        return { Unit::ShortAnswer, 2, {} };
    if (!isDinLineCharacter(bytes[1]))
        return { Unit::Garbage, 1, {} };
    if (bytes.size() < 3)
        return {};
    if (bytes[2] == DinControl::Nak || bytes[2] == DinControl::Eot)
        return { Unit::ShortAnswer, 3, {} };
    return { Unit::Garbage, 1, {} };
}

} // namespace

DinFrameDecoder::DinFrameDecoder(Role role)
    : m_role(role)
{ }

void DinFrameDecoder::feed(QByteArrayView bytes)
{
    m_buffer.append(bytes);
    qsizetype position = 0;
    while (position < m_buffer.size()) {
        const QByteArrayView rest = QByteArrayView(m_buffer).sliced(position);
        const Unit unit = m_role == Role::Drive ? requestUnit(rest) : answerUnit(rest);
        if (unit.kind == Unit::Incomplete)
            break;
        const QByteArrayView bytes = rest.first(unit.length);
        position += unit.length;
        switch (unit.kind) {
        case Unit::Incomplete:
            break;
        case Unit::Garbage:
            m_garbage.append(bytes);
            if (m_garbage.size() >= MaxGarbage)
                flushGarbage();
            break;
        case Unit::Selection:
            flushGarbage();
            m_selection = dinHexValue(bytes[1]) * 16 + dinHexValue(bytes[2]);
            break;
        case Unit::BrokenSelection:
            m_selection = -1; // a new EOT ends the previous selection even when it is broken
            emitItem(framingError(bytes, unit.detail), false);
            break;
        case Unit::Broken:
            emitItem(framingError(bytes, unit.detail), m_role == Role::Drive);
            break;
        case Unit::Frame:
            emitItem(readDinFrame(bytes, m_role), m_role == Role::Drive);
            break;
        case Unit::ReadRequest:
            emitItem(readDinReadRequest(bytes), true);
            break;
        case Unit::ShortAnswer:
            emitItem(readDinShortAnswer(bytes), false);
            break;
        case Unit::StatusInterrogation: {
            Telegram telegram;
            telegram.service = Service::StatusInterrogation;
            telegram.access = Access::Read;
            telegram.direction = Direction::Request;
            emitItem(telegram, true);
            break;
        }
        }
    }
    m_buffer.remove(0, position);
}

void DinFrameDecoder::emitItem(Decoded item, bool request)
{
    flushGarbage();
    if (request) {
        if (auto *telegram = std::get_if<Telegram>(&item))
            telegram->driveAddress = m_selection;
        else
            std::get<DecodeError>(item).driveAddress = m_selection;
        m_selection = -1;
    }
    m_items.enqueue(std::move(item));
}

void DinFrameDecoder::flushGarbage()
{
    if (m_garbage.isEmpty())
        return;
    DecodeError error;
    error.kind = DecodeError::Kind::UnexpectedByte;
    error.bytes = m_garbage;
    error.detail = QStringLiteral("%1 bytes outside any telegram skipped").arg(m_garbage.size());
    m_items.enqueue(error);
    m_garbage.clear();
}

std::optional<Decoded> DinFrameDecoder::next()
{
    if (m_items.isEmpty())
        return std::nullopt;
    return m_items.dequeue();
}

void DinFrameDecoder::reset()
{
    m_buffer.clear();
    m_garbage.clear();
}

qsizetype DinFrameDecoder::buffered() const
{
    return m_buffer.size() + m_garbage.size();
}

} // namespace DriveDesk
