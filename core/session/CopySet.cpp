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

CopySetJob::CopySetJob(Protocol protocol, CopySetPlan plan)
    : m_protocol(protocol)
    , m_plan(std::move(plan))
{
    promise().setProgressRange(0, int(m_plan.items.size()));
}

void CopySetJob::start()
{
    writeNext();
}

void CopySetJob::writeNext()
{
    if (isCancelled() || isStopRequested() || m_next >= m_plan.items.size())
        return end();
    const int index = int(m_next++);
    const CopySetPlan::Item &item = m_plan.items.at(index);
    ValueChange change;
    change.address = item.address;
    change.steps = {WriteStep{quint8(1u << m_plan.to), item.raw, false}};
    sendValueChange(sink(), m_protocol, change, [this, index](const WriteOutcome &outcome) {
        promise().addResult(outcome, index);
        promise().setProgressValue(index + 1);
        if (outcome.connectionFailed && !outcome.anyAcknowledged())
            return end();
        writeNext();
    });
}

} // namespace DriveDesk
