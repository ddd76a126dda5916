#include "scope/ScopeBuffer.h"
#include "scope/ScopeSeries.h"
#include "scope/ScopeSeriesLevels.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>

using namespace DriveDesk;

namespace {

using Column = MinMaxPyramid::Column;

// Random walks with rare spikes, so that the extremes are single samples somewhere inside.
void fillRandom(ScopeBuffer &buffer, qsizetype count, quint32 seed)
{
    QRandomGenerator random(seed);
    ScopeSample sample;
    if (buffer.count() > 0)
        sample.time = buffer.samples().time(buffer.count() - 1);
    for (qsizetype i = 0; i < count; ++i) {
        sample.time += random.bounded(0, 4);
        sample.wide[0] = qint32(random.generate());
        sample.wide[1] += random.bounded(-1000, 1001);
        sample.narrow[0] = qint16(random.bounded(-30000, 30001));
        sample.narrow[1] = random.bounded(1000) == 0 ? qint16(random.bounded(2) ? 32767 : -32768)
                                                     : qint16(random.bounded(-10, 11));
        QVERIFY(buffer.append(sample));
    }
}

MinMaxPyramid::MinMax bruteForce(const SampleStore &store, int channel, qsizetype begin,
                                 qsizetype end)
{
    MinMaxPyramid::MinMax result{store.value(begin, channel), store.value(begin, channel)};
    for (qsizetype i = begin; i < end; ++i) {
        result.min = std::min(result.min, store.value(i, channel));
        result.max = std::max(result.max, store.value(i, channel));
    }
    return result;
}

// Every column against a scan of exactly its samples; the columns tile the range.
bool checkColumns(const SampleStore &store, int channel, qsizetype begin, qsizetype end,
                  const QList<Column> &columns)
{
    qsizetype next = begin;
    for (const Column &column : columns) {
        if (column.begin != next || column.end <= column.begin)
            return false;
        const MinMaxPyramid::MinMax expected = bruteForce(store, channel, column.begin,
                                                          column.end);
        if (column.min != expected.min || column.max != expected.max
            || column.firstTime != store.time(column.begin)
            || column.lastTime != store.time(column.end - 1))
            return false;
        next = column.end;
    }
    return next == end;
}

} // namespace

// Min/max levels: decimation keeps every column's extremes exact at any zoom.
class TestMinMaxPyramid : public QObject
{
    Q_OBJECT

private slots:
    void levelsGrowWithTheSamples()
    {
        ScopeBuffer buffer;
        fillRandom(buffer, MinMaxPyramid::kBaseSize - 1, 1);
        QCOMPARE(buffer.pyramid().levelCount(), 0);
        fillRandom(buffer, 1, 2);
        QCOMPARE(buffer.pyramid().levelCount(), 1);
        buffer.clear();
        fillRandom(buffer, MinMaxPyramid::kBaseSize * 1024, 3);
        QCOMPARE(buffer.pyramid().levelCount(), 11);
        QCOMPARE(buffer.pyramid().count(), buffer.count());
    }

    void columnsMatchBruteForce()
    {
        ScopeBuffer buffer;
        const qsizetype count = 70'000;
        fillRandom(buffer, count, 42);
        const SampleStore &store = buffer.samples();
        QRandomGenerator random(7);
        for (int round = 0; round < 400; ++round) {
            const qsizetype a = random.bounded(qint64(count));
            const qsizetype b = random.bounded(qint64(count)) + 1;
            const qsizetype begin = std::min(a, b - 1);
            const qsizetype end = std::max(a + 1, b);
            const int columns = round % 5 == 0 ? random.bounded(1, 4)
                                               : random.bounded(1, 2000);
            const int channel = round % ScopeSample::kChannelCount;
            const QList<Column> result = buffer.decimate(channel, begin, end, columns);
            QCOMPARE(result.size(), std::min<qsizetype>(columns, end - begin));
            QVERIFY2(checkColumns(store, channel, begin, end, result),
                     qPrintable(QStringLiteral("channel %1, [%2, %3), %4 columns")
                                    .arg(channel).arg(begin).arg(end).arg(columns)));
        }
    }

    void rangeExtremesSurviveEveryZoom()
    {
        ScopeBuffer buffer;
        const qsizetype count = 50'000;
        fillRandom(buffer, count, 99);
        const SampleStore &store = buffer.samples();
        for (int channel = 0; channel < ScopeSample::kChannelCount; ++channel) {
            for (const auto &[begin, end] : {std::pair<qsizetype, qsizetype>{0, count},
                                             {1, count - 1}, {31, 33}, {12345, 40001},
                                             {count - 100, count}}) {
                const MinMaxPyramid::MinMax expected = bruteForce(store, channel, begin, end);
                for (int columns : {1, 2, 3, 7, 100, 1600, 4096}) {
                    const QList<Column> result = buffer.decimate(channel, begin, end, columns);
                    qint32 min = result.first().min;
                    qint32 max = result.first().max;
                    for (const Column &column : result) {
                        min = std::min(min, column.min);
                        max = std::max(max, column.max);
                    }
                    QCOMPARE(min, expected.min);
                    QCOMPARE(max, expected.max);
                }
            }
        }
    }

