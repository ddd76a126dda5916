#pragma once

#include "SampleStore.h"
#include "ScopeChannel.h"

namespace DriveDesk {

struct ScopeRecording;

// A recording's samples and channels as they were at one moment, to be read in another thread
// (measurements, math channels, the spectrum) while the recording grows or is replaced: the
// samples are shared with it (SampleStore::share()), so taking one costs a pointer a chunk.
// A value type; read-only once taken.
struct ScopeSnapshot
{
    SampleStore samples;
    ScopeChannels channels;
    qint64 originMs = 0; // the recording's first sample

    double displayValue(qsizetype index, int channel) const
    {
        return channels.at(channel).toDisplay(samples.value(index, channel));
    }
};

// The first `count` samples of `recording` (fewer than it holds while a view is frozen). Call
// it in the recording's thread.
ScopeSnapshot scopeSnapshot(const ScopeRecording &recording, qsizetype count);

} // namespace DriveDesk
