#include "SetList.h"

#include "DriveDescription.h"

#include <QStringList>

namespace DriveDesk {

QString SetList::text(quint8 mask)
{
    if (mask == 0)
        return tr("no set");
    if (mask == 0xFF)
        return tr("all sets");
    QStringList sets;
    for (int set = 0; set < kParameterSets; ++set) {
        if (mask & (1u << set))
            sets << QString::number(set);
    }
    if (sets.size() == 1)
        return tr("set %1").arg(sets.constFirst());
    return tr("sets %1").arg(sets.join(QStringLiteral(", ")));
}

quint8 SetList::setsWritten(bool setProgrammable, quint8 mask)
{
    return setProgrammable || mask == 0 ? mask : quint8(0x01);
}

quint8 SetList::setsWritten(const ParameterDescription &parameter, quint8 mask)
{
    return setsWritten(parameter.isSetProgrammable(), mask);
}

QString SetList::standardSetText(quint8 set)
{
    switch (set) {
    case 0:
        return tr("active set");
    case 1:
        return tr("set of the set pointer");
    default:
        return tr("set selection %1").arg(set);
    }
}

} // namespace DriveDesk
