#include "ScopeCsvReader.h"

#include <QCoreApplication>
#include <QFile>
#include <QStringList>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

namespace DriveDesk {

namespace {

// The context of the reader's messages.
struct ScopeCsvReader
{
    Q_DECLARE_TR_FUNCTIONS(ScopeCsvReader)
};

// The header record from `at`, RFC 4180 (a quoted field may hold commas, quotes doubled and
// line breaks); `at` moves past its line end. Nothing for an unterminated quote.
std::optional<QStringList> headerFields(const QByteArray &bytes, qsizetype &at)
{
    QStringList fields;
    QByteArray field;
    bool quoted = false;
    for (; at < bytes.size(); ++at) {
        const char c = bytes.at(at);
        if (quoted) {
            if (c == '"' && at + 1 < bytes.size() && bytes.at(at + 1) == '"') {
                field += '"';
                ++at;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields << QString::fromUtf8(field);
            field.clear();
        } else if (c == '\n') {
            ++at;
            break;
        } else if (c != '\r') {
            field += c;
        }
    }
    if (quoted)
        return std::nullopt;
    fields << QString::fromUtf8(field);
    return fields;
}

// "ru.03 Actual frequency [Hz]" -> title and unit.
ScopeSeries column(const QString &header)
{
    ScopeSeries series;
    const qsizetype open = header.lastIndexOf(QStringLiteral(" ["));
    if (open > 0 && header.endsWith(QLatin1Char(']'))) {
        series.title = header.left(open);
        series.unit = header.mid(open + 2, header.size() - open - 3);
    } else {
        series.title = header;
    }
    return series;
}

std::optional<double> number(const char *begin, const char *end)
{
    double value = 0;
    const std::from_chars_result result = std::from_chars(begin, end, value);
    if (result.ec != std::errc() || result.ptr != end || !std::isfinite(value))
        return std::nullopt;
    return value;
}

bool fail(const QString &message, QString *error)
{
    if (error)
        *error = message;
    return false;
}

} // namespace

bool readScopeCsv(const QString &path, QList<ScopeSeries> &columns, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(ScopeCsvReader::tr("cannot read '%1': %2").arg(path, file.errorString()),
                    error);
    QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return fail(ScopeCsvReader::tr("cannot read '%1': %2").arg(path, file.errorString()),
                    error);
    if (bytes.startsWith("\xEF\xBB\xBF"))
        bytes.remove(0, 3);

    qsizetype at = 0;
    const std::optional<QStringList> header = headerFields(bytes, at);
    if (!header || header->constFirst() != QLatin1String("Time [ms]")) {
        return fail(ScopeCsvReader::tr("'%1' is not a scope CSV export: its first column is not "
                                       "\"Time [ms]\"")
                        .arg(path),
                    error);
    }
    QList<ScopeSeries> read;
    for (qsizetype i = 1; i < header->size(); ++i)
        read << column(header->at(i));
    const qsizetype fieldCount = header->size();
    // About 8 bytes a field: enough room that a column seldom grows.
    const std::size_t expectedRows = std::size_t((bytes.size() - at) / (8 * fieldCount) + 1);
    for (ScopeSeries &series : read) {
        series.timeMs.reserve(expectedRows);
        series.values.reserve(expectedRows);
    }

    int line = 1;
    double previousTime = -std::numeric_limits<double>::infinity();
    const char *data = bytes.constData();
    while (at < bytes.size()) {
        ++line;
        qsizetype end = bytes.indexOf('\n', at);
        if (end < 0)
            end = bytes.size();
        qsizetype last = end;
        if (last > at && data[last - 1] == '\r')
            --last;
        // An empty line ends the samples: what follows (the measurements) is no sample.
        if (last == at)
            break;
        const qsizetype fields = 1 + std::count(data + at, data + last, ',');
        if (fields != fieldCount) {
            return fail(ScopeCsvReader::tr("'%1', line %2 has %3 fields, the header %4")
                            .arg(path)
                            .arg(line)
                            .arg(fields)
                            .arg(fieldCount),
                        error);
        }
        double time = 0;
        qsizetype begin = at;
        for (qsizetype field = 0; field < fieldCount; ++field) {
            const char *stop = std::find(data + begin, data + last, ',');
            const qsizetype size = stop - (data + begin);
            // An empty value: the scaling had no number for it.
            if (field == 0 || size > 0) {
                const std::optional<double> value = number(data + begin, stop);
                if (!value) {
                    return fail(
                        ScopeCsvReader::tr("'%1', line %2: \"%3\" in column \"%4\" is not a number")
                            .arg(path)
                            .arg(line)
                            .arg(QString::fromUtf8(data + begin, size), header->at(field)),
                        error);
                }
                if (field == 0) {
                    time = *value;
                    if (time < previousTime) {
                        return fail(
                            ScopeCsvReader::tr("'%1', line %2: the time %3 ms is earlier than the "
                                               "line's before")
                                .arg(path)
                                .arg(line)
                                .arg(time),
                            error);
                    }
                    previousTime = time;
                } else {
                    ScopeSeries &series = read[field - 1];
                    series.timeMs.push_back(time);
                    series.values.push_back(*value);
                }
            }
            begin += size + 1;
        }
        at = end + 1;
    }
    columns = std::move(read);
    return true;
}

} // namespace DriveDesk
