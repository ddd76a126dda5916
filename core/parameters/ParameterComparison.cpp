#include "ParameterComparison.h"

#include "ParameterAccess.h"
#include "ParameterFormat.h"
#include "ParameterList.h"

#include <QMap>

#include <algorithm>

namespace DriveDesk {

namespace {

struct Located
{
    const ParameterDescription *parameter = nullptr;
    QString id;
    QString groupId;
};

QMap<quint16, Located> byAddress(const DriveDescription &drive)
{
    QMap<quint16, Located> parameters;
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters)
            parameters.insert(parameter.address,
                              { &parameter, parameterId(group, parameter), group.id });
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

bool countsAsSetting(const ParameterDescription &parameter)
{
    return ParameterList::isReadByUpload(parameter) && isUserSetting(parameter);
}

QString ParameterComparison::kindText(ParameterDifference::Kind kind)
{
    switch (kind) {
    case ParameterDifference::Kind::Different:
        return ComparisonTable::stateText(ComparisonRow::State::Different);
    case ParameterDifference::Kind::OnlyInA:
        return ComparisonTable::stateText(ComparisonRow::State::OnlyInA);
    case ParameterDifference::Kind::OnlyInB:
        return ComparisonTable::stateText(ComparisonRow::State::OnlyInB);
    }
    return {};
}

// The view's rows, reduced to what differs: a parameter only one side has once, as that side
// holds its first value; a value that differs once per set.
ParameterComparison compareDescriptions(const DriveDescription &a, const DriveDescription &b)
{
    ParameterComparison comparison;
    std::optional<quint16> previous;
    for (const ComparisonRow &row : compareAll(a, b).rows) {
        const bool firstOfParameter = previous != row.address;
        previous = row.address;
        if (row.state == ComparisonRow::State::NotASetting)
            continue;
        const bool only = row.state == ComparisonRow::State::OnlyInA
            || row.state == ComparisonRow::State::OnlyInB;
        if (!only && firstOfParameter)
            ++comparison.compared;
        if (!row.differs || (only && !firstOfParameter))
            continue;
        ParameterDifference difference;
        difference.kind = row.state == ComparisonRow::State::OnlyInA
            ? ParameterDifference::Kind::OnlyInA
            : row.state == ComparisonRow::State::OnlyInB ? ParameterDifference::Kind::OnlyInB
                                                         : ParameterDifference::Kind::Different;
        difference.address = row.address;
        difference.id = row.id;
        difference.name = row.name;
        difference.set = only ? -1 : row.setA;
        difference.a = row.a;
        difference.b = row.b;
        comparison.differences.append(difference);
    }
    return comparison;
}

DriveDescription userSettingsOf(const DriveDescription &drive)
{
    DriveDescription settings = drive;
    for (GroupDescription &group : settings.groups) {
        group.parameters.removeIf(
            [](const ParameterDescription &parameter) { return !countsAsSetting(parameter); });
    }
    return settings;
}

DriveDescription defaultsOf(const DriveDescription &drive)
{
    DriveDescription defaults = userSettingsOf(drive);
    for (GroupDescription &group : defaults.groups) {
        for (ParameterDescription &parameter : group.parameters)
            parameter.values = parameter.defaultValues();
    }
    return defaults;
}

ParameterComparison compareWithDefaults(const DriveDescription &drive, bool defaultsFirst)
{
    const DriveDescription settings = userSettingsOf(drive);
    const DriveDescription defaults = defaultsOf(drive);
    return defaultsFirst ? compareDescriptions(defaults, settings)
                         : compareDescriptions(settings, defaults);
}

int ComparisonTable::count(ComparisonRow::State state) const
{
    return int(std::count_if(rows.cbegin(), rows.cend(),
                             [state](const ComparisonRow &row) { return row.state == state; }));
}

QString ComparisonTable::stateText(ComparisonRow::State state)
{
    switch (state) {
    case ComparisonRow::State::Equal:
        return tr("equal");
    case ComparisonRow::State::Different:
        return tr("different");
    case ComparisonRow::State::OnlyInA:
        return tr("only in A");
    case ComparisonRow::State::OnlyInB:
        return tr("only in B");
    case ComparisonRow::State::ReadOnly:
        return tr("read-only");
    case ComparisonRow::State::NotASetting:
        return tr("not a setting");
    }
    return {};
}

namespace {

// Both sides' parameters by address; `setA`/`setB` -1 for set by set.
ComparisonTable compareRows(const DriveDescription &a, int setA, const DriveDescription &b,
                            int setB)
{
    const bool setAgainstSet = setA >= 0;
    ComparisonTable table;
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
        const Located &named = l.parameter ? l : r;
        const bool perSet = (l.parameter && l.parameter->isSetProgrammable())
            || (r.parameter && r.parameter->isSetProgrammable());
        if (setAgainstSet && !perSet)
            continue;
        ComparisonRow row;
        row.address = address;
        row.id = named.id;
        row.name = named.parameter->name;
        row.groupId = named.groupId;
        row.perSet = perSet;
        row.onlyInA = !r.parameter;
        row.onlyInB = !l.parameter;
        if ((l.parameter && !countsAsSetting(*l.parameter))
            || (r.parameter && !countsAsSetting(*r.parameter))) {
            row.state = ComparisonRow::State::NotASetting;
            row.differs = row.onlyInA || row.onlyInB;
        } else if (!l.parameter || !r.parameter) {
            row.state = l.parameter ? ComparisonRow::State::OnlyInA
                                    : ComparisonRow::State::OnlyInB;
            row.differs = true;
        } else if (!ParameterList::isWrittenByDownload(*l.parameter)
                   || !ParameterList::isWrittenByDownload(*r.parameter)) {
            row.state = ComparisonRow::State::ReadOnly;
        }
        const int rows = setAgainstSet ? 1 : (perSet ? kParameterSets : 1);
        for (int set = 0; set < rows; ++set) {
            ComparisonRow shownRow = row;
            shownRow.setA = setAgainstSet ? setA : set;
            shownRow.setB = setAgainstSet ? setB : set;
            if (l.parameter) {
                shownRow.rawA = valueOf(*l.parameter, shownRow.setA);
                shownRow.a = shown(*l.parameter, shownRow.rawA);
            }
            if (r.parameter) {
                shownRow.rawB = valueOf(*r.parameter, shownRow.setB);
                shownRow.b = shown(*r.parameter, shownRow.rawB);
            }
            if (l.parameter && r.parameter) {
                shownRow.differs = shownRow.rawA != shownRow.rawB;
                if (row.state != ComparisonRow::State::ReadOnly
                    && row.state != ComparisonRow::State::NotASetting) {
                    shownRow.state = shownRow.differs ? ComparisonRow::State::Different
                                                      : ComparisonRow::State::Equal;
                }
            }
            table.rows.append(shownRow);
        }
    }
    return table;
}

} // namespace

ComparisonTable compareAll(const DriveDescription &a, const DriveDescription &b)
{
    return compareRows(a, -1, b, -1);
}

ComparisonTable compareSets(const DriveDescription &a, int setA, const DriveDescription &b,
                            int setB)
{
    Q_ASSERT(setA >= 0 && setA < kParameterSets && setB >= 0 && setB < kParameterSets);
    return compareRows(a, setA, b, setB);
}

} // namespace DriveDesk
