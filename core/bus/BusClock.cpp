#include "BusClock.h"

#include "SimulatedBus.h"

#include <limits>

namespace DriveDesk {

BusClock::BusClock(SimulatedBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &BusClock::deliver);
}

void BusClock::receive(const QByteArray &bytes)
{
    m_bus->receive(bytes, nowNs());
    arm();
}

void BusClock::resetLine()
{
    m_timer.stop();
    m_bus->resetLine();
}

void BusClock::arm()
{
    const std::optional<qint64> due = m_bus->nextDueNs();
    if (!due) {
        m_timer.stop();
        return;
    }
    const qint64 waitNs = *due - nowNs();
    // QTimer counts whole milliseconds. Rounding up would hand every reply out up to a
    // millisecond late, a turnaround no drive has; so the whole milliseconds are waited and the
    // rest in zero-time steps. A transmission is still never handed out before its last byte.
    const qint64 waitMs = waitNs <= 0 ? 0 : waitNs / 1'000'000;
    m_timer.start(int(std::min<qint64>(waitMs, std::numeric_limits<int>::max())));
}

void BusClock::deliver()
{
    QList<qsizetype> lineErrors;
    const QByteArray bytes = m_bus->takeDue(nowNs(), &lineErrors);
    // Arm first: a receiver may send the next request from within transmit().
    arm();
    if (!bytes.isEmpty() || !lineErrors.isEmpty())
        emit transmit(bytes, lineErrors);
}

} // namespace DriveDesk
