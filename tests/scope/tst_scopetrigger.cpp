#include "scope/ScopeRecording.h"
#include "scope/ScopeTrigger.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace DriveDesk;

namespace {

using Edge = ScopeTriggerSettings::Edge;
using State = ScopeTrigger::State;

// A recording whose channel 0 shows raw / 10 (one decimal), a sample every ms from 1000 on.
ScopeRecording recordingOf(const QList<qint32> &raw)
{
    ScopeRecording recording;
    recording.channels[0].scaling = DisplayScaling({ 0, 10, 1, 0, quint16(1 << 8) });
    for (qsizetype i = 0; i < raw.size(); ++i) {
        ScopeSample sample;
        sample.time = 1000 + i;
        sample.wide[0] = raw[i];
        recording.buffer.append(sample);
    }
    return recording;
}

void append(ScopeRecording &recording, qint64 time, qint32 raw)
{
    ScopeSample sample;
    sample.time = time;
    sample.wide[0] = raw;
    QVERIFY(recording.buffer.append(sample));
}

ScopeTriggerSettings settings(double level, Edge edge, double share = 0.0, qint64 window = 10)
{
    ScopeTriggerSettings made;
    made.level = level;
    made.edge = edge;
    made.preTriggerShare = share;
    made.windowMs = window;
    return made;
}

// A noisy signal with many crossings of 0, for comparing batch sizes.
QList<qint32> wavy(qsizetype count)
{
    QList<qint32> raw;
    for (qsizetype i = 0; i < count; ++i)
        raw << qint32(1000 * std::sin(i * 0.05) + (i * 7919 % 301) - 150);
    return raw;
}

struct Outcome
{
    State state;
    qsizetype index;
    qint64 start;
    qint64 end;
    bool operator==(const Outcome &) const = default;
};

} // namespace

// The single-shot trigger: the exact sample that fires, the pre-trigger time, the shot's range
// and its end, and the same result however the samples are fed.
class TestScopeTrigger : public QObject
{
    Q_OBJECT

private slots:
    void risingFiresAtTheFirstSampleAtOrAboveTheLevel()
    {
        const ScopeRecording recording = recordingOf({ 0, 10, 20, 30, 40, 0, 50 });
        ScopeTrigger trigger(settings(2.5, Edge::Rising));
        QCOMPARE(trigger.state(), State::Idle);
        trigger.arm(0);
        QCOMPARE(trigger.update(recording), State::Triggered);
        QCOMPARE(trigger.triggerIndex(), 3);
        QCOMPARE(trigger.triggerTime(), 1003);

        trigger.setSettings(settings(2.0, Edge::Rising)); // reaching the level is enough
        trigger.arm(0);
        trigger.update(recording);
        QCOMPARE(trigger.triggerIndex(), 2);
    }

    void fallingFiresAtTheFirstSampleAtOrBelowTheLevel()
    {
        const ScopeRecording recording = recordingOf({ 50, 40, 30, 20, 10, 60, 0 });
        ScopeTrigger trigger(settings(2.5, Edge::Falling));
        trigger.arm(0);
        QCOMPARE(trigger.update(recording), State::Triggered);
        QCOMPARE(trigger.triggerIndex(), 3);
        trigger.setSettings(settings(3.0, Edge::Falling));
        trigger.arm(0);
        trigger.update(recording);
        QCOMPARE(trigger.triggerIndex(), 2);
    }

