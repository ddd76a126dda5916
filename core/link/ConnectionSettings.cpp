#include "ConnectionSettings.h"

#include "SerialLink.h"
#include "TcpTarget.h"

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
        const std::optional<TcpTarget> tcp = TcpTarget::parse(rest, TcpTarget::Port::Given,
                                                              &message);
        if (!tcp)
            return false;
        kind = Kind::Tcp;
        host = tcp->host;
        port = tcp->port;
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
        what = ConnectionSettingsText::tr("%1 drive %2").arg(what).arg(driveAddress);
    switch (kind) {
    case Kind::Simulated:
        return ConnectionSettingsText::tr("simulated %1 drive").arg(what);
    case Kind::Serial:
        return ConnectionSettingsText::tr("%1 on %2 (%3 %4)")
            .arg(what, device)
            .arg(automaticBaudRate ? ConnectionSettingsText::tr("auto") : QString::number(baudRate))
            .arg(characterFormatName(effectiveDataBits(), effectiveParity(), effectiveStopBits()));
    case Kind::Tcp:
        return ConnectionSettingsText::tr("%1 via %2").arg(what, target().mid(4));
    }
    return what;
}

} // namespace DriveDesk
