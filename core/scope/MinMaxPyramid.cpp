#include "MinMaxPyramid.h"

#include "SampleStore.h"

#include <algorithm>
#include <bit>
#include <limits>

namespace DriveDesk {

namespace {

MinMaxPyramid::MinMax merged(MinMaxPyramid::MinMax a, MinMaxPyramid::MinMax b)
{
    return {std::min(a.min, b.min), std::max(a.max, b.max)};
}

} // namespace

void MinMaxPyramid::append(const ScopeSample &sample)
{
    const bool blockStarts = m_count % kBaseSize == 0;
    ++m_count;
    const bool blockEnds = m_count % kBaseSize == 0;
    for (int channel = 0; channel < ScopeSample::kChannelCount; ++channel) {
        const qint32 value = sample.channel(channel);
        MinMax &running = m_running[channel];
        running = blockStarts ? MinMax{value, value} : merged(running, {value, value});
        if (!blockEnds)
            continue;
        auto &levels = m_levels[channel];
        MinMax block = running;
        for (std::size_t level = 0;; ++level) {
            if (levels.size() == level)
                levels.emplace_back();
            levels[level].push_back(block);
            // An even count completes a block of the next level from the last two.
            const std::size_t size = levels[level].size();
            if (size % 2 != 0)
                break;
            block = merged(levels[level][size - 2], levels[level][size - 1]);
        }
    }
}

void MinMaxPyramid::clear()
{
    *this = MinMaxPyramid();
}

MinMaxPyramid::MinMax MinMaxPyramid::minMax(const SampleStore &store, int channel,
                                            qsizetype begin, qsizetype end) const
{
    Q_ASSERT(begin < end && end <= m_count && m_count <= store.count());
    Q_ASSERT(channel >= 0 && channel < ScopeSample::kChannelCount);
    const auto &levels = m_levels[channel];
    MinMax result{std::numeric_limits<qint32>::max(), std::numeric_limits<qint32>::min()};
    const auto addRaw = [&](qsizetype from, qsizetype to) {
        const auto [low, high] = store.valueRange(channel, from, to);
        result = merged(result, {low, high});
    };
    // The raw samples up to the first block boundary, in one pass along the store's column.
    qsizetype index = begin;
    const qsizetype aligned = std::min(end, (begin + kBaseSize - 1) / kBaseSize * kBaseSize);
    if (index < aligned) {
        addRaw(index, aligned);
        index = aligned;
    }
    // Greedy from there: each step takes the largest block aligned at `index` that ends by
    // `end`; block sizes climb to the coarsest that fits and fall again towards the end, at
    // most two blocks a level; fewer than kBaseSize raw samples are left at the end.
    while (end - index >= kBaseSize) {
        const int alignment = index == 0 ? 63 : std::countr_zero(quint64(index));
        const int fits = 63 - std::countl_zero(quint64(end - index));
        const int shift = std::min(alignment, fits);
        const int level = std::min<int>(shift - kBaseShift, int(levels.size()) - 1);
        result = merged(result, levels[level][index >> (kBaseShift + level)]);
        index += qsizetype(1) << (kBaseShift + level);
    }
    if (index < end)
        addRaw(index, end);
    return result;
}

MinMaxPyramid::Column MinMaxPyramid::column(const SampleStore &store, int channel,
                                            qsizetype begin, qsizetype end) const
{
    const MinMax extremes = minMax(store, channel, begin, end);
    return {begin, end, store.time(begin), store.time(end - 1), extremes.min, extremes.max};
}

QList<MinMaxPyramid::Column> MinMaxPyramid::decimate(const SampleStore &store, int channel,
                                                     qsizetype begin, qsizetype end,
                                                     int columns) const
{
    QList<Column> result;
    const qsizetype length = end - begin;
    if (length <= 0 || columns <= 0)
        return result;
    const qsizetype count = std::min<qsizetype>(columns, length);
    result.reserve(count);
    for (qsizetype c = 0; c < count; ++c) {
        // Column c ends where column c + 1 begins: every sample is in exactly one column.
        const qsizetype from = begin + length * c / count;
        const qsizetype to = begin + length * (c + 1) / count;
        result.append(column(store, channel, from, to));
    }
    return result;
}

QList<MinMaxPyramid::Column> MinMaxPyramid::decimateTime(const SampleStore &store, int channel,
                                                         qint64 fromMs, qint64 toMs,
                                                         int columns) const
{
    QList<Column> result;
    if (toMs < fromMs || columns <= 0)
        return result;
    const qint64 span = toMs - fromMs + 1;
    qsizetype from = std::min(store.lowerBound(fromMs), m_count);
    for (int c = 0; c < columns; ++c) {
        // Column c holds the times [fromMs + span * c / columns, fromMs + span * (c+1) / columns).
        const qint64 nextStart = fromMs + qint64(double(span) * (c + 1) / columns);
        const qsizetype to = c + 1 == columns ? std::min(store.upperBound(toMs), m_count)
                                              : std::min(store.lowerBound(nextStart), m_count);
        if (to > from)
            result.append(column(store, channel, from, to));
        from = std::max(from, to);
    }
    return result;
}

qsizetype MinMaxPyramid::bytesUsed() const
{
    qsizetype bytes = 0;
    for (const auto &levels : m_levels) {
        bytes += qsizetype(levels.capacity() * sizeof(std::vector<MinMax>));
        for (const auto &level : levels)
            bytes += qsizetype(level.capacity() * sizeof(MinMax));
    }
    return bytes;
}

} // namespace DriveDesk
