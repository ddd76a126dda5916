#pragma once

#include <QtGlobal>

#include <optional>

namespace DriveDesk {

// Unwraps the drive's 16-bit scope timestamp (ms, 65535 wraps to 0) into a continuous 64-bit
// time in ms. The first sample's time is its timestamp; later ones count on from there.
//
// The rule, for the step d = (timestamp - previous timestamp) mod 65536 (docs/scope.md):
// - If the host's clock is known for this and the previous sample and says more than half a
//   wrap (32768 ms) passed, the drive went unread long enough for the timestamp alone to be
//   ambiguous: the time moves on by d + n * 65536 with n >= 0 the wrap count that comes
//   closest to the host's elapsed time. Host and drive may disagree by up to half a wrap.
// - Otherwise a step below half a wrap (d < 32768) moves forward by d (0: the same time again).
// - Otherwise the timestamp went back by 65536 - d (a repeated or reordered reply): it adds no
//   wrap, the sample gets the earlier time and is flagged Backward, and the clock keeps its
//   place so the next sample counts on from the newest one seen. Without the host's clock a
//   pause of more than half a wrap reads the same way; callers that can should pass it.
//
// Single-threaded: one clock per stream of samples, used from one thread.
class ScopeClock
{
public:
    static constexpr qint64 kWrap = 65536;

    enum class Step : quint8 {
        First,    // the first sample since construction or reset()
        Forward,  // moved on by less than half a wrap
        Same,     // the same timestamp as the previous sample
        Backward, // earlier than the previous sample; the clock did not move
        Gap,      // the host's clock decided the number of wraps
    };

    struct Tick
    {
        qint64 time = 0; // ms, continuous
        Step step = Step::First;
        bool operator==(const Tick &) const = default;
    };

    // hostMs: a monotonic host time in ms (QElapsedTimer::elapsed() of one timer) taken when
    // the sample arrived, or nullopt if unknown.
    Tick unwrap(quint16 timestamp, std::optional<qint64> hostMs = std::nullopt);
    void reset();

    bool hasStarted() const { return m_started; }
    // The time of the newest sample that moved the clock.
    qint64 lastTime() const { return m_lastTime; }

private:
    bool m_started = false;
    quint16 m_lastTimestamp = 0;
    qint64 m_lastTime = 0;
    std::optional<qint64> m_lastHostMs;
};

} // namespace DriveDesk
