#include "BusClock.h"

#include "SimulatedBus.h"
#include "link/PreciseAlarm.h"

namespace DriveDesk {

namespace {

// A thread woken by a timer runs some tens of microseconds after the time it asked for, more
// on a busy machine. The alarm is set this much early and the rest is waited in passes of the
// event loop, so that a transmission is handed out when its last byte would have arrived, as a
// wire hands it, and never before.
constexpr qint64 kWakeEarlyNs = 150'000;

} // namespace

BusClock::BusClock(SimulatedBus *bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
    , m_alarm(new PreciseAlarm(this))
{
    m_clock.start();
    connect(m_alarm, &PreciseAlarm::timeout, this, &BusClock::deliver);
}

void BusClock::receive(const QByteArray &bytes)
{
    m_bus->receive(bytes, nowNs());
    arm();
}

void BusClock::resetLine()
{
    m_alarm->stop();
    m_bus->resetLine();
}

void BusClock::arm()
{
    const std::optional<qint64> due = m_bus->nextDueNs();
    if (!due) {
        m_alarm->stop();
        return;
    }
    const qint64 waitNs = *due - nowNs();
    m_alarm->start(waitNs > kWakeEarlyNs ? waitNs - kWakeEarlyNs : 0);
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
