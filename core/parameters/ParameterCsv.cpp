#include "ParameterCsv.h"

#include "ParameterFormat.h"
#include "SavedFile.h"

#include <QStringList>

namespace DriveDesk {

namespace {

QByteArray line(const QStringList &fields)
{
    return csvRecord(fields).toUtf8() + "\r\n";
}

} // namespace

QString csvRecord(const QStringList &fields)
{
    QStringList quoted;
    quoted.reserve(fields.size());
    for (QString field : fields) {
        if (field.contains(QLatin1Char(',')) || field.contains(QLatin1Char('"'))
            || field.contains(QLatin1Char('\n')) || field.contains(QLatin1Char('\r'))) {
            field.replace(QLatin1Char('"'), QLatin1String("\"\""));
            field = QLatin1Char('"') + field + QLatin1Char('"');
        }
        quoted << field;
    }
    return quoted.join(QLatin1Char(','));
}

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

bool saveParametersAsCsv(const QString &path, const DriveDescription &drive, QString *error)
{
    return SavedFile::write(path, parametersAsCsv(drive), error);
}

} // namespace DriveDesk
