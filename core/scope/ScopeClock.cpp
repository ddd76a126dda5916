#include "ScopeClock.h"

namespace DriveDesk {

namespace {

constexpr qint64 kHalfWrap = ScopeClock::kWrap / 2;

// The count of whole wraps n >= 0 for which step + n * wrap is nearest to hostElapsed.
qint64 nearestWrapCount(qint64 step, qint64 hostElapsed)
{
    const qint64 n = (hostElapsed - step + kHalfWrap) / ScopeClock::kWrap;
    return n > 0 ? n : 0;
}

} // namespace

ScopeClock::Tick ScopeClock::unwrap(quint16 timestamp, std::optional<qint64> hostMs)
{
    if (!m_started) {
        m_started = true;
        m_lastTimestamp = timestamp;
        m_lastTime = timestamp;
        m_lastHostMs = hostMs;
        return {m_lastTime, Step::First};
    }

    const qint64 step = (qint64(timestamp) - m_lastTimestamp + kWrap) % kWrap;
    Tick tick;
    if (hostMs && m_lastHostMs && *hostMs - *m_lastHostMs > kHalfWrap) {
        tick = {m_lastTime + step + nearestWrapCount(step, *hostMs - *m_lastHostMs) * kWrap,
                Step::Gap};
    } else if (step < kHalfWrap) {
        tick = {m_lastTime + step, step == 0 ? Step::Same : Step::Forward};
    } else {
        // A stale reply must not drag the clock back: the next fresh one counts from the newest.
        return {m_lastTime - (kWrap - step), Step::Backward};
    }

    m_lastTimestamp = timestamp;
    m_lastTime = tick.time;
    m_lastHostMs = hostMs;
    return tick;
}

void ScopeClock::reset()
{
    *this = ScopeClock();
}

} // namespace DriveDesk
