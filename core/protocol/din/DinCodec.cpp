#include "DinCodec.h"

#include "DinCharacters.h"
#include "DinFields.h"
#include "DinFrameDecoder.h"

namespace DriveDesk {

namespace {

QByteArray failed(QString *error, const QString &why)
{
    *error = why;
    return {};
}

// `STX content ETX BCC`, the BCC over everything after STX.
QByteArray dataTelegram(QByteArrayView content)
{
    QByteArray bytes;
    bytes.append(DinControl::Stx).append(content).append(DinControl::Etx);
    bytes.append(char(dinBcc(QByteArrayView(bytes).sliced(1))));
    return bytes;
}

// `content ENQ BCC` of a DIN66019II read request.
QByteArray readRequestTelegram(QByteArrayView content)
{
    QByteArray bytes = content.toByteArray();
    bytes.append(DinControl::Enq);
    bytes.append(char(dinBcc(bytes)));
    return bytes;
}

char codeCharacter(Ack ack)
{
    return dinHexDigit(int(ack));
}

QString protocolTitle(Protocol protocol)
{
    return protocol == Protocol::Din66019 ? QStringLiteral("DIN66019")
                                          : QStringLiteral("DIN66019II");
}

bool checkInvokeId(const Telegram &telegram, QString *error)
{
    if (telegram.operatorInvoke >= 1 && telegram.operatorInvoke <= 15)
        return true;
    *error = QStringLiteral("invoke id %1 is outside 1..15").arg(telegram.operatorInvoke);
    return false;
}

bool checkAck(const Telegram &telegram, QString *error)
{
    if (int(telegram.ack) <= 15)
        return true;
    *error = QStringLiteral("acknowledge %1 does not fit one hex character").arg(int(telegram.ack));
    return false;
}

} // namespace

DinCodec::DinCodec(Protocol protocol)
    : m_protocol(protocol)
{
    Q_ASSERT(protocol == Protocol::Din66019II || protocol == Protocol::Din66019);
}

bool DinCodec::supports(Service service, Access access) const
{
    if (service == Service::Legacy)
        return true;
    if (service == Service::StatusInterrogation)
        return access == Access::Read;
    if (m_protocol != Protocol::Din66019II)
        return false;
    return access == Access::Read ? isDinReadable(service) : isDinWritable(service);
}

QByteArray DinCodec::encode(const Telegram &telegram, QString *error) const
{
    QString why;
    QByteArray bytes;
    if (telegram.service == Service::Unspecified) {
        if (telegram.isResponse())
            bytes = encodeShortAnswer(telegram, &why);
        else
            why = QStringLiteral("a request must name its service");
    } else if (!supports(telegram.service, telegram.access)) {
        why = QStringLiteral("%1 has no %2 of %3")
                  .arg(protocolTitle(m_protocol),
                       telegram.isWrite() ? QStringLiteral("write") : QStringLiteral("read"),
                       serviceName(telegram.service));
    } else if (telegram.isResponse()) {
        bytes = encodeResponse(telegram, &why);
    } else {
        bytes = encodeRequest(telegram, &why);
    }
    if (bytes.isEmpty() && error)
        *error = why;
    return bytes;
}

QByteArray DinCodec::encodeRequest(const Telegram &telegram, QString *error) const
{
    QByteArray bytes;
    if (telegram.driveAddress >= 0) {
        if (telegram.driveAddress > 0xFF) {
            return failed(
                error,
                QStringLiteral("drive address %1 is outside 0..255").arg(telegram.driveAddress));
        }
        bytes.append(DinControl::Eot);
        bytes.append(dinHexDigit(telegram.driveAddress >> 4));
        bytes.append(dinHexDigit(telegram.driveAddress));
    }
    if (telegram.service == Service::StatusInterrogation)
        return bytes.append(DinControl::Enq);

    const DinForm form = telegram.isWrite() ? DinForm::WriteRequest : DinForm::ReadRequest;
    const auto fields = encodeDinFields(telegram.service, form, telegram.data, error);
    if (!fields)
        return {};
    if (telegram.service == Service::Legacy) {
        if (telegram.isWrite())
            return bytes.append(dataTelegram(*fields));
        return bytes.append(*fields).append(DinControl::Enq); // DIN66019 reads carry no BCC
    }
    if (!checkInvokeId(telegram, error))
        return {};
    QByteArray content;
    content.append(dinServiceCharacter(telegram.service));
    content.append(dinHexDigit(telegram.operatorInvoke));
    content.append(*fields);
    return bytes.append(telegram.isWrite() ? dataTelegram(content) : readRequestTelegram(content));
}

QByteArray DinCodec::encodeResponse(const Telegram &telegram, QString *error) const
{
    if (!checkAck(telegram, error))
        return {};
    const bool ok = telegram.ack == Ack::Ok;
    const char negative = telegram.isWrite() ? DinControl::Nak : DinControl::Eot;
    QByteArray bytes;
    if (telegram.service == Service::StatusInterrogation || telegram.service == Service::Legacy) {
        if (!ok)
            return bytes.append(codeCharacter(telegram.ack)).append(negative);
        if (telegram.service == Service::StatusInterrogation || telegram.isWrite())
            return bytes.append(DinControl::Ack);
        const auto fields
            = encodeDinFields(Service::Legacy, DinForm::ReadResponse, telegram.data, error);
        return fields ? dataTelegram(*fields) : QByteArray();
    }

    if (!checkInvokeId(telegram, error))
        return {};
    const char invokeId = dinHexDigit(telegram.operatorInvoke);
    const bool duplex = isDinDuplex(telegram.service);
    if (!duplex) {
        // The answers without data: any error, a write, and the 32/33 check.
        if (!ok)
            return bytes.append(invokeId).append(codeCharacter(telegram.ack)).append(negative);
        if (telegram.isWrite() || !hasDinFields(telegram.service, DinForm::ReadResponse))
            return bytes.append(invokeId).append(DinControl::Ack);
    }
    const DinForm form = duplex ? DinForm::WriteResponse : DinForm::ReadResponse;
    const auto fields = encodeDinFields(telegram.service, form, telegram.data, error);
    if (!fields)
        return {};
    QByteArray content;
    content.append(dinServiceCharacter(telegram.service)).append(invokeId).append(*fields);
    if (duplex)
        content.append(codeCharacter(telegram.ack));
    return dataTelegram(content);
}

// Service::Unspecified: the answers that name no service. Invoke id 0 gives the DIN66019 forms.
QByteArray DinCodec::encodeShortAnswer(const Telegram &telegram, QString *error) const
{
    if (!checkAck(telegram, error))
        return {};
    QByteArray bytes;
    if (telegram.operatorInvoke != 0) {
        if (m_protocol == Protocol::Din66019)
            return failed(error, QStringLiteral("DIN66019 answers carry no invoke id"));
        if (!checkInvokeId(telegram, error))
            return {};
        bytes.append(dinHexDigit(telegram.operatorInvoke));
    }
    if (telegram.access == Access::Read) {
        if (telegram.ack == Ack::Ok)
            return failed(error, QStringLiteral("a read answer without data needs an error code"));
        return bytes.append(codeCharacter(telegram.ack)).append(DinControl::Eot);
    }
    if (telegram.ack == Ack::Ok)
        return bytes.append(DinControl::Ack);
    return bytes.append(codeCharacter(telegram.ack)).append(DinControl::Nak);
}

std::unique_ptr<FrameDecoder> DinCodec::makeDecoder(Role role) const
{
    return std::make_unique<DinFrameDecoder>(role);
}

} // namespace DriveDesk
