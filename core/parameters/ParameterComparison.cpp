#include "ParameterComparison.h"

#include "ParameterAccess.h"
#include "ParameterFormat.h"

#include <QMap>

namespace DriveDesk {

namespace {

struct Located
{
    const ParameterDescription *parameter = nullptr;
    QString id;
};

QMap<quint16, Located> byAddress(const DriveDescription &drive)
{
    QMap<quint16, Located> parameters;
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters)
            parameters.insert(parameter.address,
                              { &parameter, parameterId(group.id, parameter.number()) });
    }
    return parameters;
}

QString shown(const ParameterDescription &parameter, const std::optional<qint32> &raw)
{
    return raw ? ParameterFormat(parameter).text(*raw) : ParameterComparison::tr("?");
}

// The value a side holds for a set: a parameter that is not set-programmable holds one value
// for every set.
std::optional<qint32> valueOf(const ParameterDescription &parameter, int set)
{
    return parameter.values[std::size_t(parameter.isSetProgrammable() ? set : 0)];
}

} // namespace

QString ParameterComparison::kindText(ParameterDifference::Kind kind)
{
    switch (kind) {
    case ParameterDifference::Kind::Different:
        return tr("different");
    case ParameterDifference::Kind::OnlyInA:
        return tr("only in A");
    case ParameterDifference::Kind::OnlyInB:
        return tr("only in B");
    }
    return {};
}

ParameterComparison compareDescriptions(const DriveDescription &a, const DriveDescription &b)
{
    ParameterComparison comparison;
    const QMap<quint16, Located> left = byAddress(a);
    const QMap<quint16, Located> right = byAddress(b);
    QList<quint16> addresses = left.keys();
    for (quint16 address : right.keys()) {
        if (!left.contains(address))
            addresses.append(address);
    }
    std::sort(addresses.begin(), addresses.end());

    for (quint16 address : std::as_const(addresses)) {
        const Located l = left.value(address);
        const Located r = right.value(address);
        if (!l.parameter || !r.parameter) {
            const Located &present = l.parameter ? l : r;
            ParameterDifference difference;
            difference.kind = l.parameter ? ParameterDifference::Kind::OnlyInA
                                          : ParameterDifference::Kind::OnlyInB;
            difference.address = address;
            difference.id = present.id;
            difference.name = present.parameter->name;
            (l.parameter ? difference.a : difference.b)
                = shown(*present.parameter, present.parameter->values[0]);
            comparison.differences.append(difference);
            continue;
        }
        ++comparison.compared;
        const bool perSet = l.parameter->isSetProgrammable() || r.parameter->isSetProgrammable();
        for (int set = 0; set < (perSet ? kParameterSets : 1); ++set) {
            const std::optional<qint32> x = valueOf(*l.parameter, set);
            const std::optional<qint32> y = valueOf(*r.parameter, set);
            if (x == y)
                continue;
            ParameterDifference difference;
            difference.address = address;
            difference.id = l.id;
            difference.name = l.parameter->name;
            difference.set = set;
            difference.a = shown(*l.parameter, x);
            difference.b = shown(*r.parameter, y);
            comparison.differences.append(difference);
        }
    }
    return comparison;
}

ParameterComparison compareWithDefaults(const DriveDescription &drive, bool defaultsFirst)
{
    DriveDescription settings = drive;
    for (GroupDescription &group : settings.groups) {
        group.parameters.removeIf(
            [](const ParameterDescription &parameter) { return !isUserSetting(parameter); });
    }
    DriveDescription defaults = settings;
    for (GroupDescription &group : defaults.groups) {
        for (ParameterDescription &parameter : group.parameters) {
            parameter.values = {};
            const int sets = parameter.isSetProgrammable() ? kParameterSets : 1;
            for (int set = 0; set < sets; ++set)
                parameter.values[std::size_t(set)] = parameter.defaultValue;
        }
    }
    return defaultsFirst ? compareDescriptions(defaults, settings)
                         : compareDescriptions(settings, defaults);
}

} // namespace DriveDesk
