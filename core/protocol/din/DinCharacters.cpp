#include "DinCharacters.h"

namespace DriveDesk {

namespace {

constexpr int ServiceOffset = 0x47;

} // namespace

quint8 dinBcc(QByteArrayView characters)
{
    quint8 bcc = 0;
    for (const char c : characters)
        bcc ^= quint8(c);
    return bcc < 0x20 ? quint8(bcc + 0x20) : bcc;
}

bool isDinLineCharacter(char c)
{
    return quint8(c) >= 0x20 && quint8(c) <= 0x7F;
}

bool isDinTextCharacter(char c)
{
    return quint8(c) >= 0x20 && quint8(c) <= 0x7E;
}

bool isDinHexDigit(char c)
{
    return dinHexValue(c) >= 0;
}

int dinHexValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

char dinHexDigit(int value)
{
    return "0123456789ABCDEF"[value & 0xF];
}

quint8 dinInvokeId(char c)
{
    const int value = dinHexValue(c);
    return value > 0 ? quint8(value) : 0;
}

quint8 dinInvokeIdOf(QByteArrayView telegram)
{
    if (telegram.size() < 2 || !isDinServiceCharacter(telegram[0]))
        return 0;
    return dinInvokeId(telegram[1]);
}

bool isDinServiceCharacter(char c)
{
    return quint8(c) >= ServiceOffset && quint8(c) <= 0x7F;
}

char dinServiceCharacter(Service service)
{
    return char(int(service) + ServiceOffset);
}

std::optional<Service> dinServiceFromCharacter(char c)
{
    if (!isDinServiceCharacter(c))
        return std::nullopt;
    const auto service = Service(quint8(c) - ServiceOffset);
    if (isDinReadable(service) || isDinWritable(service))
        return service;
    return std::nullopt;
}

bool isDinReadable(Service service)
{
    const int number = int(service);
    return (number >= 0 && number <= 14) || (number >= 16 && number <= 21) || number == 32
        || number == 33;
}

bool isDinWritable(Service service)
{
    const int number = int(service);
    return (number >= 0 && number <= 14) || (number >= 16 && number <= 20) || number == 32
        || number == 33 || isDinDuplex(service);
}

bool isDinDuplex(Service service)
{
    return int(service) >= 48 && int(service) <= 53;
}

QString dinCharacterName(char c)
{
    switch (c) {
    case DinControl::Stx:
        return QStringLiteral("STX");
    case DinControl::Etx:
        return QStringLiteral("ETX");
    case DinControl::Eot:
        return QStringLiteral("EOT");
    case DinControl::Enq:
        return QStringLiteral("ENQ");
    case DinControl::Ack:
        return QStringLiteral("ACK");
    case DinControl::Nak:
        return QStringLiteral("NAK");
    }
    if (isDinTextCharacter(c))
        return QStringLiteral("'%1'").arg(QLatin1Char(c));
    return dinHexName(quint8(c));
}

QString dinHexName(quint8 value)
{
    return QString::number(value, 16).rightJustified(2, QLatin1Char('0')).toUpper()
        + QLatin1Char('h');
}

} // namespace DriveDesk
