#include "ScopeMath.h"

#include "ScopeRecording.h"
#include "ScopeSnapshot.h"

#include <cmath>

namespace DriveDesk {

namespace {

using Kind = ScopeMathDefinition::Kind;

QString tooFewTimes()
{
    return ScopeMathDefinition::tr("a derivative needs samples at two different times");
}

bool derivative(const ScopeSeries &source, ScopeSeries &out, QString *error)
{
    const std::size_t n = source.timeMs.size();
    const std::vector<double> &t = source.timeMs;
    const std::vector<double> &v = source.values;
    if (n < 2 || t.front() == t.back()) {
        *error = tooFewTimes();
        return false;
    }
    out.timeMs = t;
    out.values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        // The nearest samples at an earlier and a later time: samples of the same ms stand for
        // no time between them.
        std::size_t before = i;
        while (before > 0 && t[before] == t[i])
            --before;
        std::size_t after = i;
        while (after + 1 < n && t[after] == t[i])
            ++after;
        const bool hasBefore = t[before] < t[i];
        const bool hasAfter = t[after] > t[i];
        double slope = 0; // per ms
        if (hasBefore && hasAfter) {
            // The slope at t[i] of the parabola through the three samples.
            const double h1 = t[i] - t[before];
            const double h2 = t[after] - t[i];
            slope = (-h2 / (h1 * (h1 + h2))) * v[before] + ((h2 - h1) / (h1 * h2)) * v[i]
                + (h1 / (h2 * (h1 + h2))) * v[after];
        } else if (hasAfter) {
            slope = (v[after] - v[i]) / (t[after] - t[i]);
        } else {
            slope = (v[i] - v[before]) / (t[i] - t[before]);
        }
        out.values[i] = slope * 1000.0;
    }
    return true;
}

void integral(const ScopeSeries &source, ScopeSeries &out)
{
    const std::vector<double> &t = source.timeMs;
    const std::vector<double> &v = source.values;
    out.timeMs = t;
    out.values.resize(t.size());
    // Summed in long double: a million trapezoids lose no digit the display would show.
    long double area = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (i > 0)
            area += (long double)(v[i - 1] + v[i]) / 2 * (t[i] - t[i - 1]) / 1000;
        out.values[i] = double(area);
    }
}

// first + sign * second at the first's times: `second`'s sample of the same index where both
// have the same times (channels of one recording), its line between samples otherwise.
void combine(const ScopeSeries &first, const ScopeSeries &second, double sign, ScopeSeries &out)
{
    if (first.timeMs == second.timeMs) {
        out.timeMs = first.timeMs;
        out.values.resize(first.values.size());
        for (std::size_t i = 0; i < first.values.size(); ++i)
            out.values[i] = first.values[i] + sign * second.values[i];
        return;
    }
    const std::vector<double> &t = second.timeMs;
    const std::vector<double> &v = second.values;
    std::size_t j = 0; // the last sample of `second` at or before the time wanted
    for (std::size_t i = 0; i < first.timeMs.size(); ++i) {
        const double time = first.timeMs[i];
        if (t.empty() || time < t.front() || time > t.back())
            continue;
        while (j + 1 < t.size() && t[j + 1] <= time)
            ++j;
        double other = v[j];
        if (t[j] < time && j + 1 < t.size())
            other += (v[j + 1] - v[j]) * (time - t[j]) / (t[j + 1] - t[j]);
        out.timeMs.push_back(time);
        out.values.push_back(first.values[i] + sign * other);
    }
}

void movingAverage(const ScopeSeries &source, const ScopeMathDefinition &definition,
                   ScopeSeries &out)
{
    const std::vector<double> &t = source.timeMs;
    const std::vector<double> &v = source.values;
    const std::size_t n = t.size();
    const bool bySamples = definition.windowUnit == ScopeMathDefinition::WindowUnit::Samples;
    const auto length = std::size_t(bySamples ? definition.window : 0);
    const std::size_t before = length / 2;
    const std::size_t after = length - 1 - before;
    const double halfMs = definition.window / 2;
    out.timeMs = t;
    out.values.resize(n);
    // The window [begin, end) only moves forward: each sample enters and leaves the sum once.
    std::size_t begin = 0;
    std::size_t end = 0;
    long double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t wantBegin = bySamples ? (i > before ? i - before : 0) : begin;
        std::size_t wantEnd = bySamples ? std::min(n, i + after + 1) : std::max(end, i + 1);
        if (!bySamples) {
            while (wantEnd < n && t[wantEnd] <= t[i] + halfMs)
                ++wantEnd;
        }
        for (; end < wantEnd; ++end)
            sum += v[end];
        for (; begin < wantBegin; ++begin)
            sum -= v[begin];
        if (!bySamples) {
            while (t[begin] < t[i] - halfMs) {
                sum -= v[begin];
                ++begin;
            }
        }
        out.values[i] = double(sum / (long double)(end - begin));
    }
}

} // namespace

ScopeMathResult computeScopeMath(const ScopeMathDefinition &definition, const ScopeSeries &first,
                                 const ScopeSeries *second)
{
    ScopeMathResult result;
    const bool two = ScopeMathDefinition::sourceCount(definition.kind) == 2;
    // The definition's channels are those of a recording; here the traces are given.
    result.error = two && !second
        ? ScopeMathDefinition::tr("a difference or a sum reads two channels")
        : definition.checkWindow();
    if (!result.ok())
        return result;
    const QString secondUnit = two ? second->unit : QString();
    result.unit = scopeMathUnit(definition.kind, first.unit, secondUnit);
    result.series.unit = result.unit.symbol;
    result.series.title = scopeMathTitle(definition, first.title, two ? second->title : QString());
    switch (definition.kind) {
    case Kind::Derivative:
        derivative(first, result.series, &result.error);
        break;
    case Kind::Integral:
        integral(first, result.series);
        break;
    case Kind::Difference:
        combine(first, *second, -1, result.series);
        break;
    case Kind::Sum:
        combine(first, *second, 1, result.series);
        break;
    case Kind::MovingAverage:
        movingAverage(first, definition, result.series);
        break;
    }
    return result;
}

namespace {

template<typename Recording>
ScopeMathResult computeOf(const ScopeMathDefinition &definition, const Recording &recording)
{
    const QString wrong = definition.check(int(recording.channels.size()));
    if (!wrong.isEmpty()) {
        ScopeMathResult result;
        result.error = wrong;
        return result;
    }
    const ScopeSeries first = scopeSeries(recording, definition.sources.at(0));
    if (definition.sources.size() < 2)
        return computeScopeMath(definition, first);
    const ScopeSeries second = scopeSeries(recording, definition.sources.at(1));
    return computeScopeMath(definition, first, &second);
}

} // namespace

ScopeMathResult computeScopeMath(const ScopeMathDefinition &definition,
                                 const ScopeRecording &recording)
{
    return computeOf(definition, recording);
}

ScopeMathResult computeScopeMath(const ScopeMathDefinition &definition,
                                 const ScopeSnapshot &snapshot)
{
    return computeOf(definition, snapshot);
}

} // namespace DriveDesk
