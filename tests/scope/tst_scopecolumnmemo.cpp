#include "scope/ScopeColumnMemo.h"

#include "ScopeTestRecording.h"

#include <QRandomGenerator>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ScopeTest;

namespace {

// Samples from `from` on, a ms apart with now and then a gap of a few ms (a slow line), the
// values random.
void appendSamples(ScopeRecording &recording, qint64 &timeMs, int count,
                   QRandomGenerator &random)
{
    for (int i = 0; i < count; ++i) {
        timeMs += random.bounded(20) == 0 ? 1 + random.bounded(5) : 1;
        append(recording, timeMs, qint32(random.generate()), qint32(random.bounded(1000)),
               qint16(random.bounded(-300, 300)), qint16(random.bounded(2)));
    }
}

// Every column of every channel of `grid` through the memo, each checked against the pyramid;
// then kept.
void readThrough(ScopeColumnMemo &memo, const ScopeColumnGrid &grid,
                 const ScopeRecording &recording)
{
    const MinMaxPyramid &pyramid = recording.buffer.pyramid();
    for (int channel = 0; channel < ScopeSample::kChannelCount; ++channel) {
        for (int column = 0; column < grid.count(); ++column) {
            if (grid.isEmpty(column))
                continue;
            QCOMPARE(memo.column(grid, pyramid, channel, column),
                     grid.column(pyramid, channel, column));
        }
    }
}

} // namespace

// The columns of a rolling view kept from one redraw to the next (ScopeChart's roll tick): the
// same min and max as read from the pyramid, whatever the view does.
class TestScopeColumnMemo : public QObject
{
    Q_OBJECT
private slots:
    void aRollingViewTakesOverAllButItsNewestColumns()
    {
        QRandomGenerator random(21);
        ScopeRecording recording;
        qint64 time = 1000;
        appendSamples(recording, time, 20000, random);
        ScopeColumnMemo memo;
        constexpr qint64 kViewMs = 10000;
        constexpr int kColumns = 1000;
        for (int tick = 0; tick < 30; ++tick) {
            appendSamples(recording, time, 133, random);
            const SampleStore &samples = recording.buffer.samples();
            const ScopeColumnGrid grid(samples, time - kViewMs, time, kColumns, samples.count());
            readThrough(memo, grid, recording);
            if (QTest::currentTestFailed())
                return;
            if (tick > 0) {
                // About 13 new columns a tick (133 ms in 10 ms columns) and the last one of
                // the tick before, which grew: the rest, four channels each, from the memo.
                const int drawn = grid.count() * ScopeSample::kChannelCount;
                QVERIFY2(memo.takenOver() > drawn * 9 / 10,
                         qPrintable(QStringLiteral("%1 of %2").arg(memo.takenOver()).arg(drawn)));
            }
            memo.keep(grid);
        }
    }

    void aViewThatJumpsOrZoomsReadsAfresh()
    {
        QRandomGenerator random(3);
        ScopeRecording recording;
        qint64 time = 0;
        appendSamples(recording, time, 50000, random);
        const SampleStore &samples = recording.buffer.samples();
        ScopeColumnMemo memo;
        const ScopeColumnGrid first(samples, 10000, 20000, 1000, samples.count());
        readThrough(memo, first, recording);
        memo.keep(first);
        // Zoomed: columns of another width, none taken over.
        const ScopeColumnGrid zoomed(samples, 12000, 17000, 1000, samples.count());
        readThrough(memo, zoomed, recording);
        QCOMPARE(memo.takenOver(), 0);
        memo.keep(zoomed);
        // Panned by half a column's time: the grid stays on multiples of its width, so the
        // columns are the same ones, shifted.
        const ScopeColumnGrid panned(samples, 12002, 17002, 1000, samples.count());
        readThrough(memo, panned, recording);
        QVERIFY(memo.takenOver() > 0);
        memo.keep(panned);
        // Fewer samples shown (a view frozen earlier): the last columns differ and are read.
        const ScopeColumnGrid frozen(samples, 12002, 17002, 1000, samples.count() - 2000);
        readThrough(memo, frozen, recording);
    }

    void aRecordingBegunAgainIsReadAfreshOnceCleared()
    {
        QRandomGenerator random(8);
        ScopeRecording recording;
        qint64 time = 0;
        appendSamples(recording, time, 5000, random);
        QList<qint64> times;
        for (qsizetype i = 0; i < recording.buffer.count(); ++i)
            times << recording.buffer.samples().time(i);
        ScopeColumnMemo memo;
        const ScopeColumnGrid before(recording.buffer.samples(), 0, time, 500,
                                     recording.buffer.count());
        readThrough(memo, before, recording);
        memo.keep(before);
        // The same times again, other values: what the chart tells the memo to forget.
        recording.buffer.clear();
        for (const qint64 at : times)
            append(recording, at, -qint32(random.bounded(1000)));
        memo.clear();
        const ScopeColumnGrid after(recording.buffer.samples(), 0, time, 500,
                                    recording.buffer.count());
        readThrough(memo, after, recording);
        QCOMPARE(memo.takenOver(), 0);
    }
};

QTEST_GUILESS_MAIN(TestScopeColumnMemo)
#include "tst_scopecolumnmemo.moc"
