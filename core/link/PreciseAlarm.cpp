#include "PreciseAlarm.h"

#include <QSocketNotifier>
#include <QTimer>

#include <algorithm>
#include <cmath>

#ifdef Q_OS_LINUX
#include <sys/timerfd.h>
#include <unistd.h>
#endif

namespace DriveDesk {

PreciseAlarm::PreciseAlarm(QObject *parent)
    : QObject(parent)
{
#ifdef Q_OS_LINUX
    m_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (m_fd >= 0) {
        m_notifier = new QSocketNotifier(qintptr(m_fd), QSocketNotifier::Read, this);
        connect(m_notifier, &QSocketNotifier::activated, this, &PreciseAlarm::fire);
        return;
    }
#endif
    m_fallback = new QTimer(this);
    m_fallback->setSingleShot(true);
    m_fallback->setTimerType(Qt::PreciseTimer);
    connect(m_fallback, &QTimer::timeout, this, &PreciseAlarm::fire);
}

PreciseAlarm::~PreciseAlarm()
{
    // The notifier goes before its descriptor.
    delete m_notifier;
#ifdef Q_OS_LINUX
    if (m_fd >= 0)
        ::close(m_fd);
#endif
}

void PreciseAlarm::start(qint64 delayNs)
{
    m_active = true;
    if (m_fallback) {
        m_fallback->start(int(std::ceil(double(std::max<qint64>(delayNs, 0)) / 1e6)));
        return;
    }
#ifdef Q_OS_LINUX
    // A zero it_value would disarm the timer: the shortest wait is one nanosecond.
    const qint64 ns = std::max<qint64>(delayNs, 1);
    itimerspec spec{};
    spec.it_value.tv_sec = time_t(ns / 1'000'000'000);
    spec.it_value.tv_nsec = long(ns % 1'000'000'000);
    timerfd_settime(m_fd, 0, &spec, nullptr);
#endif
}

void PreciseAlarm::stop()
{
    m_active = false;
    if (m_fallback) {
        m_fallback->stop();
        return;
    }
#ifdef Q_OS_LINUX
    const itimerspec off{};
    timerfd_settime(m_fd, 0, &off, nullptr);
#endif
}

void PreciseAlarm::fire()
{
#ifdef Q_OS_LINUX
    if (m_fd >= 0) {
        // Empties the expiry count, or the notifier would fire again at once.
        quint64 expirations = 0;
        if (::read(m_fd, &expirations, sizeof expirations) != sizeof expirations)
            return; // stopped or started again after it expired: not due yet
    }
#endif
    if (!m_active)
        return;
    m_active = false;
    emit timeout();
}

} // namespace DriveDesk
