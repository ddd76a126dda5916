#pragma once

#include <QString>
#include <QtGlobal>

#include <limits>
#include <vector>

namespace DriveDesk {

struct ScopeRecording;
struct ScopeSnapshot;

// One trace as numbers in its unit, with their times: what the measurements, the math channels
// and the spectrum read. A channel of a recording (scopeSeries()), a column of a CSV export
// (readScopeCsv()) or a math channel's result. A value type: it may go to another thread.
struct ScopeSeries
{
    QString title; // "ru.03 Actual frequency", "d/dt ru.03 Actual frequency"
    QString unit; // "Hz"; empty for none
    std::vector<double> timeMs; // non-decreasing; equal times are allowed (several samples a ms)
    std::vector<double> values; // as many as timeMs, finite

    qsizetype count() const { return qsizetype(timeMs.size()); }
    bool isEmpty() const { return timeMs.empty(); }
    // The first index whose time is >= ms / > ms (count() if none), by binary search.
    qsizetype lowerBound(double ms) const;
    qsizetype upperBound(double ms) const;
    // "ru.03 Actual frequency [Hz]", or the title alone without a unit.
    QString label() const;
};

// A channel's display values (ScopeChannel::toDisplay()) with from <= time <= to, in the
// recording's own ms (SampleStore::time(), as the chart's cursors give them), titled and unit
// as the channel. The defaults take the whole recording.
ScopeSeries scopeSeries(const ScopeRecording &recording, int channel,
                        qint64 fromMs = std::numeric_limits<qint64>::min(),
                        qint64 toMs = std::numeric_limits<qint64>::max());
// The same from a snapshot, in any thread.
ScopeSeries scopeSeries(const ScopeSnapshot &snapshot, int channel,
                        qint64 fromMs = std::numeric_limits<qint64>::min(),
                        qint64 toMs = std::numeric_limits<qint64>::max());

} // namespace DriveDesk
