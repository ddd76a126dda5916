#include "ScopeMeasurements.h"

#include "ScopeSampleWindow.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace DriveDesk {

namespace {

// Where the line from sample a to sample b crosses `level` (which lies between their values).
template<typename Window>
double crossing(const Window &window, qsizetype a, qsizetype b, double level)
{
    const double va = window.value(a);
    const double vb = window.value(b);
    const double share = vb == va ? 0.0 : (level - va) / (vb - va);
    return window.time(a) + share * (window.time(b) - window.time(a));
}

// The first passage from `from` (at or beyond it: below for a rise) to `to`.
template<typename Window>
std::optional<ScopeTransition> transition(const Window &window, double from, double to)
{
    const bool rising = to >= from;
    const auto atOrBeyondStart = [&](double v) { return rising ? v <= from : v >= from; };
    const auto reachedEnd = [&](double v) { return rising ? v >= to : v <= to; };
    qsizetype lastAtStart = -1;
    for (qsizetype i = window.begin; i < window.end; ++i) {
        const double v = window.value(i);
        if (atOrBeyondStart(v)) {
            lastAtStart = i;
        } else if (reachedEnd(v) && lastAtStart >= 0) {
            ScopeTransition found;
            found.startMs = crossing(window, lastAtStart, lastAtStart + 1, from);
            found.endMs = crossing(window, i - 1, i, to);
            if (found.durationMs() > 0)
                found.ratePerSecond = (to - from) / found.durationMs() * 1000.0;
            return found;
        }
    }
    return std::nullopt;
}

template<typename Window>
ScopeMeasurements measure(const Window &window, const ScopeMeasureOptions &options)
{
    ScopeMeasurements result;
    result.samples = window.end - window.begin;
    if (result.samples <= 0) {
        result.samples = 0;
        return result;
    }
    result.firstMs = window.time(window.begin);
    result.lastMs = window.time(window.end - 1);
    result.minimum = std::numeric_limits<double>::infinity();
    result.maximum = -std::numeric_limits<double>::infinity();
    // The line through the samples, integrated piece by piece: its mean and its mean square.
    double area = 0;
    double squareArea = 0;
    double sum = 0;
    double squareSum = 0;
    double previousTime = 0;
    double previous = 0;
    for (qsizetype i = window.begin; i < window.end; ++i) {
        const double t = window.time(i);
        const double v = window.value(i);
        if (v < result.minimum) {
            result.minimum = v;
            result.minimumMs = t;
        }
        if (v > result.maximum) {
            result.maximum = v;
            result.maximumMs = t;
        }
        sum += v;
        squareSum += v * v;
        if (i > window.begin) {
            const double dt = t - previousTime;
            area += dt * (previous + v) / 2;
            squareArea += dt * (previous * previous + previous * v + v * v) / 3;
        }
        previousTime = t;
        previous = v;
    }
    const double spanMs = result.lastMs - result.firstMs;
    if (spanMs > 0) {
        result.mean = area / spanMs;
        result.rms = std::sqrt(std::max(0.0, squareArea / spanMs));
    } else {
        result.mean = sum / double(result.samples);
        result.rms = std::sqrt(squareSum / double(result.samples));
    }

    const double span = result.maximum - result.minimum;
    result.lowLevel = options.lowLevel.value_or(result.minimum + options.lowShare * span);
    result.highLevel = options.highLevel.value_or(result.minimum + options.highShare * span);
    if (result.lowLevel > result.highLevel)
        std::swap(result.lowLevel, result.highLevel);
    // A flat window has no transitions: its levels coincide.
    if (result.highLevel > result.lowLevel) {
        result.rise = transition(window, result.lowLevel, result.highLevel);
        result.fall = transition(window, result.highLevel, result.lowLevel);
    }
    return result;
}

} // namespace

ScopeMeasurements measureScope(const ScopeRecording &recording, int channel, double fromMs,
                               double toMs, const ScopeMeasureOptions &options)
{
    Q_ASSERT(channel >= 0 && channel < recording.channels.size());
    if (toMs < fromMs)
        std::swap(fromMs, toMs);
    return measure(ScopeSampleWindow::OfRecording(recording, channel, fromMs, toMs), options);
}

ScopeMeasurements measureScope(const ScopeSnapshot &snapshot, int channel, double fromMs,
                               double toMs, const ScopeMeasureOptions &options)
{
    Q_ASSERT(channel >= 0 && channel < snapshot.channels.size());
    if (toMs < fromMs)
        std::swap(fromMs, toMs);
    return measure(ScopeSampleWindow::OfRecording(snapshot, channel, fromMs, toMs), options);
}

ScopeMeasurements measureScope(const ScopeSeries &series, double fromMs, double toMs,
                               const ScopeMeasureOptions &options)
{
    if (toMs < fromMs)
        std::swap(fromMs, toMs);
    return measure(ScopeSampleWindow::OfSeries(series, fromMs, toMs), options);
}

} // namespace DriveDesk
