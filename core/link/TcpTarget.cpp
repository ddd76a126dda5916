#include "TcpTarget.h"

#include <QCoreApplication>

namespace DriveDesk {

// The messages keep the context they have always had in the catalogues.
std::optional<TcpTarget> TcpTarget::parse(const QString &hostPort, Port port, QString *error)
{
    const auto fail = [error](const QString &message) -> std::optional<TcpTarget> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    QString hostPart;
    QString portPart;
    if (hostPort.startsWith(QLatin1Char('['))) {
        const qsizetype close = hostPort.indexOf(QLatin1Char(']'));
        if (close < 0 || hostPort.mid(close + 1, 1) != QLatin1String(":"))
            return fail(QCoreApplication::translate(
                            "ConnectionSettingsText",
                            "\"%1\" is not HOST:PORT (an IPv6 address is written [ADDRESS]:PORT)")
                            .arg(hostPort));
        hostPart = hostPort.mid(1, close - 1);
        portPart = hostPort.mid(close + 2);
    } else {
        const qsizetype colon = hostPort.lastIndexOf(QLatin1Char(':'));
        if (colon < 0)
            return fail(QCoreApplication::translate("ConnectionSettingsText",
                                                    "\"%1\" has no port: write tcp:HOST:PORT")
                            .arg(hostPort));
        hostPart = hostPort.left(colon);
        portPart = hostPort.mid(colon + 1);
    }
    if (hostPart.isEmpty())
        return fail(QCoreApplication::translate("ConnectionSettingsText",
                                                "the host is missing in \"%1\": write "
                                                "tcp:HOST:PORT")
                        .arg(hostPort));
    bool ok = false;
    const uint number = portPart.toUInt(&ok);
    const uint lowest = port == Port::AnyFree ? 0 : 1;
    if (!ok || number < lowest || number > 65535) {
        return fail(port == Port::AnyFree
                        ? QCoreApplication::translate("ConnectionSettingsText",
                                                      "\"%1\" is not a TCP port (0..65535, 0 "
                                                      "picks a free one)")
                              .arg(portPart)
                        : QCoreApplication::translate("ConnectionSettingsText",
                                                      "\"%1\" is not a TCP port (1..65535)")
                              .arg(portPart));
    }
    return TcpTarget{hostPart, quint16(number)};
}

} // namespace DriveDesk
