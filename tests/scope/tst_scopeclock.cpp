#include "scope/ScopeClock.h"

#include <QTest>

using namespace DriveDesk;

using Step = ScopeClock::Step;

// The drive's 16-bit ms timestamp unwrapped: once, many times, across pauses in polling with
// and without the host's clock, and replies that come back out of order.
class TestScopeClock : public QObject
{
    Q_OBJECT

private slots:
    void firstSampleKeepsItsTimestamp()
    {
        ScopeClock clock;
        QVERIFY(!clock.hasStarted());
        QCOMPARE(clock.unwrap(1234), (ScopeClock::Tick{1234, Step::First}));
        QVERIFY(clock.hasStarted());
        QCOMPARE(clock.lastTime(), 1234);
    }

    void unevenStepsForward()
    {
        ScopeClock clock;
        clock.unwrap(100);
        QCOMPARE(clock.unwrap(101), (ScopeClock::Tick{101, Step::Forward}));
        QCOMPARE(clock.unwrap(101), (ScopeClock::Tick{101, Step::Same}));
        QCOMPARE(clock.unwrap(117), (ScopeClock::Tick{117, Step::Forward}));
        QCOMPARE(clock.unwrap(30000), (ScopeClock::Tick{30000, Step::Forward}));
    }

    void wrapsOnce()
    {
        ScopeClock clock;
        clock.unwrap(65530);
        QCOMPARE(clock.unwrap(65535).time, 65535);
        QCOMPARE(clock.unwrap(0), (ScopeClock::Tick{65536, Step::Forward}));
        QCOMPARE(clock.unwrap(3).time, 65539);
        // A wrap between two uneven samples.
        ScopeClock other;
        other.unwrap(65000);
        QCOMPARE(other.unwrap(400), (ScopeClock::Tick{65536 + 400, Step::Forward}));
    }

    void wrapsManyTimes()
    {
        ScopeClock clock;
        qint64 expected = 500;
        clock.unwrap(quint16(expected));
        // Steps of 7..30000 ms, never half a wrap: the time follows exactly through ~45 wraps.
        quint32 seed = 1;
        for (int i = 0; i < 200; ++i) {
            seed = seed * 1103515245u + 12345u;
            expected += 7 + (seed >> 8) % 29994;
            const ScopeClock::Tick tick = clock.unwrap(quint16(expected % 65536));
            QCOMPARE(tick.time, expected);
            QCOMPARE(tick.step, Step::Forward);
        }
        QVERIFY(expected > 40 * ScopeClock::kWrap);
    }

    void gapLongerThanAWrapNeedsTheHostClock()
    {
        // 70 s without a sample: the timestamp moves on by 70000 - 65536 = 4464.
        ScopeClock blind;
        blind.unwrap(1000);
        QCOMPARE(blind.unwrap(quint16((1000 + 70000) % 65536)).time, 1000 + 4464);

        ScopeClock clock;
        clock.unwrap(1000, 5000);
        QCOMPARE(clock.unwrap(quint16((1000 + 70000) % 65536), 5000 + 70000),
                 (ScopeClock::Tick{1000 + 70000, Step::Gap}));
        // The host's clock only picks the wrap count; the drive's timestamp stays exact even if
        // the host is late by a few seconds (its polling, its scheduler).
        QCOMPARE(clock.unwrap(quint16((71000 + 200000) % 65536), 75000 + 203000).time,
                 71000 + 200000);
        // And the clock goes on from there without the host.
        QCOMPARE(clock.unwrap(quint16((271000 + 10) % 65536)).time, 271010);
    }

    void gapOfMoreThanHalfAWrap()
    {
        // 40 s: without the host it reads as a step back; with it, as the pause it was.
        ScopeClock blind;
        blind.unwrap(0);
        QCOMPARE(blind.unwrap(40000), (ScopeClock::Tick{40000 - 65536, Step::Backward}));

        ScopeClock clock;
        clock.unwrap(0, 0);
        QCOMPARE(clock.unwrap(40000, 40100), (ScopeClock::Tick{40000, Step::Gap}));
        // A host time of less than half a wrap leaves the usual rule alone.
        QCOMPARE(clock.unwrap(40050, 40200), (ScopeClock::Tick{40050, Step::Forward}));
    }

    void gapWithExactWrapCount()
    {
        // The same timestamp after exactly three wraps.
        ScopeClock clock;
        clock.unwrap(777, 0);
        QCOMPARE(clock.unwrap(777, 3 * 65536 + 150).time, 777 + 3 * 65536);
    }

    void backwardStepAddsNoWrap()
    {
        ScopeClock clock;
        clock.unwrap(65530);
        clock.unwrap(4); // 65540
        // A reply from before the wrap comes late.
        QCOMPARE(clock.unwrap(65532), (ScopeClock::Tick{65532, Step::Backward}));
        QCOMPARE(clock.lastTime(), 65540);
        // The next fresh one counts from the newest seen, not from the stale one.
        QCOMPARE(clock.unwrap(10), (ScopeClock::Tick{65546, Step::Forward}));
        QCOMPARE(clock.unwrap(9, 0), (ScopeClock::Tick{65545, Step::Backward}));
        QCOMPARE(clock.unwrap(12, 10), (ScopeClock::Tick{65548, Step::Forward}));
    }

    void reset()
    {
        ScopeClock clock;
        clock.unwrap(65000);
        clock.unwrap(100);
        clock.reset();
        QVERIFY(!clock.hasStarted());
        QCOMPARE(clock.unwrap(50), (ScopeClock::Tick{50, Step::First}));
    }
};

QTEST_APPLESS_MAIN(TestScopeClock)
#include "tst_scopeclock.moc"
