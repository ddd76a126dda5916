#include "ScopeSeries.h"

#include "ScopeRecording.h"
#include "ScopeSnapshot.h"

#include <algorithm>

namespace DriveDesk {

qsizetype ScopeSeries::lowerBound(double ms) const
{
    return qsizetype(std::lower_bound(timeMs.begin(), timeMs.end(), ms) - timeMs.begin());
}

qsizetype ScopeSeries::upperBound(double ms) const
{
    return qsizetype(std::upper_bound(timeMs.begin(), timeMs.end(), ms) - timeMs.begin());
}

QString ScopeSeries::label() const
{
    return unit.isEmpty() ? title : QStringLiteral("%1 [%2]").arg(title, unit);
}

namespace {

template<typename Recording>
ScopeSeries seriesOf(const Recording &recording, const SampleStore &samples, int channel,
                     qint64 fromMs, qint64 toMs)
{
    Q_ASSERT(channel >= 0 && channel < recording.channels.size());
    ScopeSeries series;
    series.title = recording.channels.at(channel).title(channel);
    series.unit = recording.channels.at(channel).unit();
    const SampleStore::IndexRange range = samples.indexRange(fromMs, toMs);
    series.timeMs.reserve(std::size_t(range.count()));
    series.values.reserve(std::size_t(range.count()));
    for (qsizetype index = range.begin; index < range.end; ++index) {
        series.timeMs.push_back(double(samples.time(index)));
        series.values.push_back(recording.displayValue(index, channel));
    }
    return series;
}

} // namespace

ScopeSeries scopeSeries(const ScopeRecording &recording, int channel, qint64 fromMs, qint64 toMs)
{
    return seriesOf(recording, recording.buffer.samples(), channel, fromMs, toMs);
}

ScopeSeries scopeSeries(const ScopeSnapshot &snapshot, int channel, qint64 fromMs, qint64 toMs)
{
    return seriesOf(snapshot, snapshot.samples, channel, fromMs, toMs);
}

} // namespace DriveDesk
