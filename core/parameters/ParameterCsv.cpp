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

// The texts' context, as lupdate finds it.
class ParameterCsv
{
    Q_DECLARE_TR_FUNCTIONS(ParameterCsv)
};

} // namespace

CsvStyle CsvStyle::forSpreadsheet()
{
    CsvStyle style;
    if (QLocale().decimalPoint() == QLatin1String(","))
        style.separator = QLatin1Char(';');
    style.translatedHeader = true;
    style.byteOrderMark = true;
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
        heading << ParameterCsv::tr("id") << ParameterCsv::tr("name") << ParameterCsv::tr("unit");
        for (int set = 0; set < kParameterSets; ++set)
            heading << ParameterCsv::tr("set %1").arg(set);
    } else {
        heading << QStringLiteral("id") << QStringLiteral("name") << QStringLiteral("unit");
        for (int set = 0; set < kParameterSets; ++set)
            heading << QStringLiteral("set %1").arg(set);
    }
    QByteArray csv = style.byteOrderMark ? QByteArray("\xEF\xBB\xBF") : QByteArray();
    csv += line(heading, style.separator);
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
