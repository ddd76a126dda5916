#pragma once

#include <QtGlobal>

#include <optional>

namespace DriveDesk {

struct ScopeRecording;
struct ScopeSnapshot;
struct ScopeSeries;

// Where the transitions are measured: between two levels, by default 10 % and 90 % of the span
// between the window's minimum and maximum. A level given in the channel's unit takes the
// place of its share.
struct ScopeMeasureOptions
{
    double lowShare = 0.1;
    double highShare = 0.9;
    std::optional<double> lowLevel; // in the channel's unit
    std::optional<double> highLevel; // in the channel's unit
};

// One passage from one level to the other: the first in the window that goes all the way from
// at or beyond the first level to at or beyond the second. The times are where the line between
// two samples crosses each level (linear interpolation), in the recording's ms.
struct ScopeTransition
{
    double startMs = 0; // the first level left behind (low for a rise, high for a fall)
    double endMs = 0; // the second level reached
    double durationMs() const { return endMs - startMs; }
    // The change between the levels over the duration, in the channel's unit per second
    // (negative for a fall); nothing where both crossings fall in the same ms.
    std::optional<double> ratePerSecond;
};

// What lies between the two cursors on one channel, in the channel's unit. The samples are
// those with from <= time <= to; min and max are the samples', the mean and RMS those of the
// line through the samples (as the chart draws it) over the time from the first to the last,
// so samples that come unevenly weigh by the time they stand for. Where that time is 0 (one
// sample, or all in the same ms) the mean and RMS are the samples' own.
struct ScopeMeasurements
{
    qsizetype samples = 0; // 0: nothing in the window, and nothing else is set
    double firstMs = 0; // the first and last sample's time
    double lastMs = 0;
    double minimum = 0;
    double maximum = 0;
    double minimumMs = 0; // the first sample at the minimum
    double maximumMs = 0; // the first sample at the maximum
    double mean = 0;
    double rms = 0;
    double peakToPeak() const { return maximum - minimum; }

    double lowLevel = 0; // the levels the transitions were measured between
    double highLevel = 0;
    std::optional<ScopeTransition> rise; // nothing when the window holds none
    std::optional<ScopeTransition> fall;
};

// The measurements of `channel` between fromMs and toMs (in either order), read from the
// recording's samples in place (the display values, ScopeChannel::toDisplay()).
ScopeMeasurements measureScope(const ScopeRecording &recording, int channel, double fromMs,
                               double toMs, const ScopeMeasureOptions &options = {});
// The same on a snapshot of a recording, in any thread.
ScopeMeasurements measureScope(const ScopeSnapshot &snapshot, int channel, double fromMs,
                               double toMs, const ScopeMeasureOptions &options = {});
// The same on any trace: a math channel's, a CSV column's.
ScopeMeasurements measureScope(const ScopeSeries &series, double fromMs, double toMs,
                               const ScopeMeasureOptions &options = {});

} // namespace DriveDesk
