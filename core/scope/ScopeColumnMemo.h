#pragma once

#include "scope/ScopeColumnGrid.h"
#include "scope/ScopeSample.h"

#include <array>
#include <vector>

namespace DriveDesk {

// The columns of a recording's last redraw, kept for the next. A rolling view moves on by a
// few columns a tick, and its grid is fixed in time (ScopeColumnGrid), so all but the newest
// columns hold the same samples as before: their min and max are taken from here instead of
// the pyramid, which was a quarter of a roll tick's data (docs/performance.md).
//
// A column is taken over only where the last grid had one at the same time with the same
// samples (the same first and last index, and the same times there); anything else is read
// afresh. The recording must be the same one, samples only appended: clear() when it is
// replaced or cleared.
class ScopeColumnMemo
{
public:
    void clear();
    // `column` of `grid` on `channel`, as grid.column() reads it.
    MinMaxPyramid::Column column(const ScopeColumnGrid &grid, const MinMaxPyramid &pyramid,
                                 int channel, int column);
    // The columns read since the last keep() are the ones kept for the next grid.
    void keep(const ScopeColumnGrid &grid);
    // Columns taken over since the last keep(), of all channels.
    int takenOver() const { return m_takenOver; }

private:
    using Columns = std::array<std::vector<MinMaxPyramid::Column>, ScopeSample::kChannelCount>;

    qint64 m_widthMs = 0; // 0: nothing kept
    qint64 m_fromMs = 0;
    Columns m_kept;
    Columns m_read;
    int m_takenOver = 0;
};

} // namespace DriveDesk
