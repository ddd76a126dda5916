#pragma once

#include <QtGlobal>

#include <vector>

namespace DriveDesk {

struct ScopeSeries;

// Min and max of a ScopeSeries' values over blocks of 2^k samples (k >= kBaseShift), as
// MinMaxPyramid keeps them for a recording's channels: a math channel's million values drawn
// into 1600 pixel columns read a few thousand entries instead of every value.
//
// Built once from a finished series (a math channel is computed whole, not extended), in
// O(n) and about a sixteenth of the values' memory; then read-only, so it may be built in the
// thread pool and read in the window's thread. It belongs to the values it was built from.
class ScopeSeriesLevels
{
public:
    static constexpr int kBaseShift = 5;
    static constexpr qsizetype kBaseSize = qsizetype(1) << kBaseShift;

    struct MinMax
    {
        double min = 0;
        double max = 0;
    };

    ScopeSeriesLevels() = default;
    explicit ScopeSeriesLevels(const ScopeSeries &series);

    // The values the levels were built of.
    qsizetype count() const { return m_count; }
    int levelCount() const { return int(m_levels.size()); }

    // Min and max of `values` [begin, end) (not empty; `values` those built from): the
    // largest aligned blocks that fit, raw values for less than kBaseSize at either end.
    // O(levelCount() + kBaseSize).
    MinMax minMax(const std::vector<double> &values, qsizetype begin, qsizetype end) const;

private:
    // m_levels[k][i]: min/max of the values [i << (kBaseShift + k), (i + 1) << ...).
    std::vector<std::vector<MinMax>> m_levels;
    qsizetype m_count = 0;
};

} // namespace DriveDesk
