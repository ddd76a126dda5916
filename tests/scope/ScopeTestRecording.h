#pragma once

#include "scope/ScopeRecording.h"

namespace DriveDesk::ScopeTest {

constexpr quint16 kHz = 18;
constexpr quint16 kVolt = 21;
constexpr quint16 kAmpere = 29;

// A channel as the scan describes one: `divisor` raw counts a unit, shown with up to four
// decimals.
inline ScopeChannel scaledChannel(quint16 address, const QString &id, const QString &name,
                                  qint16 divisor, quint16 unit)
{
    ScopeChannel channel;
    channel.source = address;
    channel.id = id;
    channel.name = name;
    channel.scaling
        = DisplayScaling(DisplayScalingData { address, divisor, 1, 0, quint16(unit | (5 << 8)) });
    return channel;
}

inline bool append(ScopeRecording &recording, qint64 timeMs, qint32 wide0, qint32 wide1 = 0,
                   qint16 narrow0 = 0, qint16 narrow1 = 0)
{
    ScopeSample sample;
    sample.time = timeMs;
    sample.wide = { wide0, wide1 };
    sample.narrow = { narrow0, narrow1 };
    return recording.buffer.append(sample);
}

} // namespace DriveDesk::ScopeTest
