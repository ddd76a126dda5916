#include "link/PreciseAlarm.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

#include <atomic>

using namespace DriveDesk;

namespace {

constexpr int kWaitMs = 5000;

} // namespace

// PreciseAlarm: once, never before its time, replaced by a new start, silenced by stop, in the
// thread it was moved to. A busy machine may make it late; nothing here asks how late.
class TestPreciseAlarm : public QObject
{
    Q_OBJECT
private slots:
    void firesOnceAndNeverEarly_data()
    {
        QTest::addColumn<qint64>("delayNs");
        QTest::newRow("a fraction of a millisecond") << qint64(300'000);
        QTest::newRow("one and a half milliseconds") << qint64(1'500'000);
        QTest::newRow("twenty milliseconds") << qint64(20'000'000);
        QTest::newRow("due already") << qint64(-5);
    }

    void firesOnceAndNeverEarly()
    {
        QFETCH(qint64, delayNs);
        PreciseAlarm alarm;
        QSignalSpy fired(&alarm, &PreciseAlarm::timeout);
        QElapsedTimer clock;
        qint64 firedAtNs = -1;
        connect(&alarm, &PreciseAlarm::timeout, this, [&] { firedAtNs = clock.nsecsElapsed(); });
        clock.start();
        alarm.start(delayNs);
        QVERIFY(alarm.isActive());
        QVERIFY(fired.wait(kWaitMs));
        QVERIFY2(firedAtNs >= delayNs, qPrintable(QStringLiteral("fired after %1 ns of %2")
                                                      .arg(firedAtNs).arg(delayNs)));
        QVERIFY(!alarm.isActive());
        QTest::qWait(30);
        QCOMPARE(fired.count(), 1);
    }

    void aNewStartReplacesTheTime()
    {
        PreciseAlarm alarm;
        QSignalSpy fired(&alarm, &PreciseAlarm::timeout);
        QElapsedTimer clock;
        clock.start();
        alarm.start(10'000'000'000); // ten seconds
        alarm.start(2'000'000);
        QVERIFY(fired.wait(kWaitMs));
        QVERIFY(clock.nsecsElapsed() >= 2'000'000);
        QVERIFY(clock.elapsed() < 10'000);
        alarm.start(50'000'000);
        alarm.start(5'000'000'000); // later again: the earlier time is gone
        QTest::qWait(150);
        QCOMPARE(fired.count(), 1);
    }

    void stopSilencesIt()
    {
        PreciseAlarm alarm;
        QSignalSpy fired(&alarm, &PreciseAlarm::timeout);
        alarm.start(1'000'000);
        alarm.stop();
        QVERIFY(!alarm.isActive());
        QTest::qWait(50);
        QCOMPARE(fired.count(), 0);
        // Stopped after its time passed but before the event loop saw it: silent all the same.
        alarm.start(1);
        QThread::usleep(2000);
        alarm.stop();
        QTest::qWait(50);
        QCOMPARE(fired.count(), 0);
    }

    void firesInTheThreadItWasMovedTo()
    {
        QThread thread;
        thread.start();
        auto *alarm = new PreciseAlarm;
        alarm->moveToThread(&thread);
        std::atomic<QThread *> firedIn = nullptr;
        connect(alarm, &PreciseAlarm::timeout, alarm,
                [&firedIn] { firedIn = QThread::currentThread(); });
        QMetaObject::invokeMethod(alarm, [alarm] { alarm->start(1'000'000); });
        QVERIFY(QTest::qWaitFor([&firedIn] { return firedIn.load() != nullptr; }, kWaitMs));
        QCOMPARE(firedIn.load(), &thread);
        QMetaObject::invokeMethod(alarm, &QObject::deleteLater);
        thread.quit();
        QVERIFY(thread.wait(kWaitMs));
    }
};

QTEST_GUILESS_MAIN(TestPreciseAlarm)
#include "tst_precisealarm.moc"