    void levelTouchedFromTheWrongSideDoesNotFire()
    {
        // rising: down to the level and back up is no rising edge
        ScopeTrigger rising(settings(2.0, Edge::Rising));
        rising.arm(0);
        QCOMPARE(rising.update(recordingOf({ 30, 20, 30, 20, 20, 30 })), State::Armed);
        QCOMPARE(rising.update(recordingOf({ 30, 20, 30, 20, 20, 30, 10, 20 })), State::Triggered);
        QCOMPARE(rising.triggerIndex(), 7);
        // falling: up to the level and back down is no falling edge
        ScopeTrigger falling(settings(2.0, Edge::Falling));
        falling.arm(0);
        QCOMPARE(falling.update(recordingOf({ 10, 20, 10, 20, 20, 10 })), State::Armed);
        // a level between samples in display units: 1.5 lies between raw 10 and 20
        falling.setSettings(settings(1.5, Edge::Falling));
        falling.arm(0);
        falling.update(recordingOf({ 10, 20, 10 }));
        QCOMPARE(falling.triggerIndex(), 2);
    }

    void theSampleBeforeMustBeWatched()
    {
        // armed at 3: the step from index 2 to 3 happened before arming
        const ScopeRecording recording = recordingOf({ 0, 0, 0, 50, 50, 0, 50 });
        ScopeTrigger trigger(settings(2.5, Edge::Rising));
        trigger.arm(3);
        QCOMPARE(trigger.update(recording), State::Triggered);
        QCOMPARE(trigger.triggerIndex(), 6);
        // armed beyond the samples there are: waits for them
        trigger.arm(7);
        QCOMPARE(trigger.update(recording), State::Armed);
    }

    void notBeforeThePreTriggerTimeIsRecorded()
    {
        // window 100 ms, 30 % before: armed at 1000, nothing fires before 1030
        ScopeRecording recording;
        ScopeTrigger trigger(settings(2.5, Edge::Rising, 0.3, 100));
        QCOMPARE(trigger.settings().preTriggerMs(), 30);
        trigger.arm(0);
        append(recording, 1000, 0);
        append(recording, 1010, 50); // crossing too early
        append(recording, 1020, 0);
        append(recording, 1029, 50); // still too early
        append(recording, 1029, 0);
        QCOMPARE(trigger.update(recording), State::Armed);
        append(recording, 1030, 50); // exactly when the pre-trigger time is full
        QCOMPARE(trigger.update(recording), State::Triggered);
        QCOMPARE(trigger.triggerIndex(), 5);
        QCOMPARE(trigger.shotStart(), 1000);
        QCOMPARE(trigger.shotEnd(), 1100);
    }

    void preTriggerSharePlacesTheTriggerInTheShot_data()
    {
        QTest::addColumn<double>("share");
        QTest::addColumn<qint64>("start");
        QTest::addColumn<qint64>("end");
        // trigger at 1500, window 200 ms
        QTest::newRow("none before") << 0.0 << qint64(1500) << qint64(1700);
        QTest::newRow("a quarter") << 0.25 << qint64(1450) << qint64(1650);
        QTest::newRow("half") << 0.5 << qint64(1400) << qint64(1600);
        QTest::newRow("all before") << 1.0 << qint64(1300) << qint64(1500);
        QTest::newRow("rounded to ms") << 0.3333 << qint64(1433) << qint64(1633);
        QTest::newRow("beyond 1") << 1.5 << qint64(1300) << qint64(1500);
    }

    void preTriggerSharePlacesTheTriggerInTheShot()
    {
        QFETCH(double, share);
        QFETCH(qint64, start);
        QFETCH(qint64, end);
        QList<qint32> raw(1000, 0);
        raw[500] = 50;
        const ScopeRecording recording = recordingOf(raw);
        ScopeTrigger trigger(settings(2.5, Edge::Rising, share, 200));
        trigger.arm(0);
        QCOMPARE(trigger.update(recording), State::Complete);
        QCOMPARE(trigger.triggerTime(), 1500);
        QCOMPARE(trigger.shotStart(), start);
        QCOMPARE(trigger.shotEnd(), end);
        QCOMPARE(trigger.shotEnd() - trigger.shotStart(), 200);
    }

