#include "ParameterCsv.h"

#include "ParameterFormat.h"

#include <QStringList>

namespace DriveDesk {

namespace {

QString field(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"'))
        && !text.contains(QLatin1Char('\n')) && !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QByteArray line(const QStringList &fields)
{
    QStringList quoted;
    for (const QString &text : fields)
        quoted << field(text);
    return quoted.join(QLatin1Char(',')).toUtf8() + "\r\n";
}

} // namespace

QByteArray parametersAsCsv(const DriveDescription &drive)
{
    QStringList heading { QStringLiteral("id"), QStringLiteral("name"), QStringLiteral("unit") };
    for (int set = 0; set < kParameterSets; ++set)
        heading << QStringLiteral("set %1").arg(set);
    QByteArray csv = line(heading);
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            const ParameterFormat format(parameter);
            QStringList row { parameterId(group.id, parameter.number()), parameter.name,
                              format.scaling().unitSymbol() };
            const int sets = parameter.isSetProgrammable() ? kParameterSets : 1;
            for (int set = 0; set < kParameterSets; ++set) {
                const std::optional<qint32> &value = parameter.values[std::size_t(set)];
                row << (set >= sets ? QString()
                        : value     ? format.text(*value, false)
                                    : QStringLiteral("?"));
            }
            csv += line(row);
        }
    }
    return csv;
}

} // namespace DriveDesk
