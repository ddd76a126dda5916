#include "ScopeRecording.h"

namespace DriveDesk {

ScopeRecording::ScopeRecording()
    : channels(ScopeSample::kChannelCount)
{
}

qint64 ScopeRecording::firstTime() const
{
    return buffer.count() == 0 ? 0 : buffer.samples().time(0);
}

qint64 ScopeRecording::lastTime() const
{
    return buffer.count() == 0 ? 0 : buffer.samples().time(buffer.count() - 1);
}

QList<int> ScopeRecording::recordedChannels() const
{
    QList<int> recorded;
    for (int channel = 0; channel < channels.size(); ++channel) {
        if (channels.at(channel).enabled)
            recorded << channel;
    }
    if (recorded.isEmpty()) {
        for (int channel = 0; channel < channels.size(); ++channel)
            recorded << channel;
    }
    return recorded;
}

} // namespace DriveDesk