    void completeOnlyWhenTheShotEndIsRecorded()
    {
        ScopeRecording recording;
        ScopeTrigger trigger(settings(2.5, Edge::Rising, 0.2, 50)); // 10 ms before, 40 after
        trigger.arm(0);
        QCOMPARE(trigger.update(recording), State::Armed); // no samples yet
        append(recording, 0, 0);
        append(recording, 15, 50);
        QCOMPARE(trigger.update(recording), State::Triggered);
        QCOMPARE(trigger.shotEnd(), 55);
        append(recording, 40, 0);
        append(recording, 54, 50);
        QCOMPARE(trigger.update(recording), State::Triggered);
        append(recording, 55, 0);
        QCOMPARE(trigger.update(recording), State::Complete);
        // single shot: later edges change nothing
        append(recording, 56, 50);
        QCOMPARE(trigger.update(recording), State::Complete);
        QCOMPARE(trigger.triggerIndex(), 1);
        // a sample beyond the end completes it as well
        trigger.arm(0);
        ScopeRecording sparse = recordingOf({ 0, 50 });
        QCOMPARE(trigger.update(sparse), State::Armed); // 1001 is before the 10 ms
        append(sparse, 1010, 0);
        append(sparse, 1011, 50);
        append(sparse, 1200, 0);
        QCOMPARE(trigger.update(sparse), State::Complete);
        QCOMPARE(trigger.triggerTime(), 1011);
    }

    void batchesGiveTheSameResultAsOne_data()
    {
        QTest::addColumn<int>("batch");
        for (int batch : { 1, 2, 7, 64, 999 })
            QTest::newRow(qPrintable(QString::number(batch))) << batch;
    }

    void batchesGiveTheSameResultAsOne()
    {
        QFETCH(int, batch);
        const QList<qint32> raw = wavy(3000);
        for (Edge edge : { Edge::Rising, Edge::Falling }) {
            for (qsizetype armedAt : { 0, 1, 333 }) {
                const ScopeTriggerSettings chosen = settings(12.5, edge, 0.4, 400);
                ScopeTrigger whole(chosen);
                whole.arm(armedAt);
                whole.update(recordingOf(raw));

                ScopeTrigger fed(chosen);
                fed.arm(armedAt);
                ScopeRecording growing = recordingOf({});
                QList<State> states;
                for (qsizetype i = 0; i < raw.size(); ++i) {
                    append(growing, 1000 + i, raw[i]);
                    if ((i + 1) % batch == 0 || i + 1 == raw.size())
                        states << fed.update(growing);
                }
                QCOMPARE(whole.state(), State::Complete);
                const Outcome expected { whole.state(), whole.triggerIndex(), whole.shotStart(),
                                         whole.shotEnd() };
                const Outcome got { fed.state(), fed.triggerIndex(), fed.shotStart(),
                                    fed.shotEnd() };
                QVERIFY(got == expected);
                QVERIFY(whole.triggerIndex() > armedAt);
                QVERIFY(std::is_sorted(states.begin(), states.end()));
            }
        }
    }

    void settingsAreBroughtIntoRangeAndDisarm()
    {
        ScopeTriggerSettings wild = settings(1.0, Edge::Rising, -0.5, -10);
        wild.channel = 7;
        ScopeTrigger trigger(wild);
        QCOMPARE(trigger.settings().channel, 3);
        QCOMPARE(trigger.settings().preTriggerShare, 0.0);
        QCOMPARE(trigger.settings().windowMs, 1);
        trigger.arm(0);
        trigger.setSettings(settings(1.0, Edge::Rising));
        QCOMPARE(trigger.state(), State::Idle);
        QCOMPARE(trigger.update(recordingOf({ 0, 50 })), State::Idle);
        trigger.arm(0);
        QCOMPARE(trigger.update(recordingOf({ 0, 50 })), State::Triggered); // until 1011
        trigger.disarm();
        QCOMPARE(trigger.state(), State::Idle);
    }
};

QTEST_GUILESS_MAIN(TestScopeTrigger)
#include "tst_scopetrigger.moc"
