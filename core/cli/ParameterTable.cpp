#include "ParameterTable.h"


#include "parameters/DisplayScaling.h"
#include "parameters/DriveIdentity.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterId.h"
#include "parameters/Plaintexts.h"

#include <QStringList>

namespace DriveDesk::ParameterTable {

namespace {

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
        return unique.constFirst() + QStringLiteral(" (sets 0-7)");
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

QString scan(const DriveDescription &drive, bool withValues, Language language)
{
    const bool german = language == Language::German;
    QString text;
    for (const GroupDescription &group : drive.groups) {
        text += QStringLiteral("%1  %2\n").arg(group.id, group.name);
        QList<QStringList> rows;
        QStringList header{german ? QStringLiteral("  Parameter") : QStringLiteral("  parameter"),
                           german ? QStringLiteral("Name") : QStringLiteral("name")};
        if (withValues)
            header << (german ? QStringLiteral("Wert") : QStringLiteral("value"));
        header << QStringLiteral("min") << QStringLiteral("max")
               << (german ? QStringLiteral("Vorgabe") : QStringLiteral("default"))
               << (german ? QStringLiteral("Einheit") : QStringLiteral("unit"));
        rows << header;
        for (const ParameterDescription &p : group.parameters) {
            const DisplayScaling scaling(p.scaling);
            QStringList row{QStringLiteral("  ") + parameterId(group.id, p.number()), p.name};
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
    text += german ? QStringLiteral("%1 Gruppen, %2 Parameter\n").arg(drive.groups.size()).arg(drive.parameterCount())
                   : QStringLiteral("%1 groups, %2 parameters\n").arg(drive.groups.size()).arg(drive.parameterCount());
    return text;
}

QString info(const DriveDescription &drive, const DriveDescription &system, Language language)
{
    const bool german = language == Language::German;
    QString text;
    text += QStringLiteral("%1: %2 (%3)\n")
                .arg(german ? QStringLiteral("Verbindung") : QStringLiteral("connection"),
                     drive.connection, drive.protocol);
    // What the drive is, from its identification parameters (and service 13 where the
    // protocol carries it): the same lines as the window's drive information.
    QList<QStringList> identity;
    for (const DriveIdentity::Line &line : DriveIdentity::lines(system))
        identity << QStringList{line.label + QLatin1Char(':'), line.value};
    text += align(identity);
    text += QLatin1Char('\n');
    QList<QStringList> rows;
    rows << QStringList{german ? QStringLiteral("Gruppe") : QStringLiteral("group"),
                        german ? QStringLiteral("Adresse") : QStringLiteral("address"),
                        german ? QStringLiteral("Parameter") : QStringLiteral("parameters"),
                        german ? QStringLiteral("Name") : QStringLiteral("name")};
    int total = 0;
    for (const GroupDescription &g : drive.groups) {
        rows << QStringList{g.id, ParameterId::hexAddress(g.address),
                            QString::number(g.parameterCount), g.name};
        total += g.parameterCount;
    }
    text += align(rows);
    text += german ? QStringLiteral("%1 Gruppen, %2 Parameter\n").arg(drive.groups.size()).arg(total)
                   : QStringLiteral("%1 groups, %2 parameters\n").arg(drive.groups.size()).arg(total);
    return text;
}

} // namespace DriveDesk::ParameterTable
