#include "link/SignalNotifier.h"

#include <QSignalSpy>
#include <QTest>

#include <csignal>

using namespace DriveDesk;

namespace {

bool handledByDefault(int signalNumber)
{
    struct sigaction current {};
    ::sigaction(signalNumber, nullptr, &current);
    return current.sa_handler == SIG_DFL;
}

} // namespace

// Ctrl+C and the other signals reach drivedesk-cli and drivedesk-sim through the event loop.
class TestSignalNotifier : public QObject
{
    Q_OBJECT
private slots:
    void deliversEachSignalFromTheEventLoop()
    {
        SignalNotifier notifier;
        QVERIFY(notifier.watch({SIGUSR1, SIGUSR2}));
        QSignalSpy caught(&notifier, &SignalNotifier::caught);
        ::raise(SIGUSR1);
        ::raise(SIGUSR2);
        ::raise(SIGUSR1);
        QCOMPARE(caught.size(), 0); // nothing happens inside the handler
        QTRY_COMPARE(caught.size(), 3);
        QCOMPARE(caught.at(0).at(0).toInt(), SIGUSR1);
        QCOMPARE(caught.at(1).at(0).toInt(), SIGUSR2);
        QCOMPARE(caught.at(2).at(0).toInt(), SIGUSR1);
    }

    void givesTheSignalsBackWhenItGoes()
    {
        {
            SignalNotifier notifier;
            QVERIFY(notifier.watch({SIGUSR1}));
            QVERIFY(!handledByDefault(SIGUSR1));
        }
        QVERIFY(handledByDefault(SIGUSR1));
        // A later one works as the first did.
        SignalNotifier again;
        QVERIFY(again.watch({SIGUSR1}));
        QSignalSpy caught(&again, &SignalNotifier::caught);
        ::raise(SIGUSR1);
        QTRY_COMPARE(caught.size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestSignalNotifier)
#include "tst_signalnotifier.moc"
