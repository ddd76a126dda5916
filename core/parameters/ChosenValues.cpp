#include "ChosenValues.h"

#include "DriveIdentity.h"
#include "ParameterFormat.h"
#include "ParameterId.h"
#include "ParameterList.h"

#include <QSet>

namespace DriveDesk {

namespace {

// The cell a set's value lives in: set 0 for a parameter with one value.
std::size_t cellOf(const ParameterDescription &parameter, int set)
{
    return std::size_t(parameter.isSetProgrammable() ? set : 0);
}

} // namespace

QList<ChosenValue> ChosenValues::from(const QList<ComparisonRow> &chosen, bool toA)
{
    QList<ChosenValue> values;
    for (const ComparisonRow &row : chosen) {
        if (!row.isWritableTo(toA))
            continue;
        values.append({ row.address, toA ? row.setA : row.setB, toA ? *row.rawB : *row.rawA });
    }
    return values;
}

int ChosenValues::apply(DriveDescription &target, const QList<ChosenValue> &values,
                        QStringList *refusals)
{
    int applied = 0;
    for (const ChosenValue &value : values) {
        ParameterDescription *parameter = target.find(value.address);
        QString refusal;
        const QString id = ParameterId::format(value.address, target);
        if (!parameter) {
            refusal = tr("%1: the target has no such parameter").arg(id);
        } else if (!ParameterList::isWrittenByDownload(*parameter)) {
            refusal = tr("%1: %2").arg(id, ParameterList::whyNotWritten(*parameter));
        } else if (const QString problem = ParameterFormat(*parameter).limitsProblem(value.raw);
                   !problem.isEmpty()) {
            refusal = tr("%1: %2").arg(id, problem);
        }
        if (!refusal.isEmpty()) {
            if (refusals)
                refusals->append(refusal);
            continue;
        }
        parameter->values[cellOf(*parameter, value.set)] = value.raw;
        ++applied;
    }
    return applied;
}

DriveDescription ChosenValues::selectionFor(const DriveDescription &source,
                                            const QList<ChosenValue> &values)
{
    QSet<quint16> identification;
    for (const IdentificationParameter &id : DriveIdentity::parameters()) {
        if (const GroupDescription *group = source.findGroup(QString::fromLatin1(id.group)))
            identification.insert(quint16(group->address | id.number));
    }
    DriveDescription selection = source;
    for (GroupDescription &group : selection.groups) {
        for (ParameterDescription &parameter : group.parameters) {
            if (!identification.contains(parameter.address))
                parameter.values = {};
        }
    }
    for (const ChosenValue &value : values) {
        if (ParameterDescription *parameter = selection.find(value.address))
            parameter->values[cellOf(*parameter, value.set)] = value.raw;
    }
    return selection;
}

} // namespace DriveDesk
