#pragma once

#include <QList>
#include <QString>

#include <functional>
#include <limits>
#include <optional>
#include <utility>

class QIODevice;

namespace DriveDesk {

struct ScopeChannel;
struct ScopeRecording;
struct ScopeSeries;

// Called after every kScopeCsvProgressRows rows and after the last one with the rows written
// and the rows to write; returning false cancels the export.
using ScopeCsvProgress = std::function<bool(qsizetype done, qsizetype total)>;

constexpr qsizetype kScopeCsvProgressRows = 65536;

// What of a recording goes into a CSV file.
struct ScopeCsvOptions
{
    // The samples with fromMs <= time <= toMs, in the recording's own time (SampleStore::time(),
    // not the relative time written in the file); the defaults take everything.
    qint64 fromMs = std::numeric_limits<qint64>::min();
    qint64 toMs = std::numeric_limits<qint64>::max();
    // Channel indices (0..3), in the order of the columns. A channel that is off is still
    // written when asked for.
    QList<int> channels { 0, 1, 2, 3 };
    // Math channels' traces (computeScopeMath() over the recording: one value a sample, in the
    // samples' order), written after the channels: header "title [unit]", each value at the
    // row's sample to six significant digits, an empty field past the trace's end.
    QList<const ScopeSeries *> math;
    ScopeCsvProgress progress; // may be empty
    // The cursors' times (recording ms, either order): the measurements between them follow
    // the samples as a section of their own (scopeCsvMeasurements()). None: no section.
    std::optional<std::pair<double, double>> measureBetweenMs;
};

// A scope recording as CSV for spreadsheets and analysis tools, every sample (undecimated).
// The header row is "Time [ms]" and, per channel, its title with " [unit]" where it has a unit.
// Each row is the sample's time in whole ms since the recording's first sample (not the
// range's), then each channel's display value: scaled as DisplayScaling::format() rounds it,
// with exactly the scaling's decimals (variable decimals: up to 4, trailing zeros trimmed),
// without the unit. A hexadecimal channel, or one whose scaling is invalid (divisor 0), is
// written as its raw value in decimal; a value the scaling cannot show (calculation mode 1
// with raw + offset = 0) is an empty field. The decimal separator is always '.', whatever
// the language, since the file is for tools. Comma-separated, header fields quoted as
// RFC 4180 asks, CRLF line ends, UTF-8.
//
// With measureBetweenMs, an empty line ends the samples and the measurements follow
// (scopeCsvMeasurements()).
//
// Writes to `out` (open for writing). False with the reason on a write error, a channel index
// outside 0..3, or a cancel (what was written by then stays in `out`).
bool writeScopeCsv(QIODevice &out, const ScopeRecording &recording,
                   const ScopeCsvOptions &options = {}, QString *error = nullptr);
// A channel's column header: its title (ScopeChannel::title()) with " [unit]" where it has a
// unit.
QString scopeCsvColumnHeader(const ScopeChannel &channel, int index);
// The measurements between two times (recording ms, either order) of `channels`, as the CSV's
// section after the samples: a header row "Measurement" and the channels' column headers as
// the samples' header names them, then a row a quantity ("From [ms]", "To [ms]" in the file's
// time, "Samples", "Minimum", "Maximum", "Peak to peak", "Mean", "RMS", "Rise time [ms]",
// "Rise rate [unit/s]", "Fall time [ms]", "Fall rate [unit/s]"), each value in the column's
// unit at full precision ('.', shortest form that reads back the same), an empty field where
// there is none (no samples, no rise). Not translated: for tools, as the header.
QByteArray scopeCsvMeasurements(const ScopeRecording &recording, const QList<int> &channels,
                                double fromMs, double toMs,
                                const QList<const ScopeSeries *> &math = {});
// The same into a file, whole or not at all (QSaveFile): after an error or a cancel the file at
// `path` stays as it was.
bool saveScopeCsv(const QString &path, const ScopeRecording &recording,
                  const ScopeCsvOptions &options = {}, QString *error = nullptr);

} // namespace DriveDesk
