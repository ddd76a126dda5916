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

std::unique_ptr<ScopeRecording> ScopeRecording::excerpt(qint64 fromMs, qint64 toMs) const
{
    auto part = std::make_unique<ScopeRecording>();
    part->channels = channels;
    part->source = source;
    part->math = math;
    if (triggerMs && *triggerMs >= fromMs && *triggerMs <= toMs)
        part->triggerMs = triggerMs;
    const SampleStore &samples = buffer.samples();
    const SampleStore::IndexRange range = samples.indexRange(fromMs, toMs);
    for (qsizetype index = range.begin; index < range.end; ++index)
        part->buffer.append(samples.at(index));
    // The host's clock at the first sample kept.
    part->started = started.isValid() && !range.isEmpty()
        ? started.addMSecs(samples.time(range.begin) - firstTime())
        : started;
    return part;
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
