#include "EditOutcome.h"

namespace DriveDesk {

quint8 EditOutcome::askedMask() const
{
    quint8 mask = 0;
    for (const WriteStep &step : steps)
        mask |= step.setMask;
    return mask;
}

std::optional<qint32> EditOutcome::asked(int set) const
{
    std::optional<qint32> raw;
    for (const WriteStep &step : steps) {
        if ((step.setMask & (1u << set)) || (step.setMask == 0 && set == 0))
            raw = step.raw;
    }
    return raw;
}

} // namespace DriveDesk
