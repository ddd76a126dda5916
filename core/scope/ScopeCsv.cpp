#include "ScopeCsv.h"

#include "ScopeRecording.h"
#include "ScopeSeries.h"
#include "parameters/ParameterCsv.h"

#include <QCoreApplication>
#include <QIODevice>
#include <QSaveFile>
#include <QStringList>

#include <array>
#include <charconv>
#include <optional>

namespace DriveDesk {

namespace {

// Rows are formatted into a block of about this size and written in one call: a million rows
// make some forty calls, not millions.
constexpr qsizetype kBlockSize = qsizetype(1) << 20;
// Room for one field: a sign, 19 digits of a qint64, a point and four decimals, a comma.
constexpr qsizetype kMaxFieldSize = 32;
// A math channel's value: computed, not sent by the drive; six digits tell its shape.
constexpr int kMathDigits = 6;

constexpr std::array<quint64, DisplayScaling::kMaxDecimals + 1> kPow10 { 1, 10, 100, 1000, 10000 };

// How one column turns a raw value into text, worked out once per export.
struct ColumnFormat
{
    int channel = 0;
    const DisplayScaling *scaling = nullptr; // nullptr: the raw value
    int decimals = 0;
    bool trimZeros = false;
};

enum class Outcome { Written, Cancelled, WriteFailed };

char *writeInteger(char *at, qint64 value)
{
    return std::to_chars(at, at + kMaxFieldSize, value).ptr;
}

// `scaled` / 10^decimals with '.' as separator; `scaled` is already rounded, so a zero has no
// sign. std::to_chars on a double would round a second time; this keeps format()'s digits.
char *writeFixedPoint(char *at, qint64 scaled, int decimals, bool trimZeros)
{
    if (decimals == 0)
        return writeInteger(at, scaled);
    if (scaled < 0)
        *at++ = '-';
    const quint64 magnitude = scaled < 0 ? 0 - quint64(scaled) : quint64(scaled);
    at = std::to_chars(at, at + kMaxFieldSize, magnitude / kPow10[decimals]).ptr;
    quint64 fraction = magnitude % kPow10[decimals];
    if (trimZeros) {
        while (decimals > 0 && fraction % 10 == 0) {
            fraction /= 10;
            --decimals;
        }
        if (decimals == 0)
            return at;
    }
    *at++ = '.';
    for (int digit = decimals - 1; digit >= 0; --digit) {
        at[digit] = char('0' + fraction % 10);
        fraction /= 10;
    }
    return at + decimals;
}

QList<ColumnFormat> columnFormats(const ScopeRecording &recording, const QList<int> &channels)
{
    QList<ColumnFormat> columns;
    for (int channel : channels) {
        const DisplayScaling &scaling = recording.channels.at(channel).scaling;
        ColumnFormat column;
        column.channel = channel;
        // Hexadecimal has no number to scale, an invalid scaling none at all: the chart shows
        // these raw (ScopeChannel::toDisplay()), and so does the file.
        if (scaling.representation() != DisplayScaling::Representation::Hexadecimal
            && scaling.isValid()) {
            column.scaling = &scaling;
            column.decimals = scaling.decimals();
            column.trimZeros
                = scaling.representation() == DisplayScaling::Representation::VariableDecimals;
        }
        columns << column;
    }
    return columns;
}

QByteArray headerLine(const ScopeRecording &recording, const QList<int> &channels,
                      const QList<const ScopeSeries *> &math)
{
    // Not translated: tools read this column by name.
    QStringList fields { QStringLiteral("Time [ms]") };
    for (int channel : channels)
        fields << scopeCsvColumnHeader(recording.channels.at(channel), channel);
    for (const ScopeSeries *series : math)
        fields << series->label();
    return csvRecord(fields).toUtf8() + "\r\n";
}

bool writeAll(QIODevice &out, const char *data, qsizetype size)
{
    return out.write(data, size) == size;
}

// The header and the rows; a channel index is known to be valid.
Outcome writeCsv(QIODevice &out, const ScopeRecording &recording, const ScopeCsvOptions &options)
{
    const QByteArray header = headerLine(recording, options.channels, options.math);
    if (!writeAll(out, header.constData(), header.size()))
        return Outcome::WriteFailed;

    const QList<ColumnFormat> columns = columnFormats(recording, options.channels);
    const SampleStore &store = recording.buffer.samples();
    const SampleStore::IndexRange range = store.indexRange(options.fromMs, options.toMs);
    const qint64 origin = recording.firstTime();
    const qsizetype maxRowSize = kMaxFieldSize * (columns.size() + options.math.size() + 1) + 2;
    QByteArray block(kBlockSize + maxRowSize, Qt::Uninitialized);
    char *const begin = block.data();
    char *at = begin;

    for (qsizetype index = range.begin; index < range.end; ++index) {
        const ScopeSample sample = store.at(index);
        at = writeInteger(at, sample.time - origin);
        for (const ColumnFormat &column : columns) {
            *at++ = ',';
            const qint32 raw = sample.channel(column.channel);
            if (!column.scaling) {
                at = writeInteger(at, raw);
            } else if (const std::optional<qint64> scaled = column.scaling->toFixedPoint(raw)) {
                at = writeFixedPoint(at, *scaled, column.decimals, column.trimZeros);
            } // else: no number (mode 1 at its pole), an empty field
        }
        for (const ScopeSeries *series : options.math) {
            *at++ = ',';
            if (index < series->count()) {
                at = std::to_chars(at, at + kMaxFieldSize, series->values[std::size_t(index)],
                                   std::chars_format::general, kMathDigits)
                         .ptr;
            }
        }
        *at++ = '\r';
        *at++ = '\n';
        if (at - begin >= kBlockSize) {
            if (!writeAll(out, begin, at - begin))
                return Outcome::WriteFailed;
            at = begin;
        }
        const qsizetype done = index - range.begin + 1;
        if (options.progress && done % kScopeCsvProgressRows == 0 && done < range.count()
            && !options.progress(done, range.count()))
            return Outcome::Cancelled;
    }
    if (!writeAll(out, begin, at - begin))
        return Outcome::WriteFailed;
    if (options.progress && !options.progress(range.count(), range.count()))
        return Outcome::Cancelled;
    if (options.measureBetweenMs) {
        const QByteArray section
            = "\r\n"
            + scopeCsvMeasurements(recording, options.channels, options.measureBetweenMs->first,
                                   options.measureBetweenMs->second, options.math);
        if (!writeAll(out, section.constData(), section.size()))
            return Outcome::WriteFailed;
    }
    return Outcome::Written;
}

bool checkChannels(const QList<int> &channels, QString *error)
{
    for (int channel : channels) {
        if (channel < 0 || channel >= ScopeSample::kChannelCount) {
            if (error)
                *error = QCoreApplication::translate("ScopeCsv", "there is no channel %1")
                             .arg(channel + 1);
            return false;
        }
    }
    return true;
}

QString cancelledText()
{
    return QCoreApplication::translate("ScopeCsv", "the export was cancelled");
}

} // namespace

bool writeScopeCsv(QIODevice &out, const ScopeRecording &recording, const ScopeCsvOptions &options,
                   QString *error)
{
    if (!checkChannels(options.channels, error))
        return false;
    switch (writeCsv(out, recording, options)) {
    case Outcome::Written:
        return true;
    case Outcome::Cancelled:
        if (error)
            *error = cancelledText();
        return false;
    case Outcome::WriteFailed:
        if (error)
            *error = QCoreApplication::translate("ScopeCsv", "cannot write the CSV: %1")
                         .arg(out.errorString());
        return false;
    }
    return false;
}

bool saveScopeCsv(const QString &path, const ScopeRecording &recording,
                  const ScopeCsvOptions &options, QString *error)
{
    if (!checkChannels(options.channels, error))
        return false;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error)
            *error = QCoreApplication::translate("ScopeCsv", "cannot write '%1': %2")
                         .arg(path, file.errorString());
        return false;
    }
    switch (writeCsv(file, recording, options)) {
    case Outcome::Written:
        break;
    case Outcome::Cancelled:
        file.cancelWriting();
        if (error)
            *error = cancelledText();
        return false;
    case Outcome::WriteFailed:
        if (error)
            *error = QCoreApplication::translate("ScopeCsv", "cannot write '%1': %2")
                         .arg(path, file.errorString());
        file.cancelWriting();
        return false;
    }
    if (!file.commit()) {
        if (error)
            *error = QCoreApplication::translate("ScopeCsv", "cannot save '%1': %2")
                         .arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace DriveDesk
