#include "CliFormatOption.h"

#include <QCommandLineParser>

namespace DriveDesk {

bool parseFormatOption(const QCommandLineParser &parser, const QString &command,
                       const QStringList &allowed, CliRequest *request, QString *error)
{
    if (!parser.isSet(QStringLiteral("format")))
        return true;
    const QString format = parser.value(QStringLiteral("format")).toLower();
    if (!allowed.contains(format)) {
        QStringList words = allowed;
        const QString last = words.takeLast();
        *error = QStringLiteral("unknown format '%1': %2 writes %3")
                     .arg(format, command, words.isEmpty() ? last
                                                  : words.join(QStringLiteral(", "))
                                                        + QStringLiteral(" or ") + last);
        return false;
    }
    request->format = format == QLatin1String("json") ? CliRequest::Format::Json
        : format == QLatin1String("csv")              ? CliRequest::Format::Csv
                                                      : CliRequest::Format::Table;
    return true;
}

} // namespace DriveDesk
