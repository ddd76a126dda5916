#include "ScopeCursorReadout.h"

#include <algorithm>
#include <cmath>

namespace DriveDesk {

std::optional<double> ScopeCursorReadout::Channel::difference() const
{
    if (!value[0] || !value[1])
        return std::nullopt;
    return *value[1] - *value[0];
}

std::optional<double> ScopeCursorReadout::deltaMs() const
{
    if (!timeMs[0] || !timeMs[1])
        return std::nullopt;
    return *timeMs[1] - *timeMs[0];
}

std::optional<double> ScopeCursorReadout::seconds(int cursor) const
{
    if (!timeMs[cursor])
        return std::nullopt;
    return (*timeMs[cursor] - double(originMs)) / 1000.0;
}

ScopeCursorReadout readScopeCursors(const ScopeRecording &recording,
                                    const std::array<std::optional<double>, 2> &timeMs,
                                    const QList<int> &channels, qsizetype sampleCount)
{
    const SampleStore &samples = recording.buffer.samples();
    sampleCount = std::min(sampleCount, samples.count());

    ScopeCursorReadout readout;
    readout.originMs = recording.firstTime();
    readout.timeMs = timeMs;
    std::array<std::optional<qsizetype>, ScopeCursorReadout::kCursors> index;
    for (int cursor = 0; cursor < ScopeCursorReadout::kCursors; ++cursor) {
        if (!timeMs[cursor])
            continue;
        // Sample times are whole ms: the last sample with time <= the cursor's.
        const qint64 ms = qint64(std::floor(*timeMs[cursor]));
        const qsizetype at = std::min(samples.upperBound(ms), sampleCount) - 1;
        if (at < 0)
            continue;
        index[cursor] = at;
        readout.sampleTimeMs[cursor] = samples.time(at);
    }
    for (const int channel : channels) {
        const ScopeChannel &source = recording.channels.at(channel);
        ScopeCursorReadout::Channel row;
        row.channel = channel;
        row.title = source.title(channel);
        row.unit = source.unit();
        for (int cursor = 0; cursor < ScopeCursorReadout::kCursors; ++cursor) {
            if (!index[cursor])
                continue;
            const qint32 raw = samples.value(*index[cursor], channel);
            row.raw[cursor] = raw;
            row.value[cursor] = source.toDisplay(raw);
        }
        readout.channels.append(row);
    }
    return readout;
}

} // namespace DriveDesk
