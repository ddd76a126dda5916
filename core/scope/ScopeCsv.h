#pragma once

#include <QList>
#include <QString>

#include <functional>
#include <limits>

class QIODevice;

namespace DriveDesk {

struct ScopeRecording;

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
    ScopeCsvProgress progress; // may be empty
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
// Writes to `out` (open for writing). False with the reason on a write error, a channel index
// outside 0..3, or a cancel (what was written by then stays in `out`).
bool writeScopeCsv(QIODevice &out, const ScopeRecording &recording,
                   const ScopeCsvOptions &options = {}, QString *error = nullptr);
// The same into a file, whole or not at all (QSaveFile): after an error or a cancel the file at
// `path` stays as it was.
bool saveScopeCsv(const QString &path, const ScopeRecording &recording,
                  const ScopeCsvOptions &options = {}, QString *error = nullptr);

} // namespace DriveDesk
