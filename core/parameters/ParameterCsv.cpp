#include "ParameterCsv.h"

#include "ParameterFormat.h"
#include "SavedFile.h"

#include <QCoreApplication>
#include <QLocale>
#include <QStringList>

namespace DriveDesk {

namespace {

QByteArray line(const QStringList &fields, QChar separator)
{
    return csvRecord(fields, separator).toUtf8() + "\r\n";
}

QString tr(const char *text)
{
    return QCoreApplication::translate("ParameterCsv", text);
}

} // namespace

CsvStyle CsvStyle::forSpreadsheet()
{
    CsvStyle style;
    if (QLocale().decimalPoint() == QLatin1String(","))
        style.separator = QLatin1Char(';');
    style.translatedHeader = true;
    return style;
}

QString csvRecord(const QStringList &fields, QChar separator)
{
    QStringList quoted;
    quoted.reserve(fields.size());
    for (QString field : fields) {
        if (field.contains(separator) || field.contains(QLatin1Char('"'))
            || field.contains(QLatin1Char('\n')) || field.contains(QLatin1Char('\r'))) {
            field.replace(QLatin1Char('"'), QLatin1String("\"\""));
            field = QLatin1Char('"') + field + QLatin1Char('"');
        }
        quoted << field;
    }
    return quoted.join(separator);
}

QByteArray parametersAsCsv(const DriveDescription &drive, const CsvStyle &style)
{
    QStringList heading;
    if (style.translatedHeader) {
        heading << tr("id") << tr("name") << tr("unit");
        for (int set = 0; set < kParameterSets; ++set)
            heading << tr("set %1").arg(set);
    } else {
        heading << QStringLiteral("id") << QStringLiteral("name") << QStringLiteral("unit");
        for (int set = 0; set < kParameterSets; ++set)
            heading << QStringLiteral("set %1").arg(set);
    }
    QByteArray csv = line(heading, style.separator);
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            const ParameterFormat format(parameter);
            QStringList row { parameterId(group, parameter), parameter.name,
                              format.scaling().unitSymbol() };
            const int sets = parameter.isSetProgrammable() ? kParameterSets : 1;
            for (int set = 0; set < kParameterSets; ++set) {
                const std::optional<qint32> &value = parameter.values[std::size_t(set)];
                row << (set >= sets ? QString()
                        : value     ? format.text(*value, false)
                                    : QStringLiteral("?"));
            }
            csv += line(row, style.separator);
        }
    }
    return csv;
}

bool saveParametersAsCsv(const QString &path, const DriveDescription &drive, QString *error,
                         const CsvStyle &style)
{
    return SavedFile::write(path, parametersAsCsv(drive, style), error);
}

} // namespace DriveDesk
