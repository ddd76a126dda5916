#include "ScopeChannel.h"

#include <QCoreApplication>

namespace DriveDesk {

QString ScopeChannel::title(int index) const
{
    if (!source || id.isEmpty())
        return QCoreApplication::translate("ScopeChannel", "Channel %1").arg(index + 1);
    return name.isEmpty() ? id : id + QLatin1Char(' ') + name;
}

bool ScopeChannel::operator==(const ScopeChannel &other) const
{
    return source == other.source && setMask == other.setMask && enabled == other.enabled
           && id == other.id && name == other.name && scaling.data() == other.scaling.data();
}

} // namespace DriveDesk
