#pragma once

#include <QString>

#include <optional>

namespace DriveDesk {

// "HOST:PORT" after "tcp:", as the client's --connect and the simulated drive's --listen both
// write it: HOST a name or an IPv4 address, an IPv6 address in brackets ([::1]:5020).
struct TcpTarget {
    QString host; // without the brackets of an IPv6 address
    quint16 port = 0;

    enum class Port : quint8 {
        Given,    // 1..65535: where to connect
        AnyFree,  // 0..65535, 0 for any free one: where a server listens
    };
    // Nothing, and why in `error`, for anything else.
    static std::optional<TcpTarget> parse(const QString &hostPort, Port port,
                                          QString *error = nullptr);
};

} // namespace DriveDesk
