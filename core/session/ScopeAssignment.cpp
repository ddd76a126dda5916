#include "ScopeAssignment.h"

#include "parameters/ParameterId.h"
#include "parameters/ParameterProperties.h"
#include "scope/ScopeSample.h"

#include <algorithm>
#include <limits>

namespace DriveDesk {

namespace {

// keb_f5_notes: read channel i is assigned at 0010h + 2i (address) and 0011h + 2i (set mask).
constexpr quint16 kFirstAssignment = 0x0010;
const QString kAssignmentGroup = QStringLiteral("Sy");

bool inAssignmentGroup(const GroupDescription &group, quint16 address)
{
    return std::any_of(group.parameters.begin(), group.parameters.end(),
                       [address](const ParameterDescription &p) { return p.address == address; });
}

} // namespace

QList<quint16> ScopeAssignmentParameters::all() const
{
    QList<quint16> addresses;
    for (std::size_t channel = 0; channel < source.size(); ++channel)
        addresses << source[channel] << setMask[channel];
    return addresses;
}

std::optional<ScopeAssignmentParameters> scopeAssignmentParameters(const DriveDescription &drive)
{
    ScopeAssignmentParameters parameters;
    for (std::size_t channel = 0; channel < parameters.source.size(); ++channel) {
        parameters.source[channel] = quint16(kFirstAssignment + 2 * channel);
        parameters.setMask[channel] = quint16(kFirstAssignment + 2 * channel + 1);
    }
    const GroupDescription *group = drive.findGroup(kAssignmentGroup);
    if (!group)
        return std::nullopt;
    for (const quint16 address : parameters.all()) {
        if (!inAssignmentGroup(*group, address))
            return std::nullopt;
    }
    return parameters;
}

QList<const ParameterDescription *> scopeSources(const DriveDescription &drive)
{
    QList<const ParameterDescription *> sources;
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (ParameterProperties(parameter.properties1, parameter.properties2)
                    .isProcessDataPermitted()) {
                sources << &parameter;
            }
        }
    }
    return sources;
}

bool fitsNarrowChannel(const ParameterDescription &parameter)
{
    return parameter.minimum >= std::numeric_limits<qint16>::min()
           && parameter.maximum <= std::numeric_limits<qint16>::max();
}

ScopeChannels scopeChannels(const DriveDescription &drive, const ScopeAssignment &assignment)
{
    ScopeChannels channels(ScopeSample::kChannelCount);
    for (int index = 0; index < ScopeSample::kChannelCount; ++index) {
        const std::optional<ChannelAssignment> &assigned = assignment[std::size_t(index)];
        ScopeChannel &channel = channels[index];
        if (!assigned)
            continue; // raw, as the drive has it
        channel.setMask = assigned->setMask;
        if (assigned->source < 0 || assigned->source > 0xFFFF) {
            channel.enabled = false;
            continue;
        }
        const auto address = quint16(assigned->source);
        channel.source = address;
        channel.id = ParameterId::format(address, drive);
        if (const ParameterDescription *parameter = drive.find(address)) {
            channel.name = parameter->name;
            channel.scaling = DisplayScaling(parameter->scaling);
        }
    }
    return channels;
}

std::optional<ChannelAssignment> scopeSourceOn(const ScopeSourceText &source,
                                               const DriveDescription &drive, QString *error)
{
    if (source.isOff())
        return ChannelAssignment{ChannelAssignment::kOff, 0x01};
    const std::optional<quint16> address = ParameterId::parse(source.id, drive, error);
    if (!address)
        return std::nullopt;
    return ChannelAssignment{*address, quint8(1u << source.set)};
}

ScopeSourceText scopeSourceText(const ChannelAssignment &assignment, const DriveDescription &drive)
{
    if (assignment.source == ChannelAssignment::kOff || assignment.source < 0)
        return {};
    int set = 0;
    while (set < kParameterSets - 1 && !(assignment.setMask & (1u << set)))
        ++set;
    return {ParameterId::format(quint16(assignment.source), drive), set};
}

} // namespace DriveDesk
