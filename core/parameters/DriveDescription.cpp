#include "DriveDescription.h"

#include "ParameterId.h"

namespace DriveDesk {

int DriveDescription::parameterCount() const
{
    int count = 0;
    for (const GroupDescription &group : groups)
        count += int(group.parameters.size());
    return count;
}

const ParameterDescription *DriveDescription::find(quint16 address) const
{
    // Half-page groups (0280h next to 0200h) share a high byte, so every group is searched.
    for (const GroupDescription &group : groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (parameter.address == address)
                return &parameter;
        }
    }
    return nullptr;
}

const GroupDescription *DriveDescription::findGroup(const QString &id) const
{
    // KEB ids mix case ("Sy", "dS"): an exact match wins over a case-insensitive one.
    const GroupDescription *caseInsensitive = nullptr;
    for (const GroupDescription &group : groups) {
        if (group.id == id)
            return &group;
        if (!caseInsensitive && group.id.compare(id, Qt::CaseInsensitive) == 0)
            caseInsensitive = &group;
    }
    return caseInsensitive;
}

QString parameterId(const QString &groupId, quint8 number)
{
    return QStringLiteral("%1.%2").arg(groupId).arg(number, 2, 10, QLatin1Char('0'));
}

QString parameterId(const GroupDescription &group, const ParameterDescription &parameter)
{
    return ParameterId::format(parameter.address, GroupAddress { group.id, group.address });
}

} // namespace DriveDesk
