#include "ScopeChannel.h"

#include <QCoreApplication>

#include <bit>

namespace DriveDesk {

QString ScopeChannel::title(int index) const
{
    if (!source || id.isEmpty())
        return QCoreApplication::translate("ScopeChannel", "Channel %1").arg(index + 1);
    const QString parameter = name.isEmpty() ? id : id + QLatin1Char(' ') + name;
    if (setMask == 0x01 || setMask == 0)
        return parameter;
    // A drive reads a channel from the lowest set of its mask.
    const int set = std::countr_zero(unsigned(setMask));
    return QCoreApplication::translate("ScopeChannel", "%1 (set %2)").arg(parameter).arg(set);
}

bool ScopeChannel::operator==(const ScopeChannel &other) const
{
    return source == other.source && setMask == other.setMask && enabled == other.enabled
           && id == other.id && name == other.name && scaling.data() == other.scaling.data();
}

} // namespace DriveDesk
