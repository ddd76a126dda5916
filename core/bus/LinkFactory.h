#pragma once

#include "link/ConnectionSettings.h"
#include "link/Link.h"

#include <memory>

namespace DriveDesk {

// The link the settings describe: SerialLink, TcpLink or SimulatedLink.
std::unique_ptr<Link> makeLink(const ConnectionSettings &settings, QObject *parent = nullptr);

// makeLink() for a client: every kind of link DriveDesk has, the simulated drive included.
LinkMaker everyLink();

} // namespace DriveDesk