    void everyShortRange()
    {
        // All ranges of a few base blocks: every alignment of both ends.
        ScopeBuffer buffer;
        const qsizetype count = 5 * MinMaxPyramid::kBaseSize + 3;
        fillRandom(buffer, count, 5);
        for (qsizetype begin = 0; begin < count; ++begin) {
            for (qsizetype end = begin + 1; end <= count; ++end) {
                const MinMaxPyramid::MinMax got = buffer.pyramid().minMax(buffer.samples(), 0,
                                                                           begin, end);
                QCOMPARE(got, bruteForce(buffer.samples(), 0, begin, end));
            }
        }
    }

    void fewerSamplesThanColumns()
    {
        ScopeBuffer buffer;
        fillRandom(buffer, 10, 11);
        const QList<Column> result = buffer.decimate(3, 2, 7, 1600);
        QCOMPARE(result.size(), 5);
        QVERIFY(checkColumns(buffer.samples(), 3, 2, 7, result));
        QVERIFY(buffer.decimate(3, 4, 4, 1600).isEmpty());
        QVERIFY(buffer.decimate(3, 0, 10, 0).isEmpty());
    }

    void columnsOfEqualTime()
    {
        ScopeBuffer buffer;
        fillRandom(buffer, 20'000, 13);
        const SampleStore &store = buffer.samples();
        const qint64 first = store.time(0);
        const qint64 last = store.time(store.count() - 1);
        for (const auto &[from, to] : {std::pair<qint64, qint64>{first, last},
                                       {first + 100, last - 777}, {first - 50, first + 10},
                                       {last - 3, last + 1000}}) {
            for (int columns : {1, 13, 800, 1600}) {
                const QList<Column> result = buffer.decimateTime(2, from, to, columns);
                const SampleStore::IndexRange range = store.indexRange(from, to);
                QVERIFY(result.size() <= columns);
                QVERIFY(checkColumns(store, 2, range.begin, range.end, result));
                for (const Column &column : result) {
                    QVERIFY(column.firstTime >= from);
                    QVERIFY(column.lastTime <= to);
                }
            }
        }
    }

    void clearStartsOver()
    {
        ScopeBuffer buffer;
        fillRandom(buffer, 1000, 17);
        buffer.clear();
        QCOMPARE(buffer.pyramid().count(), 0);
        QCOMPARE(buffer.pyramid().levelCount(), 0);
        fillRandom(buffer, 100, 19);
        QVERIFY(checkColumns(buffer.samples(), 1, 0, 100, buffer.decimate(1, 0, 100, 7)));
    }

    void bufferRefusesAnEarlierSample()
    {
        ScopeBuffer buffer;
        QVERIFY(buffer.append(ScopeSample{10, {5, 5}, {5, 5}}));
        QVERIFY(!buffer.append(ScopeSample{9, {100, 100}, {100, 100}}));
        QCOMPARE(buffer.pyramid().count(), 1);
    }

    void wholeBufferWithin24BytesASample()
    {
        ScopeBuffer buffer;
        ScopeSample sample;
        for (qsizetype i = 0; i < 1'000'000; ++i) {
            sample.time = i;
            sample.wide[0] = qint32(i);
            buffer.append(sample);
        }
        const double perSample = double(buffer.bytesUsed()) / buffer.count();
        qInfo("samples and levels: %.2f bytes a sample", perSample);
        QVERIFY(perSample <= 24.0);
    }

    // A math channel's levels (doubles of a ScopeSeries): every range of a few blocks, and
    // long ranges of a long trace at random, as a scan of the values finds them.
    void seriesLevelsMatchBruteForce()
    {
        QRandomGenerator random(23);
        for (const qsizetype count : { qsizetype(0), qsizetype(1), qsizetype(31), qsizetype(32),
                                       qsizetype(33), 5 * ScopeSeriesLevels::kBaseSize + 3,
                                       qsizetype(100000) }) {
            ScopeSeries series;
            for (qsizetype i = 0; i < count; ++i) {
                series.timeMs.push_back(double(i));
                series.values.push_back(random.generateDouble() * 2e6 - 1e6);
            }
            const ScopeSeriesLevels levels(series);
            QCOMPARE(levels.count(), count);
            const auto check = [&](qsizetype begin, qsizetype end) {
                const ScopeSeriesLevels::MinMax got = levels.minMax(series.values, begin, end);
                const auto [low, high] = std::minmax_element(series.values.begin() + begin,
                                                             series.values.begin() + end);
                return got.min == *low && got.max == *high;
            };
            if (count <= 5 * ScopeSeriesLevels::kBaseSize + 3) {
                for (qsizetype begin = 0; begin < count; ++begin) {
                    for (qsizetype end = begin + 1; end <= count; ++end)
                        QVERIFY2(check(begin, end), qPrintable(QStringLiteral("%1..%2 of %3")
                                                                   .arg(begin).arg(end).arg(count)));
                }
                continue;
            }
            QVERIFY(check(0, count));
            for (int round = 0; round < 2000; ++round) {
                const qsizetype begin = random.bounded(count);
                const qsizetype end = begin + 1 + random.bounded(count - begin);
                QVERIFY2(check(begin, end),
                         qPrintable(QStringLiteral("%1..%2 of %3").arg(begin).arg(end).arg(count)));
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestMinMaxPyramid)
#include "tst_scopepyramid.moc"
