#pragma once

#include "parameters/DriveDescription.h"
#include "scope/ScopeChannel.h"
#include "scope/ScopePreset.h"

#include <QList>

#include <array>
#include <optional>

namespace DriveDesk {

// Which parameter the drive delivers on each scope channel. On an F5 the read channels are
// assigned by Sy.16/18/20/22 (the source's bus address, -1 = off) and Sy.17/19/21/23 (the set
// mask): the scan finds them as parameters 0010h..0017h of group Sy. A drive without them has
// its channels assigned some other way, and DriveDesk records them raw.
struct ScopeAssignmentParameters
{
    std::array<quint16, 4> source{};  // Sy.16, Sy.18, Sy.20, Sy.22
    std::array<quint16, 4> setMask{}; // Sy.17, Sy.19, Sy.21, Sy.23
    // The eight, in the order they are read back: source, set mask, channel by channel.
    QList<quint16> all() const;
};

// The channel-assignment parameters, where the scan found all eight; nothing otherwise.
std::optional<ScopeAssignmentParameters> scopeAssignmentParameters(const DriveDescription &drive);

// What a channel is assigned to, as the drive holds it.
struct ChannelAssignment
{
    static constexpr qint32 kOff = -1;
    qint32 source = kOff; // a bus address, or kOff
    quint8 setMask = 1;
    bool operator==(const ChannelAssignment &) const = default;
};
using ScopeAssignment = std::array<std::optional<ChannelAssignment>, 4>; // empty: not known

// The parameters a user may put on a channel: those properties 1 bit 28 permits as process
// data, in the drive's order.
QList<const ParameterDescription *> scopeSources(const DriveDescription &drive);

// Whether the parameter's values fit channels 3 and 4, which carry 16 bits: beyond its limits
// a value arrives cut to its low 16 bits.
bool fitsNarrowChannel(const ParameterDescription &parameter);

// The channels as a recording shows them: the source's id, name and display scaling where the
// assignment names a parameter the scan found, the bare address where it names another, raw
// ("Channel 2") where the assignment is not known.
ScopeChannels scopeChannels(const DriveDescription &drive, const ScopeAssignment &assignment);

// A source as a user writes it ("ru.03", "op.11@2", "off") on this drive: the bus address and
// set mask to assign; nothing, and why, where the drive has no such group or number. Whether
// the drive permits it as process data is planScopeChannels()'s to say.
std::optional<ChannelAssignment> scopeSourceOn(const ScopeSourceText &source,
                                               const DriveDescription &drive,
                                               QString *error = nullptr);
// The other way: how a user writes an assignment ("op.11@2"; the lowest set of a mask).
ScopeSourceText scopeSourceText(const ChannelAssignment &assignment, const DriveDescription &drive);

} // namespace DriveDesk
