#pragma once

#include "MinMaxPyramid.h"
#include "SampleStore.h"

namespace DriveDesk {

// The samples of one scope recording and their min/max levels, kept in step: what the chart
// reads. Single-threaded (see SampleStore).
class ScopeBuffer
{
public:
    // False if the sample is earlier than the last one (e.g. a ScopeClock Backward tick):
    // nothing is stored.
    bool append(const ScopeSample &sample);
    // An answer with the time and the values of the last sample is that sample again (polled
    // twice within one of the drive's milliseconds): recorders store it once, and rates count
    // it once.
    bool repeatsLast(const ScopeSample &sample) const;
    void clear();

    const SampleStore &samples() const { return m_samples; }
    const MinMaxPyramid &pyramid() const { return m_pyramid; }
    qsizetype count() const { return m_samples.count(); }

    QList<MinMaxPyramid::Column> decimate(int channel, qsizetype begin, qsizetype end,
                                          int columns) const
    {
        return m_pyramid.decimate(m_samples, channel, begin, end, columns);
    }
    QList<MinMaxPyramid::Column> decimateTime(int channel, qint64 fromMs, qint64 toMs,
                                              int columns) const
    {
        return m_pyramid.decimateTime(m_samples, channel, fromMs, toMs, columns);
    }

    qsizetype bytesUsed() const { return m_samples.bytesUsed() + m_pyramid.bytesUsed(); }

private:
    SampleStore m_samples;
    MinMaxPyramid m_pyramid;
};

} // namespace DriveDesk
