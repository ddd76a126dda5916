#pragma once

#include "scope/ScopeRecording.h"

#include <QList>
#include <QString>

#include <array>
#include <optional>

namespace DriveDesk {

// What the chart's two cursors read: their times, the time between them, and each drawn
// channel's value at both. A value is that of the sample at or before the cursor's time (the
// one the drive had sent by then); none where the cursor is off or before the first sample.
// A plain value, for a table in the chart or a dock.
struct ScopeCursorReadout
{
    static constexpr int kCursors = 2;

    struct Channel
    {
        int channel = 0; // 0..3
        QString title; // ScopeChannel::title()
        QString unit;
        std::array<std::optional<qint32>, kCursors> raw; // as the drive sent it
        std::array<std::optional<double>, kCursors> value; // ScopeChannel::toDisplay(raw)

        // value[1] - value[0], where both are known.
        std::optional<double> difference() const;
        bool operator==(const Channel &) const = default;
    };

    qint64 originMs = 0; // the recording's first sample: the chart's time 0
    std::array<std::optional<double>, kCursors> timeMs; // the cursors, recording ms
    std::array<std::optional<qint64>, kCursors> sampleTimeMs; // the samples read at them
    QList<Channel> channels; // the drawn channels, in channel order

    // timeMs[1] - timeMs[0], where both cursors are placed.
    std::optional<double> deltaMs() const;
    // A cursor's time in seconds on the chart's axis (from the first sample).
    std::optional<double> seconds(int cursor) const;
    bool hasCursor() const { return timeMs[0] || timeMs[1]; }
    bool operator==(const ScopeCursorReadout &) const = default;
};

// Reads `channels` of `recording` at the cursor times, looking only at its first
// `sampleCount` samples (fewer than it holds while the chart's view is frozen).
ScopeCursorReadout readScopeCursors(const ScopeRecording &recording,
                                    const std::array<std::optional<double>, 2> &timeMs,
                                    const QList<int> &channels, qsizetype sampleCount);

} // namespace DriveDesk
