#pragma once

#include "scope/MinMaxPyramid.h"
#include "scope/SampleStore.h"

#include <vector>

namespace DriveDesk {

// The pixel columns of one redraw: the columns of equal time that
// MinMaxPyramid::decimateTime() makes, found once for all four channels. Each is a whole
// number of ms wide and sits on a grid fixed in time (multiples of its width), so that a
// scrolling view regroups no samples and a column keeps its min and max as the view moves on.
//
// decimateTime() searches each column's first sample anew for every channel, from scratch;
// on a roll view's redraw those searches took about a fifth of its time (docs/performance.md).
// Here they are made once, each outwards from where the previous column's width points, and
// every channel reads its column's min and max from the pyramid (MinMaxPyramid::minMax():
// exact, every peak kept).
class ScopeColumnGrid
{
public:
    // The samples [0, sampleCount) with fromMs <= time <= toMs (the grid's first column may
    // start up to a column's width before fromMs), in about `columns` columns. The last
    // column ends at sample sampleCount - 1 at the latest, by index.
    ScopeColumnGrid(const SampleStore &samples, qint64 fromMs, qint64 toMs, int columns,
                    qsizetype sampleCount);

    int count() const { return int(m_bounds.size()) - 1; }
    qint64 widthMs() const { return m_widthMs; }
    // Where the first column starts: a multiple of widthMs() at or before the view's start.
    qint64 fromMs() const { return m_fromMs; }
    // The samples in all columns, [first(), end()).
    qsizetype first() const { return m_bounds.empty() ? 0 : m_bounds.front(); }
    qsizetype end() const { return m_bounds.empty() ? 0 : m_bounds.back(); }
    bool isEmpty(int column) const { return m_bounds[column] >= m_bounds[column + 1]; }
    // The samples of a column, [columnBegin(), columnEnd()).
    qsizetype columnBegin(int column) const { return m_bounds[std::size_t(column)]; }
    qsizetype columnEnd(int column) const { return m_bounds[std::size_t(column) + 1]; }
    // The time of the sample at `index`, ms.
    qint64 timeAt(qsizetype index) const { return m_samples.time(index); }
    // A column that is not empty, with its min and max on `channel`.
    MinMaxPyramid::Column column(const MinMaxPyramid &pyramid, int channel, int column) const;

private:
    // The first index in [low, end) whose time is >= ms (end if none), searched outwards from
    // a guess.
    qsizetype search(qsizetype low, qsizetype guess, qsizetype end, qint64 ms) const;

    const SampleStore &m_samples;
    qint64 m_widthMs = 1;
    qint64 m_fromMs = 0;
    std::vector<qsizetype> m_bounds; // column c: [m_bounds[c], m_bounds[c + 1])
};

} // namespace DriveDesk
