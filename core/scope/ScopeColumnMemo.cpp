#include "ScopeColumnMemo.h"

namespace DriveDesk {

void ScopeColumnMemo::clear()
{
    m_widthMs = 0;
    m_takenOver = 0;
    for (auto &columns : m_kept)
        columns.clear();
    for (auto &columns : m_read)
        columns.clear();
}

MinMaxPyramid::Column ScopeColumnMemo::column(const ScopeColumnGrid &grid,
                                              const MinMaxPyramid &pyramid, int channel,
                                              int column)
{
    std::vector<MinMaxPyramid::Column> &read = m_read[std::size_t(channel)];
    if (read.size() != std::size_t(grid.count()))
        read.assign(std::size_t(grid.count()), MinMaxPyramid::Column {});
    const std::vector<MinMaxPyramid::Column> &kept = m_kept[std::size_t(channel)];
    const qint64 shift = grid.fromMs() - m_fromMs;
    if (m_widthMs == grid.widthMs() && shift % m_widthMs == 0) {
        const qint64 at = column + shift / m_widthMs;
        if (at >= 0 && at < qint64(kept.size())) {
            const MinMaxPyramid::Column &candidate = kept[std::size_t(at)];
            const qsizetype begin = grid.columnBegin(column);
            const qsizetype end = grid.columnEnd(column);
            if (candidate.end > candidate.begin && candidate.begin == begin
                && candidate.end == end && candidate.firstTime == grid.timeAt(begin)
                && candidate.lastTime == grid.timeAt(end - 1)) {
                read[std::size_t(column)] = candidate;
                ++m_takenOver;
                return candidate;
            }
        }
    }
    const MinMaxPyramid::Column fresh = grid.column(pyramid, channel, column);
    read[std::size_t(column)] = fresh;
    return fresh;
}

void ScopeColumnMemo::keep(const ScopeColumnGrid &grid)
{
    m_widthMs = grid.widthMs();
    m_fromMs = grid.fromMs();
    std::swap(m_kept, m_read);
    for (auto &columns : m_read)
        columns.clear();
    m_takenOver = 0;
}

} // namespace DriveDesk
