#include "GroupProperties.h"

namespace DriveDesk {

QStringList GroupProperties::describe() const
{
    QStringList lines;
    lines << tr("password level: %1").arg(passwordLevelName(passwordLevel()));
    if (isVisibleOnDisplay())
        lines << tr("visible on the display");
    if (isVisibleInCombivis())
        lines << tr("visible in COMBIVIS");
    for (int bit = 5; bit < 16; ++bit) {
        if (m_properties & (1u << bit))
            lines << tr("free bit %1 set").arg(bit);
    }
    return lines;
}

} // namespace DriveDesk
