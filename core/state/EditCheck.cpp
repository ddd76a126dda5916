#include "EditCheck.h"

#include "parameters/ParameterAccess.h"

#include <algorithm>

namespace DriveDesk {

bool EditCheck::isAboveLevel(const ParameterProperties &properties, PasswordLevel level)
{
    return !isReadable(properties, level)
        || (!properties.isReadOnly() && !isWritable(properties, level));
}

QString EditCheck::refusal(const ParameterState &parameter, PasswordLevel level)
{
    const ParameterProperties &properties = parameter.properties();
    if (isWritable(properties, level))
        return {};
    if (properties.isReadOnly())
        return tr("%1 is read-only").arg(parameter.id());
    if (isAboveLevel(properties, level)) {
        const PasswordLevel needed = std::max(properties.readLevel(), properties.writeLevel());
        return tr("%1 needs password level %2 (in force: %3)")
            .arg(parameter.id(), passwordLevelName(needed), passwordLevelName(level));
    }
    return {};
}

QString EditCheck::valueRefusal(const ParameterState &parameter, qint32 raw, PasswordLevel level)
{
    if (QString refused = refusal(parameter, level); !refused.isEmpty())
        return refused;
    if (!parameter.format().isWithinLimits(raw))
        return tr("%1: %2").arg(parameter.id(), parameter.format().limitsProblem(raw));
    return {};
}

QString EditCheck::writeRefusal(const ParameterState &parameter, quint8 setMask, qint32 raw,
                                PasswordLevel level)
{
    if (QString refused = refusal(parameter, level); !refused.isEmpty())
        return refused;
    if (setMask == 0)
        return tr("%1: no set chosen").arg(parameter.id());
    return valueRefusal(parameter, raw, level);
}

} // namespace DriveDesk
