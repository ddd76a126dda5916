#include "ConnectionSettings.h"

#include "SerialLink.h"

#include <QCoreApplication>

namespace DriveDesk {

namespace {

// The translation context of this file's messages: ConnectionSettings is a plain value type.
class ConnectionSettingsText
{
    Q_DECLARE_TR_FUNCTIONS(ConnectionSettingsText)
};

bool isDin(Protocol protocol)
{
    return protocol == Protocol::Din66019II || protocol == Protocol::Din66019;
}

QString protocolTitle(Protocol protocol)
{
    switch (protocol) {
    case Protocol::Hsp5: return QStringLiteral("HSP5");
    case Protocol::Din66019II: return QStringLiteral("DIN66019II");
    case Protocol::Din66019: return QStringLiteral("DIN66019");
    }
    return QString();
}

// "HOST:PORT" or "[IPv6]:PORT".
bool splitHostPort(const QString &text, QString *host, quint16 *port, QString *error)
{
    QString hostPart;
    QString portPart;
    if (text.startsWith(QLatin1Char('['))) {
        const qsizetype close = text.indexOf(QLatin1Char(']'));
        if (close < 0 || text.mid(close + 1, 1) != QLatin1String(":")) {
            *error = ConnectionSettingsText::tr(
                         "\"%1\" is not HOST:PORT (an IPv6 address is written [ADDRESS]:PORT)")
                         .arg(text);
            return false;
        }
        hostPart = text.mid(1, close - 1);
        portPart = text.mid(close + 2);
    } else {
        const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
        if (colon < 0) {
            *error
                = ConnectionSettingsText::tr("\"%1\" has no port: write tcp:HOST:PORT").arg(text);
            return false;
        }
        hostPart = text.left(colon);
        portPart = text.mid(colon + 1);
    }
    if (hostPart.isEmpty()) {
        *error = ConnectionSettingsText::tr("the host is missing in \"%1\": write tcp:HOST:PORT")
                     .arg(text);
        return false;
    }
    bool ok = false;
    const uint number = portPart.toUInt(&ok);
    if (!ok || number < 1 || number > 65535) {
        *error = ConnectionSettingsText::tr("\"%1\" is not a TCP port (1..65535)").arg(portPart);
        return false;
    }
    *host = hostPart;
    *port = quint16(number);
    return true;
}

} // namespace

QSerialPort::DataBits ConnectionSettings::effectiveDataBits() const
{
    if (dataBits)
        return *dataBits;
    return isDin(protocol) ? QSerialPort::Data7 : QSerialPort::Data8;
}

QSerialPort::Parity ConnectionSettings::effectiveParity() const
{
    return parity.value_or(QSerialPort::EvenParity);
}

QSerialPort::StopBits ConnectionSettings::effectiveStopBits() const
{
    return stopBits.value_or(QSerialPort::OneStop);
}

bool ConnectionSettings::parseTarget(const QString &target, QString *error)
{
    QString scratch;
    QString &message = error ? *error : scratch;
    const QString text = target.trimmed();
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    const QString scheme = (colon < 0 ? text : text.left(colon)).toLower();
    const QString rest = colon < 0 ? QString() : text.mid(colon + 1);

    if (scheme == QLatin1String("sim") || scheme == QLatin1String("simulated")) {
        if (!rest.isEmpty()) {
            message = ConnectionSettingsText::tr(
                          "\"%1\": the simulated drive takes no further address (write sim)")
                          .arg(target);
            return false;
        }
        kind = Kind::Simulated;
        return true;
    }
    if (scheme == QLatin1String("tcp")) {
        QString newHost;
        quint16 newPort = 0;
        if (!splitHostPort(rest, &newHost, &newPort, &message))
            return false;
        kind = Kind::Tcp;
        host = newHost;
        port = newPort;
        return true;
    }
    if (scheme == QLatin1String("serial")) {
        if (rest.isEmpty()) {
            message = ConnectionSettingsText::tr(
                          "\"%1\" names no serial device: write serial:/dev/ttyUSB0 or serial:COM3")
                          .arg(target);
            return false;
        }
        kind = Kind::Serial;
        device = rest;
        return true;
    }
    message = ConnectionSettingsText::tr(
                  "unknown connection \"%1\": expected tcp:HOST:PORT, serial:DEVICE or sim")
                  .arg(target);
    return false;
}

QString ConnectionSettings::target() const
{
    switch (kind) {
    case Kind::Simulated: return QStringLiteral("sim");
    case Kind::Serial: return QStringLiteral("serial:") + device;
    case Kind::Tcp:
        if (host.contains(QLatin1Char(':')))
            return QStringLiteral("tcp:[%1]:%2").arg(host).arg(port);
        return QStringLiteral("tcp:%1:%2").arg(host).arg(port);
    }
    return QString();
}

QString ConnectionSettings::displayName() const
{
    QString what = protocolTitle(protocol);
    if (isDin(protocol) && kind != Kind::Simulated)
        what += ConnectionSettingsText::tr(" drive %1").arg(driveAddress);
    switch (kind) {
    case Kind::Simulated:
        return ConnectionSettingsText::tr("simulated %1 drive").arg(what);
    case Kind::Serial:
        return ConnectionSettingsText::tr("%1 on %2 (%3 %4)")
            .arg(what, device)
            .arg(baudRate)
            .arg(characterFormatName(effectiveDataBits(), effectiveParity(), effectiveStopBits()));
    case Kind::Tcp:
        return ConnectionSettingsText::tr("%1 via %2").arg(what, target().mid(4));
    }
    return what;
}

} // namespace DriveDesk
