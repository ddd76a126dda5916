#pragma once

#include <QObject>

class QSocketNotifier;
class QTimer;

namespace DriveDesk {

// A single-shot timer that keeps a fraction of a millisecond. QTimer counts whole milliseconds
// (and poll() rounds its wait up to the next one), which is as long as a drive's clock tick:
// a job that spaces its requests by that tick needs the rest too. On Linux a timerfd waited on
// by the event loop; elsewhere a QTimer rounded up to whole milliseconds (never early).
// Thread: lives in one thread (moveToThread() takes its parts along), whose event loop delivers
// timeout().
class PreciseAlarm : public QObject
{
    Q_OBJECT
public:
    explicit PreciseAlarm(QObject *parent = nullptr);
    ~PreciseAlarm() override;

    // Fires once after delayNs (at once for 0 or less); starting again replaces the time.
    void start(qint64 delayNs);
    void stop();
    bool isActive() const { return m_active; }

signals:
    void timeout();

private:
    void fire();

    int m_fd = -1;
    QSocketNotifier *m_notifier = nullptr; // children
    QTimer *m_fallback = nullptr;          // without a timerfd
    bool m_active = false;
};

} // namespace DriveDesk
