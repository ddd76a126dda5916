#include "MetadataMatch.h"

#include "ParameterFormat.h"
#include "ParameterList.h"
#include "ParameterProperties.h"

namespace DriveDesk {

namespace {

using Presence = MetadataDifference::Presence;

const GroupDescription *groupAt(const DriveDescription &drive, quint16 address)
{
    for (const GroupDescription &group : drive.groups) {
        if (group.address == address)
            return &group;
    }
    return nullptr;
}

// A parameter a side has in its parameter list: a drive's scan also holds those a list leaves
// out, which a file never does.
const ParameterDescription *listed(const GroupDescription *group, quint16 address)
{
    if (!group)
        return nullptr;
    for (const ParameterDescription &parameter : group->parameters) {
        if (parameter.address == address)
            return ParameterList::holds(parameter) ? &parameter : nullptr;
    }
    return nullptr;
}

QString hex(quint32 value)
{
    return QString::number(value, 16).toUpper().rightJustified(8, QLatin1Char('0'))
        + QLatin1Char('h');
}

QString quoted(const QString &text)
{
    return QLatin1Char('"') + text + QLatin1Char('"');
}

QString scalingText(const DisplayScalingData &scaling)
{
    return MetadataMatch::tr("divisor %1, multiplier %2, offset %3, flags %4h")
        .arg(scaling.divisor)
        .arg(scaling.multiplier)
        .arg(scaling.offset)
        .arg(QString::number(scaling.flags, 16).toUpper().rightJustified(4, QLatin1Char('0')));
}

bool sameScaling(const DisplayScalingData &a, const DisplayScalingData &b)
{
    // The address in a service 5 answer is the request's, not part of the scaling.
    return a.divisor == b.divisor && a.multiplier == b.multiplier && a.offset == b.offset
        && a.flags == b.flags;
}

std::optional<MetadataDifference> fieldDifference(const GroupDescription &group,
                                                  const ParameterDescription &a,
                                                  const ParameterDescription &b)
{
    const auto differs = [&](const QString &field, const QString &inA, const QString &inB) {
        return MetadataDifference{false, parameterId(group, a), a.name, Presence::Both,
                                  field, inA, inB};
    };
    if (a.name != b.name)
        return differs(MetadataMatch::tr("name"), quoted(a.name), quoted(b.name));
    if (a.properties1 != b.properties1)
        return differs(MetadataMatch::tr("properties 1"), hex(a.properties1), hex(b.properties1));
    if (a.properties2 != b.properties2)
        return differs(MetadataMatch::tr("properties 2"), hex(a.properties2), hex(b.properties2));
    const ParameterProperties properties(a.properties1, a.properties2);
    if (!properties.hasVariableScaling() && !sameScaling(a.scaling, b.scaling)) {
        return differs(MetadataMatch::tr("display scaling"), scalingText(a.scaling),
                       scalingText(b.scaling));
    }
    // With the scaling the same, each side's format shows its limit as the drive would.
    const ParameterFormat formatA(a);
    const ParameterFormat formatB(b);
    using LimitType = ParameterProperties::LimitType;
    if (properties.lowerLimitType() == LimitType::Constant && a.minimum != b.minimum) {
        return differs(MetadataMatch::tr("lower limit"), formatA.number(a.minimum, true),
                       formatB.number(b.minimum, true));
    }
    if (properties.upperLimitType() == LimitType::Constant && a.maximum != b.maximum) {
        return differs(MetadataMatch::tr("upper limit"), formatA.number(a.maximum, true),
                       formatB.number(b.maximum, true));
    }
    return std::nullopt;
}

} // namespace

// A field that differs says more than a parameter one side lacks (which a download lists on
// its own), so the fields of what both have are looked at first, in A's order.
std::optional<MetadataDifference> MetadataMatch::firstDifference(const DriveDescription &a,
                                                                 const DriveDescription &b,
                                                                 Scope scope)
{
    std::optional<MetadataDifference> missing;
    const auto noteMissing = [&missing](MetadataDifference difference) {
        if (!missing)
            missing = std::move(difference);
    };
    for (const GroupDescription &groupA : a.groups) {
        const GroupDescription *groupB = groupAt(b, groupA.address);
        if (!groupB) {
            noteMissing({true, groupA.id, groupA.name, Presence::OnlyInA, {}, {}, {}});
            continue;
        }
        if (groupA.id != groupB->id)
            return MetadataDifference{true, groupA.id, groupA.name, Presence::Both, tr("id"),
                                      groupA.id, groupB->id};
        if (groupA.name != groupB->name)
            return MetadataDifference{true, groupA.id, groupA.name, Presence::Both, tr("name"),
                                      quoted(groupA.name), quoted(groupB->name)};
        for (const ParameterDescription &parameterA : groupA.parameters) {
            if (!ParameterList::holds(parameterA))
                continue;
            const ParameterDescription *parameterB = listed(groupB, parameterA.address);
            if (!parameterB) {
                noteMissing({false, parameterId(groupA, parameterA), parameterA.name,
                             Presence::OnlyInA, {}, {}, {}});
                continue;
            }
            if (auto difference = fieldDifference(groupA, parameterA, *parameterB))
                return difference;
        }
        if (scope == Scope::AHoldsPart)
            continue;
        for (const ParameterDescription &parameterB : groupB->parameters) {
            if (ParameterList::holds(parameterB) && !listed(&groupA, parameterB.address)) {
                noteMissing({false, parameterId(*groupB, parameterB), parameterB.name,
                             Presence::OnlyInB, {}, {}, {}});
            }
        }
    }
    if (scope == Scope::Whole) {
        for (const GroupDescription &groupB : b.groups) {
            if (!groupAt(a, groupB.address))
                noteMissing({true, groupB.id, groupB.name, Presence::OnlyInB, {}, {}, {}});
        }
    }
    return missing;
}

// The texts keep the context of the download, which showed them first.
QString MetadataMatch::text(const MetadataDifference &difference)
{
    using Presence = MetadataDifference::Presence;
    const QString what = difference.isGroup
        ? QCoreApplication::translate("DownloadPlan", "group %1 %2")
              .arg(difference.id, difference.name)
        : QCoreApplication::translate("DownloadPlan", "%1 %2").arg(difference.id, difference.name);
    switch (difference.presence) {
    case Presence::OnlyInA:
        return QCoreApplication::translate("DownloadPlan", "%1 is in the file, not on the drive")
            .arg(what);
    case Presence::OnlyInB:
        return QCoreApplication::translate("DownloadPlan", "%1 is on the drive, not in the file")
            .arg(what);
    case Presence::Both:
        break;
    }
    return QCoreApplication::translate("DownloadPlan", "%1: %2 is %3 in the file, %4 on the drive")
        .arg(what, difference.field, difference.a, difference.b);
}

} // namespace DriveDesk
