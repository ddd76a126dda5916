#pragma once

#include <QElapsedTimer>
#include <QObject>

namespace DriveDesk {

class PreciseAlarm;
class SimulatedBus;

// Runs a SimulatedBus in real time: stamps the operator's bytes with the time on its clock and
// hands each transmission out once its last byte would have arrived. One alarm is armed for the
// earliest due time; the bus keeps the exact schedule in ns, so no rounding adds up.
// Thread: lives in the thread of its owner; the bus is not shared with other threads.
class BusClock : public QObject
{
    Q_OBJECT
public:
    explicit BusClock(SimulatedBus *bus, QObject *parent = nullptr);

    void receive(const QByteArray &bytes);
    // Forgets what is on its way (a new operator on the line).
    void resetLine();
    qint64 nowNs() const { return m_clock.nsecsElapsed(); }

signals:
    // lineErrors: indices into bytes before which the operator's UART flagged a character.
    void transmit(const QByteArray &bytes, const QList<qsizetype> &lineErrors);

private:
    void arm();
    void deliver();

    SimulatedBus *m_bus = nullptr;
    QElapsedTimer m_clock;
    PreciseAlarm *m_alarm = nullptr; // a child
};

} // namespace DriveDesk
