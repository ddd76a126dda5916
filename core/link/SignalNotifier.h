#pragma once

#include <QList>
#include <QObject>

#include <initializer_list>

class QSocketNotifier;

namespace DriveDesk {

// Unix signals (Ctrl+C, SIGTERM, SIGUSR1) delivered in the event loop, for the command-line
// programs. The handler only writes the signal's number to a socket pair, which is all a
// signal handler may safely do; caught() follows from the event loop.
// One per process; the signals it catches get their default handling back when it goes.
class SignalNotifier : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    ~SignalNotifier() override;

    // Catches these signals from now on. False when the socket pair cannot be made; then
    // nothing is caught.
    bool watch(std::initializer_list<int> signalNumbers);

signals:
    void caught(int signalNumber);

private:
    QSocketNotifier *m_notifier = nullptr;
    QList<int> m_signals;
};

} // namespace DriveDesk
