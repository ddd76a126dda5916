#include "DinTelegramReader.h"

#include "DinCharacters.h"
#include "DinFields.h"

namespace DriveDesk {

namespace {

DecodeError failure(DecodeError::Kind kind, QByteArrayView bytes, const QString &detail,
                    quint8 invokeId = 0)
{
    DecodeError error;
    error.kind = kind;
    error.bytes = bytes.toByteArray();
    error.detail = detail;
    error.operatorInvoke = invokeId;
    return error;
}

QString serviceLabel(char c)
{
    return QStringLiteral("service %1").arg(dinCharacterName(c));
}

std::optional<DecodeError> checkBcc(QByteArrayView covered, char bcc, QByteArrayView bytes,
                                    quint8 invokeId)
{
    const quint8 expected = dinBcc(covered);
    if (quint8(bcc) == expected)
        return std::nullopt;
    return failure(
        DecodeError::Kind::ChecksumMismatch, bytes,
        QStringLiteral("BCC %1, expected %2").arg(dinHexName(quint8(bcc)), dinHexName(expected)),
        invokeId);
}

Decoded withFields(Telegram telegram, DinForm form, QByteArrayView fields, QByteArrayView bytes,
                   const QString &label)
{
    QString why;
    auto data = decodeDinFields(telegram.service, form, fields, &why);
    if (!data) {
        return failure(DecodeError::Kind::Framing, bytes, QStringLiteral("%1: %2").arg(label, why),
                       telegram.operatorInvoke);
    }
    telegram.data = std::move(*data);
    return telegram;
}

// `Svc IID`: the service (known, and defined in this access mode) and a valid invoke id.
std::optional<DecodeError> checkServiceAndInvokeId(QByteArrayView content, Access access,
                                                   QByteArrayView bytes)
{
    const char character = content[0];
    const quint8 invokeId = dinInvokeIdOf(content);
    const auto service = dinServiceFromCharacter(character);
    if (!service) {
        return failure(DecodeError::Kind::UnknownService, bytes,
                       QStringLiteral("service character %1 (service %2) is not defined in "
                                      "DIN66019II")
                           .arg(dinCharacterName(character))
                           .arg(int(quint8(character)) - 0x47),
                       invokeId);
    }
    const bool defined = access == Access::Read ? isDinReadable(*service) : isDinWritable(*service);
    if (!defined) {
        return failure(
            DecodeError::Kind::UnknownService, bytes,
            QStringLiteral("%1 (%2) cannot be %3")
                .arg(serviceLabel(character))
                .arg(int(*service))
                .arg(access == Access::Read ? QStringLiteral("read") : QStringLiteral("written")),
            invokeId);
    }
    if (content.size() < 2) {
        return failure(DecodeError::Kind::Framing, bytes,
                       QStringLiteral("%1: invoke id missing").arg(serviceLabel(character)));
    }
    if (invokeId == 0) {
        return failure(DecodeError::Kind::Framing, bytes,
                       QStringLiteral("%1: invoke id %2 is not 1..F")
                           .arg(serviceLabel(character), dinCharacterName(content[1])));
    }
    return std::nullopt;
}

} // namespace

Decoded readDinFrame(QByteArrayView frame, Role role)
{
    const QByteArrayView content = frame.sliced(1, frame.size() - 3);
    const quint8 invokeId = dinInvokeIdOf(content);
    if (auto error = checkBcc(frame.sliced(1, frame.size() - 2), frame.back(), frame, invokeId))
        return *error;
    if (content.isEmpty()) {
        return failure(DecodeError::Kind::Framing, frame,
                       QStringLiteral("empty telegram: ETX right after STX"));
    }

    Telegram telegram;
    const bool drive = role == Role::Drive;
    telegram.direction = drive ? Direction::Request : Direction::Response;
    const char first = content[0];
    if (isDinHexDigit(first)) {
        telegram.service = Service::Legacy;
        telegram.access = drive ? Access::Write : Access::Read;
        return withFields(telegram, drive ? DinForm::WriteRequest : DinForm::ReadResponse, content,
                          frame, QStringLiteral("DIN66019 telegram"));
    }
    if (!isDinServiceCharacter(first)) {
        return failure(DecodeError::Kind::Framing, frame,
                       QStringLiteral("%1 after STX is neither a service character nor a hex "
                                      "digit")
                           .arg(dinCharacterName(first)));
    }

    const auto service = dinServiceFromCharacter(first);
    // A master writes with STX; a drive answers with STX to reads, and to the duplex writes.
    const bool duplex = service && isDinDuplex(*service);
    const Access access = drive || duplex ? Access::Write : Access::Read;
    if (auto error = checkServiceAndInvokeId(content, access, frame))
        return *error;
    telegram.service = *service;
    telegram.access = access;
    telegram.operatorInvoke = invokeId;
    const QString label = serviceLabel(first);
    QByteArrayView fields = content.sliced(2);
    if (drive)
        return withFields(telegram, DinForm::WriteRequest, fields, frame, label);
    if (!duplex) {
        if (!hasDinFields(telegram.service, DinForm::ReadResponse)) {
            return failure(DecodeError::Kind::Framing, frame,
                           QStringLiteral("%1: the check is answered IID ACK or IID code EOT, "
                                          "never with data")
                               .arg(label),
                           invokeId);
        }
        return withFields(telegram, DinForm::ReadResponse, fields, frame, label);
    }
    if (fields.isEmpty()) {
        return failure(DecodeError::Kind::Framing, frame,
                       QStringLiteral("%1: error code missing").arg(label), invokeId);
    }
    const int code = dinHexValue(fields.back());
    if (code < 0) {
        return failure(DecodeError::Kind::Framing, frame,
                       QStringLiteral("%1: error code %2 is not an upper-case hex digit")
                           .arg(label, dinCharacterName(fields.back())),
                       invokeId);
    }
    telegram.ack = Ack(code);
    return withFields(telegram, DinForm::WriteResponse, fields.chopped(1), frame, label);
}

Decoded readDinReadRequest(QByteArrayView request)
{
    Telegram telegram;
    telegram.access = Access::Read;
    telegram.direction = Direction::Request;
    if (isDinHexDigit(request[0])) {
        telegram.service = Service::Legacy;
        return withFields(telegram, DinForm::ReadRequest, request.chopped(1), request,
                          QStringLiteral("DIN66019 read request"));
    }
    const QByteArrayView content = request.chopped(2);
    const quint8 invokeId = dinInvokeIdOf(content);
    if (auto error = checkBcc(request.chopped(1), request.back(), request, invokeId))
        return *error;
    if (auto error = checkServiceAndInvokeId(content, Access::Read, request))
        return *error;
    telegram.service = *dinServiceFromCharacter(content[0]);
    telegram.operatorInvoke = invokeId;
    return withFields(telegram, DinForm::ReadRequest, content.sliced(2), request,
                      serviceLabel(content[0]));
}

Decoded readDinShortAnswer(QByteArrayView answer)
{
    const char end = answer.back();
    const QByteArrayView characters = answer.chopped(1);
    Telegram telegram;
    telegram.service = Service::Unspecified;
    telegram.direction = Direction::Response;
    telegram.access = end == DinControl::Eot ? Access::Read : Access::Write;
    const bool withInvokeId
        = end == DinControl::Ack ? characters.size() == 1 : characters.size() == 2;
    if (withInvokeId) {
        telegram.operatorInvoke = dinInvokeId(characters[0]);
        if (telegram.operatorInvoke == 0) {
            return failure(DecodeError::Kind::Framing, answer,
                           QStringLiteral("invoke id %1 before %2 is not 1..F")
                               .arg(dinCharacterName(characters[0]), dinCharacterName(end)));
        }
    }
    if (end == DinControl::Ack)
        return telegram;
    const char code = characters.back();
    const int value = dinHexValue(code);
    if (value <= 0) {
        // A negative answer with code 0 would contradict itself.
        return failure(DecodeError::Kind::Framing, answer,
                       QStringLiteral("error code %1 before %2 is not 1..F")
                           .arg(dinCharacterName(code), dinCharacterName(end)),
                       telegram.operatorInvoke);
    }
    telegram.ack = Ack(value);
    return telegram;
}

} // namespace DriveDesk
