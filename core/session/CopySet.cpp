#include "CopySet.h"

#include "parameters/ParameterAccess.h"

namespace DriveDesk {

CopySetPlan planCopySet(const DriveDescription &drive, int from, int to, PasswordLevel level)
{
    CopySetPlan plan;
    plan.from = from;
    plan.to = to;
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (!parameter.isSetProgrammable())
                continue;
            const std::optional<qint32> source = parameter.values[std::size_t(from)];
            if (!source) {
                ++plan.unknown;
                continue;
            }
            if (parameter.values[std::size_t(to)] == source)
                continue;
            if (!isWritable(parameter, level)) {
                ++plan.locked;
                continue;
            }
            plan.items << CopySetPlan::Item{parameter.address, *source};
        }
    }
    return plan;
}

} // namespace DriveDesk
