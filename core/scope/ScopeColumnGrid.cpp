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
    for (std::size_t c = 1; c < gridColumns; ++c) {
        // Columns of equal time hold about as many samples as the one before.
        const qsizetype previous = m_bounds[c - 1];
        const qsizetype guess = previous + (c > 1 ? previous - m_bounds[c - 2] : 0);
        m_bounds[c] = search(previous, guess, end, m_fromMs + qint64(c) * m_widthMs);
    }
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

qsizetype ScopeColumnGrid::search(qsizetype low, qsizetype guess, qsizetype end, qint64 ms) const
{
    // From the guess, steps of 1, 2, 4, ... towards the boundary until past it, then a binary
    // search in the last step: O(log of the guess's error), on memory near the guess.
    guess = std::clamp(guess, low, end);
    qsizetype from = low;
    qsizetype to = end;
    if (guess < end && m_samples.time(guess) < ms) {
        from = guess + 1;
        qsizetype probe = from;
        for (qsizetype step = 1; probe < end && m_samples.time(probe) < ms; step *= 2) {
            from = probe + 1;
            probe += step;
        }
        to = std::min(probe, end);
    } else {
        to = guess;
        qsizetype probe = guess - 1;
        for (qsizetype step = 1; probe >= low && m_samples.time(probe) >= ms; step *= 2) {
            to = probe;
            probe -= step;
        }
        from = std::max(probe + 1, low);
    }
    while (from < to) {
        const qsizetype middle = from + (to - from) / 2;
        if (m_samples.time(middle) < ms)
            from = middle + 1;
        else
            to = middle;
    }
    return from;
}

} // namespace DriveDesk
