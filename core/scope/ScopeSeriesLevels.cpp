#include "ScopeSeriesLevels.h"

#include "ScopeSeries.h"

#include <algorithm>
#include <bit>
#include <limits>

namespace DriveDesk {

namespace {

ScopeSeriesLevels::MinMax merged(ScopeSeriesLevels::MinMax a, ScopeSeriesLevels::MinMax b)
{
    return { std::min(a.min, b.min), std::max(a.max, b.max) };
}

ScopeSeriesLevels::MinMax rawMinMax(const std::vector<double> &values, qsizetype begin,
                                    qsizetype end)
{
    const auto [low, high] = std::minmax_element(values.begin() + begin, values.begin() + end);
    return { *low, *high };
}

} // namespace

ScopeSeriesLevels::ScopeSeriesLevels(const ScopeSeries &series)
    : m_count(series.count())
{
    const qsizetype blocks = m_count >> kBaseShift;
    if (blocks == 0)
        return;
    std::vector<MinMax> base;
    base.reserve(std::size_t(blocks));
    for (qsizetype block = 0; block < blocks; ++block)
        base.push_back(rawMinMax(series.values, block << kBaseShift, (block + 1) << kBaseShift));
    m_levels.push_back(std::move(base));
    // Each level from pairs of the one below, while a pair is left.
    while (m_levels.back().size() >= 2) {
        const std::vector<MinMax> &below = m_levels.back();
        std::vector<MinMax> level;
        level.reserve(below.size() / 2);
        for (std::size_t i = 0; i + 1 < below.size(); i += 2)
            level.push_back(merged(below[i], below[i + 1]));
        m_levels.push_back(std::move(level));
    }
}

ScopeSeriesLevels::MinMax ScopeSeriesLevels::minMax(const std::vector<double> &values,
                                                    qsizetype begin, qsizetype end) const
{
    Q_ASSERT(begin < end && end <= m_count && qsizetype(values.size()) == m_count);
    MinMax result { std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity() };
    qsizetype index = begin;
    const qsizetype aligned = std::min(end, (begin + kBaseSize - 1) / kBaseSize * kBaseSize);
    if (index < aligned) {
        result = merged(result, rawMinMax(values, index, aligned));
        index = aligned;
    }
    // As MinMaxPyramid::minMax(): the largest block aligned at `index` that ends by `end`.
    while (end - index >= kBaseSize) {
        const int alignment = index == 0 ? 63 : std::countr_zero(quint64(index));
        const int fits = 63 - std::countl_zero(quint64(end - index));
        const int shift = std::min(alignment, fits);
        const int level = std::min<int>(shift - kBaseShift, levelCount() - 1);
        result = merged(result, m_levels[std::size_t(level)][std::size_t(index >> (kBaseShift + level))]);
        index += qsizetype(1) << (kBaseShift + level);
    }
    if (index < end)
        result = merged(result, rawMinMax(values, index, end));
    return result;
}

} // namespace DriveDesk
