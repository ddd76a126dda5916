#include "ScopeColumnGrid.h"

#include <algorithm>

namespace DriveDesk {

ScopeColumnGrid::ScopeColumnGrid(const SampleStore &samples, qint64 fromMs, qint64 toMs,
                                 int columns, qsizetype sampleCount)
    : m_samples(samples)
{
    const qsizetype count = std::min(sampleCount, samples.count());
    if (count == 0 || toMs < fromMs || columns <= 0)
        return;
    m_widthMs = std::max<qint64>(1, (toMs - fromMs + columns) / columns); // ceil(span / columns)
    m_fromMs = fromMs >= 0 ? fromMs / m_widthMs * m_widthMs
                           : -((-fromMs + m_widthMs - 1) / m_widthMs) * m_widthMs;
    toMs = std::min(toMs, samples.time(count - 1));
    if (toMs < m_fromMs)
        return;
    const qsizetype end = std::min(samples.upperBound(toMs), count);
    const auto gridColumns = std::size_t((toMs - m_fromMs) / m_widthMs + 1);
    m_bounds.resize(gridColumns + 1);
    m_bounds[0] = std::min(samples.lowerBound(m_fromMs), end);
    for (std::size_t c = 1; c < gridColumns; ++c)
        m_bounds[c] = gallop(m_bounds[c - 1], end, m_fromMs + qint64(c) * m_widthMs);
    m_bounds[gridColumns] = end;
}

MinMaxPyramid::Column ScopeColumnGrid::column(const MinMaxPyramid &pyramid, int channel,
                                              int column) const
{
    const qsizetype begin = m_bounds[column];
    const qsizetype end = m_bounds[column + 1];
    const MinMaxPyramid::MinMax extremes = pyramid.minMax(m_samples, channel, begin, end);
    return {
        begin, end, m_samples.time(begin), m_samples.time(end - 1), extremes.min, extremes.max
    };
}

qsizetype ScopeColumnGrid::gallop(qsizetype from, qsizetype end, qint64 ms) const
{
    // Steps of 1, 2, 4, ... until a sample at or after ms, then a binary search in the last
    // step: O(log of the distance), on memory near the previous boundary.
    qsizetype low = from;
    qsizetype high = from;
    for (qsizetype step = 1; high < end && m_samples.time(high) < ms; step *= 2) {
        low = high + 1;
        high = std::min(high + step, end);
    }
    while (low < high) {
        const qsizetype middle = low + (high - low) / 2;
        if (m_samples.time(middle) < ms)
            low = middle + 1;
        else
            high = middle;
    }
    return low;
}

} // namespace DriveDesk
