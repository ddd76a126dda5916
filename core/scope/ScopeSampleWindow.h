#pragma once

#include "ScopeRecording.h"
#include "ScopeSeries.h"
#include "ScopeSnapshot.h"

#include <algorithm>
#include <cmath>

// Inside core/scope: the samples between two times, read alike from a recording's store in
// place (or a snapshot's) or from a series, by the measurements and the spectrum (time(i) and value(i) for
// begin <= i < end).
namespace DriveDesk::ScopeSampleWindow {

struct OfRecording
{
    OfRecording(const ScopeRecording &recording, int channel, double fromMs, double toMs)
        : OfRecording(recording.buffer.samples(), recording.channels.at(channel), channel, fromMs,
                      toMs)
    { }
    OfRecording(const ScopeSnapshot &snapshot, int channel, double fromMs, double toMs)
        : OfRecording(snapshot.samples, snapshot.channels.at(channel), channel, fromMs, toMs)
    { }
    OfRecording(const SampleStore &samples, const ScopeChannel &source, int channel,
                double fromMs, double toMs)
        : samples(samples)
        , source(source)
        , channel(channel)
    {
        // Whole ms: the first sample at or after `from`, the last at or before `to`.
        const auto clamp = [](double ms) {
            constexpr double limit = 9.0e18;
            return qint64(std::clamp(ms, -limit, limit));
        };
        const SampleStore::IndexRange range
            = samples.indexRange(clamp(std::ceil(fromMs)), clamp(std::floor(toMs)));
        begin = range.begin;
        end = range.end;
    }
    double time(qsizetype i) const { return double(samples.time(i)); }
    double value(qsizetype i) const { return source.toDisplay(samples.value(i, channel)); }

    const SampleStore &samples;
    const ScopeChannel &source;
    int channel = 0;
    qsizetype begin = 0;
    qsizetype end = 0;
};

struct OfSeries
{
    OfSeries(const ScopeSeries &series, double fromMs, double toMs)
        : series(series)
        , begin(series.lowerBound(fromMs))
        , end(std::max(begin, series.upperBound(toMs)))
    { }
    double time(qsizetype i) const { return series.timeMs[std::size_t(i)]; }
    double value(qsizetype i) const { return series.values[std::size_t(i)]; }

    const ScopeSeries &series;
    qsizetype begin = 0;
    qsizetype end = 0;
};

} // namespace DriveDesk::ScopeSampleWindow
