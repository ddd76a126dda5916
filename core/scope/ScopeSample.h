#pragma once

#include <QtGlobal>

#include <array>

namespace DriveDesk {

// One scope sample as the drive sends it (service 18), its time unwrapped: two 32-bit and two
// 16-bit channels of raw integers. Channels 0 and 1 are the wide ones, 2 and 3 the narrow.
struct ScopeSample
{
    static constexpr int kChannelCount = 4;

    qint64 time = 0; // ms, continuous (ScopeClock)
    std::array<qint32, 2> wide{};
    std::array<qint16, 2> narrow{};

    qint32 channel(int channel) const { return channel < 2 ? wide[channel] : narrow[channel - 2]; }
    bool operator==(const ScopeSample &) const = default;
};

} // namespace DriveDesk
