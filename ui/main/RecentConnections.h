#pragma once

#include "link/ConnectionSettings.h"

#include <QList>

namespace DriveDesk {

// The connections used lately, most recent first, kept in QSettings ("connections/recent").
// The first one is the last connection: what the connection dialog offers on the next start.
class RecentConnections
{
public:
    static constexpr int kMaximum = 10;

    static QList<ConnectionSettings> load();
    // Puts `settings` first (dropping an equal entry further down) and saves the list.
    static void remember(const ConnectionSettings &settings);
    // The last connection, or the simulated HSP5 drive on first start.
    static ConnectionSettings last();

    // The same drive: kind, device or host and port, protocol, address and baud rate.
    static bool sameConnection(const ConnectionSettings &a, const ConnectionSettings &b);
    // "simulated HSP5 drive", "DIN66019II drive 3 on /dev/ttyUSB0 (38400 8E1)".
    static QString describe(const ConnectionSettings &settings);
};

} // namespace DriveDesk
