#include "DriveVariety.h"

#include "DatabaseLoader.h"
#include "DriveState.h"
#include "F5Addresses.h"
#include "GeneratedParameters.h"

#include <algorithm>

namespace DriveDesk::Sim {

namespace {

// The other kind is the standard drive with this many more parameters; padding raises its
// software version with them (addGeneratedParameters).
constexpr int kOtherKindExtraParameters = 24;

struct OwnSetting
{
    quint16 address;
    qint32 step; // raw units per address
};
constexpr OwnSetting kOwnSettings[] = {
    { F5::kAccelerationTime, 25 }, // 0.25 s
    { F5::kQuickStopTime, 5 },     // 0.05 s
    { F5::kFixedSpeed1, 10 },      // 10 rpm
};

} // namespace

std::shared_ptr<const ParameterDatabase> databaseFor(SimulatedDriveKind kind, int parameterCount,
                                                     quint32 seed)
{
    std::shared_ptr<const ParameterDatabase> standard = standardDatabase();
    const int standardCount = int(standard->parameters().size());
    switch (kind) {
    case SimulatedDriveKind::Standard:
        break;
    case SimulatedDriveKind::Other:
        parameterCount = std::max(parameterCount, standardCount) + kOtherKindExtraParameters;
        break;
    case SimulatedDriveKind::Unidentified: {
        auto bare = std::make_shared<ParameterDatabase>(*standard);
        for (quint16 address : F5::kIdentification)
            bare->removeParameter(address);
        if (parameterCount > standardCount)
            addGeneratedParameters(*bare, parameterCount, seed); // calls finish()
        else
            bare->finish();
        return bare;
    }
    }
    if (parameterCount <= standardCount)
        return standard;
    auto padded = std::make_shared<ParameterDatabase>(*standard);
    addGeneratedParameters(*padded, parameterCount, seed);
    return padded;
}

void giveOwnSettings(DriveState &state)
{
    const int steps = state.address() - 1;
    if (steps == 0)
        return;
    for (const OwnSetting &own : kOwnSettings) {
        const int index = state.db().indexOf(own.address);
        if (index < 0)
            continue;
        const SimParameter &p = state.db().parameters()[std::size_t(index)];
        for (int set = 0; set < kSets; ++set) {
            const qint64 value = qint64(p.initial[std::size_t(set)]) + qint64(own.step) * steps;
            state.store(index, quint8(1u << set),
                        qint32(std::clamp<qint64>(value, p.minimum, p.maximum)));
        }
    }
}

} // namespace DriveDesk::Sim
