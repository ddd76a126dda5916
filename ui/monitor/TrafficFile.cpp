#include "TrafficFile.h"

#include "parameters/ParameterCsv.h"

#include <QDir>
#include <QSaveFile>

namespace DriveDesk {

namespace {

QString headerOf(TrafficFile::Format format)
{
    QStringList names;
    for (int field = 0; field < TrafficFormat::FieldCount; ++field)
        names << TrafficFormat::fieldName(TrafficFormat::Field(field));
    return format == TrafficFile::Format::Csv ? csvRecord(names)
                                              : TrafficFormat::tabSeparated(names);
}

} // namespace

TrafficFile::Format TrafficFile::formatFor(const QString &path)
{
    return path.endsWith(QStringLiteral(".csv"), Qt::CaseInsensitive) ? Format::Csv : Format::Text;
}

bool TrafficFile::save(const QString &path, const QList<TrafficEntry> &entries, QString *error)
{
    const auto fail = [&](const QString &reason) {
        if (error)
            *error = tr("Cannot save the telegrams to %1: %2")
                         .arg(QDir::toNativeSeparators(path), reason);
        return false;
    };
    if (path.isEmpty())
        return fail(tr("no file name given"));

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return fail(file.errorString());

    const Format format = formatFor(path);
    QString text = headerOf(format) + QLatin1Char('\n');
    for (const TrafficEntry &entry : entries) {
        const QStringList fields = TrafficFormat::fields(entry, TrafficFormat::Clock::DateAndTime);
        text += (format == Format::Csv ? csvRecord(fields)
                                       : TrafficFormat::tabSeparated(fields));
        text += QLatin1Char('\n');
        // Write as we go so that a long monitor does not need the whole file in memory twice.
        if (text.size() > 64 * 1024) {
            if (file.write(text.toUtf8()) < 0)
                return fail(file.errorString());
            text.clear();
        }
    }
    if (file.write(text.toUtf8()) < 0)
        return fail(file.errorString());
    if (!file.commit())
        return fail(file.errorString());
    return true;
}

} // namespace DriveDesk
