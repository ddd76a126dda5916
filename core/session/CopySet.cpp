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

namespace {

QList<ValueChange> changesOf(const CopySetPlan &plan)
{
    QList<ValueChange> changes;
    changes.reserve(plan.items.size());
    for (const CopySetPlan::Item &item : plan.items) {
        ValueChange change;
        change.address = item.address;
        change.steps = {WriteStep{quint8(1u << plan.to), item.raw, false}};
        changes << change;
    }
    return changes;
}

} // namespace

CopySetJob::CopySetJob(Protocol protocol, const CopySetPlan &plan)
    : WriteChangesJob(protocol, changesOf(plan))
{ }

} // namespace DriveDesk
