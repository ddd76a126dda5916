#include "ParameterTable.h"

#include "parameters/DisplayScaling.h"
#include "parameters/DriveIdentity.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterId.h"
#include "parameters/Plaintexts.h"

#include <QCoreApplication>
#include <QStringList>

namespace DriveDesk::ParameterTable {

namespace {

// The translation context of the reports: ParameterTable is a namespace.
class TableText
{
    Q_DECLARE_TR_FUNCTIONS(ParameterTable)
};

// The last line of both reports: two counts side by side, each translated with its plural.
QString counts(qsizetype groups, int parameters)
{
    const int groupCount = int(groups);
    return TableText::tr("%n group(s)", nullptr, groupCount) + QStringLiteral(", ")
        + TableText::tr("%n parameter(s)", nullptr, parameters) + QLatin1Char('\n');
}

// Columns padded to their widest cell; the last column is not padded.
QString align(const QList<QStringList> &rows)
{
    QList<qsizetype> widths;
    for (const QStringList &row : rows) {
        for (qsizetype c = 0; c < row.size(); ++c) {
            if (widths.size() <= c)
                widths << 0;
            widths[c] = std::max(widths[c], row[c].size());
        }
    }
    QString text;
    for (const QStringList &row : rows) {
        QString line;
        for (qsizetype c = 0; c < row.size(); ++c)
            line += c + 1 < row.size() ? row[c].leftJustified(widths[c] + 2) : row[c];
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
        text += line + QLatin1Char('\n');
    }
    return text;
}

QString valuesText(const ParameterDescription &parameter)
{
    if (!parameter.isSetProgrammable()) {
        return parameter.values[0] ? valueText(parameter, *parameter.values[0], false)
                                   : QStringLiteral("?");
    }
    QStringList perSet;
    for (const auto &value : parameter.values)
        perSet << (value ? valueText(parameter, *value, false) : QStringLiteral("?"));
    QStringList unique = perSet;
    unique.removeDuplicates();
    if (unique.size() == 1)
        return TableText::tr("%1 (sets 0-7)").arg(unique.constFirst());
    QStringList labelled;
    for (qsizetype s = 0; s < perSet.size(); ++s)
        labelled << QStringLiteral("%1:%2").arg(s).arg(perSet[s]);
    return labelled.join(QLatin1Char(' '));
}

} // namespace

QString valueText(const ParameterDescription &parameter, qint32 raw, bool withUnit)
{
    return ParameterFormat(parameter).text(raw, withUnit);
}

QString scan(const DriveDescription &drive, bool withValues)
{
    QString text;
    for (const GroupDescription &group : drive.groups) {
        text += QStringLiteral("%1  %2\n").arg(group.id, group.name);
        QList<QStringList> rows;
        QStringList header{QStringLiteral("  ") + TableText::tr("parameter"), TableText::tr("name")};
        if (withValues)
            header << TableText::tr("value");
        header << TableText::tr("min") << TableText::tr("max") << TableText::tr("default")
               << TableText::tr("unit");
        rows << header;
        for (const ParameterDescription &p : group.parameters) {
            const DisplayScaling scaling(p.scaling);
            QStringList row{QStringLiteral("  ") + parameterId(group, p), p.name};
            if (withValues)
                row << valuesText(p);
            row << scaling.format(p.minimum, false) << scaling.format(p.maximum, false)
                << valueText(p, p.defaultValue, false) << scaling.unitSymbol();
            if (!p.error.isEmpty())
                row << QStringLiteral("(%1)").arg(p.error);
            rows << row;
        }
        text += align(rows) + QLatin1Char('\n');
    }
    return text + counts(drive.groups.size(), drive.parameterCount());
}

QString info(const DriveDescription &drive, const DriveDescription &system)
{
    QString text = TableText::tr("connection: %1 (%2)").arg(drive.connection, drive.protocol)
        + QLatin1Char('\n');
    // What the drive is, from its identification parameters (and service 13 where the
    // protocol carries it): the same lines as the window's drive information.
    QList<QStringList> identity;
    for (const DriveIdentity::Line &line : DriveIdentity::lines(system))
        identity << QStringList{line.label + QLatin1Char(':'), line.value};
    text += align(identity);
    text += QLatin1Char('\n');
    QList<QStringList> rows;
    rows << QStringList{TableText::tr("group"), TableText::tr("address"),
                        TableText::tr("parameters"), TableText::tr("name")};
    int total = 0;
    for (const GroupDescription &g : drive.groups) {
        rows << QStringList{g.id, ParameterId::hexAddress(g.address),
                            QString::number(g.parameterCount), g.name};
        total += g.parameterCount;
    }
    text += align(rows);
    return text + counts(drive.groups.size(), total);
}

QString differences(const ParameterComparison &comparison, const QString &a, const QString &b)
{
    QList<QStringList> rows;
    rows << QStringList{ TableText::tr("parameter"), TableText::tr("name"), TableText::tr("set"),
                         a, b };
    for (const ParameterDifference &d : comparison.differences) {
        const QString set = d.set >= 0 ? QString::number(d.set)
                                       : ParameterComparison::kindText(d.kind);
        rows << QStringList{ d.id, d.name, set, d.a.isEmpty() ? QStringLiteral("-") : d.a,
                             d.b.isEmpty() ? QStringLiteral("-") : d.b };
    }
    const int count = int(comparison.differences.size());
    QString text = count ? align(rows) : QString();
    text += TableText::tr("%n difference(s)", nullptr, count) + QStringLiteral(", ")
        + TableText::tr("%n parameter(s) on both sides", nullptr, comparison.compared)
        + QLatin1Char('\n');
    return text;
}

} // namespace DriveDesk::ParameterTable
