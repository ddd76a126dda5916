#include "LinkFactory.h"

#include "SimulatedLink.h"
#include "link/SerialLink.h"
#include "link/TcpLink.h"

namespace DriveDesk {

LinkMaker everyLink()
{
    return [](const ConnectionSettings &settings) { return makeLink(settings); };
}

std::unique_ptr<Link> makeLink(const ConnectionSettings &settings, QObject *parent)
{
    switch (settings.kind) {
    case ConnectionSettings::Kind::Serial: return std::make_unique<SerialLink>(settings, parent);
    case ConnectionSettings::Kind::Tcp: return std::make_unique<TcpLink>(settings, parent);
    case ConnectionSettings::Kind::Simulated:
        break;
    }
    return std::make_unique<SimulatedLink>(settings, parent);
}

} // namespace DriveDesk
