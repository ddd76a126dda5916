#pragma once

#include "ScopeSample.h"

#include <QList>

#include <array>
#include <vector>

namespace DriveDesk {

class SampleStore;

// Min and max per channel over blocks of 2^k samples (k >= kBaseShift), so that a range of
// any length can be summed up from a few blocks: drawing a million samples into 1600 pixel
// columns reads a few thousand values, and no peak is lost at any zoom.
//
// Level 0 holds one entry per complete block of kBaseSize samples, level k one per 2^k of
// those. append() is amortised O(1): a block is written once it is complete, from the running
// min/max of the samples or from two entries of the level below. About 2 bytes a sample for
// four channels.
//
// It indexes the samples of one SampleStore: append() every sample appended there, in the
// same order, and clear() both together (ScopeBuffer does). Single-threaded, like the store.
class MinMaxPyramid
{
public:
    static constexpr int kBaseShift = 5;
    static constexpr qsizetype kBaseSize = qsizetype(1) << kBaseShift;

    struct MinMax
    {
        qint32 min = 0;
        qint32 max = 0;
        bool operator==(const MinMax &) const = default;
    };

    // One pixel column: the samples [begin, end), their time span and extremes.
    struct Column
    {
        qsizetype begin = 0;
        qsizetype end = 0;
        qint64 firstTime = 0; // ms, of the sample at begin
        qint64 lastTime = 0;  // ms, of the sample at end - 1
        qint32 min = 0;
        qint32 max = 0;
        bool operator==(const Column &) const = default;
    };

    void append(const ScopeSample &sample);
    void clear();

    // The samples appended so far.
    qsizetype count() const { return m_count; }
    // Levels with at least one complete block.
    int levelCount() const { return int(m_levels[0].size()); }

    // Min and max of a channel over the samples [begin, end) (not empty): the largest aligned
    // blocks that fit, finer ones towards the ends, raw samples for less than kBaseSize.
    // O(levelCount() + kBaseSize).
    MinMax minMax(const SampleStore &store, int channel, qsizetype begin, qsizetype end) const;

    // The samples [begin, end) cut into `columns` columns of (nearly) equal sample counts,
    // each with its min and max. Fewer columns than asked if there are fewer samples; none if
    // the range is empty. O(columns * (levelCount() + kBaseSize)), whatever the range's length.
    QList<Column> decimate(const SampleStore &store, int channel, qsizetype begin, qsizetype end,
                           int columns) const;
    // The same with columns of equal time between fromMs and toMs (uneven sampling stays
    // honest: a column with no sample is left out). Adds a binary search per column.
    QList<Column> decimateTime(const SampleStore &store, int channel, qint64 fromMs, qint64 toMs,
                               int columns) const;

    // The heap the levels hold.
    qsizetype bytesUsed() const;

private:
    Column column(const SampleStore &store, int channel, qsizetype begin, qsizetype end) const;

    // m_levels[channel][k][i]: min/max of samples [i << (kBaseShift + k), (i + 1) << ...).
    std::array<std::vector<std::vector<MinMax>>, ScopeSample::kChannelCount> m_levels;
    std::array<MinMax, ScopeSample::kChannelCount> m_running{}; // the incomplete base block
    qsizetype m_count = 0;
};

} // namespace DriveDesk
