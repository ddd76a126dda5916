#include "scope/SampleStore.h"

#include <QTest>

#include <limits>

using namespace DriveDesk;

namespace {

ScopeSample sampleAt(qsizetype index)
{
    // Uneven times (steps of 1..3 ms, some repeated) and values that tell samples apart.
    ScopeSample sample;
    sample.time = 1000 + index * 2 - (index % 3 == 0 ? 1 : 0);
    sample.wide = {qint32(index * 7 - 100000), qint32(-index)};
    sample.narrow = {qint16(index % 30000 - 15000), qint16(index % 2 ? -32768 : 32767)};
    return sample;
}

void fill(SampleStore &store, qsizetype count)
{
    for (qsizetype i = 0; i < count; ++i)
        QVERIFY(store.append(sampleAt(i)));
}

} // namespace

// The scope's samples in chunks: indices across chunk boundaries, time lookup, order, memory.
class TestSampleStore : public QObject
{
    Q_OBJECT

private slots:
    void emptyStore()
    {
        SampleStore store;
        QCOMPARE(store.count(), 0);
        QVERIFY(store.isEmpty());
        QCOMPARE(store.indexRange(0, 100), (SampleStore::IndexRange{0, 0}));
        QCOMPARE(store.bytesUsed(), 0);
    }

    void indicesAcrossChunks()
    {
        SampleStore store;
        const qsizetype count = 3 * SampleStore::kChunkSize + 17;
        fill(store, count);
        QCOMPARE(store.count(), count);
        for (qsizetype i : {qsizetype(0), qsizetype(1), SampleStore::kChunkSize - 1,
                            SampleStore::kChunkSize, SampleStore::kChunkSize + 1,
                            2 * SampleStore::kChunkSize - 1, 2 * SampleStore::kChunkSize,
                            3 * SampleStore::kChunkSize, count - 1}) {
            QCOMPARE(store.at(i), sampleAt(i));
            QCOMPARE(store.time(i), sampleAt(i).time);
            for (int channel = 0; channel < ScopeSample::kChannelCount; ++channel)
                QCOMPARE(store.value(i, channel), sampleAt(i).channel(channel));
        }
        for (qsizetype i = 0; i < count; ++i)
            QCOMPARE(store.at(i), sampleAt(i));
    }

    void narrowChannelsKeepTheirSign()
    {
        SampleStore store;
        ScopeSample sample;
        sample.wide = {std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max()};
        sample.narrow = {-32768, 32767};
        store.append(sample);
        QCOMPARE(store.value(0, 0), std::numeric_limits<qint32>::min());
        QCOMPARE(store.value(0, 1), std::numeric_limits<qint32>::max());
        QCOMPARE(store.value(0, 2), -32768);
        QCOMPARE(store.value(0, 3), 32767);
    }

    void timeRangeLookup()
    {
        SampleStore store;
        const qsizetype count = 2 * SampleStore::kChunkSize + 500;
        fill(store, count);
        const qint64 first = store.time(0);
        const qint64 last = store.time(count - 1);
        // Every range against a linear scan, including ones that start or end between samples,
        // before the first and after the last.
        for (qint64 from = first - 3; from <= last + 3; from += 997) {
            for (qint64 length : {0, 1, 2, 5, 100, 9000, 100000}) {
                const qint64 to = from + length;
                qsizetype begin = 0;
                while (begin < count && store.time(begin) < from)
                    ++begin;
                qsizetype end = begin;
                while (end < count && store.time(end) <= to)
                    ++end;
                QCOMPARE(store.indexRange(from, to), (SampleStore::IndexRange{begin, end}));
            }
        }
        QCOMPARE(store.indexRange(first, last), (SampleStore::IndexRange{0, count}));
        QVERIFY(store.indexRange(last + 1, last + 10).isEmpty());
        QVERIFY(store.indexRange(first - 10, first - 1).isEmpty());
        QVERIFY(store.indexRange(5000, 4000).isEmpty());
    }

    void equalTimesAreOneRange()
    {
        SampleStore store;
        for (qint64 time : {10, 20, 20, 20, 30})
            store.append(ScopeSample{time, {}, {}});
        QCOMPARE(store.indexRange(20, 20), (SampleStore::IndexRange{1, 4}));
        QCOMPARE(store.lowerBound(20), 1);
        QCOMPARE(store.upperBound(20), 4);
    }

    void refusesAnEarlierSample()
    {
        SampleStore store;
        QVERIFY(store.append(ScopeSample{100, {1, 1}, {1, 1}}));
        QVERIFY(!store.append(ScopeSample{99, {2, 2}, {2, 2}}));
        QCOMPARE(store.count(), 1);
        QCOMPARE(store.at(0), (ScopeSample{100, {1, 1}, {1, 1}}));
        QVERIFY(store.append(ScopeSample{100, {3, 3}, {3, 3}}));
        QCOMPARE(store.count(), 2);
    }

    void clear()
    {
        SampleStore store;
        fill(store, SampleStore::kChunkSize + 1);
        store.clear();
        QCOMPARE(store.count(), 0);
        QCOMPARE(store.bytesUsed(), 0);
        QVERIFY(store.append(ScopeSample{5, {}, {}}));
        QCOMPARE(store.time(0), 5);
    }

    // A share read in another thread must not see the store grow, nor lose its samples when
    // the store is cleared: its own chunk where the store's was still filling.
    void aShareKeepsItsSamplesWhileTheStoreGrows()
    {
        SampleStore store;
        const qsizetype count = 2 * SampleStore::kChunkSize + 10;
        fill(store, count);
        const SampleStore whole = store.share(count);
        const SampleStore fewer = store.share(SampleStore::kChunkSize + 3);
        const SampleStore tooMany = store.share(count + 100);
        for (qsizetype i = count; i < count + SampleStore::kChunkSize; ++i)
            QVERIFY(store.append(sampleAt(i)));
        store.clear();
        QCOMPARE(whole.count(), count);
        QCOMPARE(fewer.count(), SampleStore::kChunkSize + 3);
        QCOMPARE(tooMany.count(), count);
        for (qsizetype i = 0; i < count; ++i) {
            const ScopeSample expected = sampleAt(i);
            QCOMPARE(whole.time(i), expected.time);
            QCOMPARE(whole.value(i, 0), expected.wide[0]);
            QCOMPARE(whole.value(i, 3), qint32(expected.narrow[1]));
        }
        QCOMPARE(fewer.value(SampleStore::kChunkSize + 2, 2),
                 qint32(sampleAt(SampleStore::kChunkSize + 2).narrow[0]));
        QCOMPARE(fewer.upperBound(std::numeric_limits<qint64>::max()), fewer.count());
        QCOMPARE(store.share(5).count(), 0);
    }

    void atMost24BytesASample()
    {
        SampleStore store;
        const qsizetype count = 1'000'000;
        ScopeSample sample;
        for (qsizetype i = 0; i < count; ++i) {
            sample.time = i;
            store.append(sample);
        }
        // The last chunk may be nearly empty, and the chunk table is a few pointers a chunk.
        const qsizetype smallConstant = 20 * SampleStore::kChunkSize + 4096;
        QVERIFY2(store.bytesUsed() <= 24 * count + smallConstant,
                 QByteArray::number(store.bytesUsed()));
        const double bytesPerSample = double(store.bytesUsed()) / count;
        qInfo("%.2f bytes a sample for %lld samples", bytesPerSample, qlonglong(count));
        QVERIFY(bytesPerSample <= 24.0);
        QVERIFY(bytesPerSample >= 20.0); // the accounting counts what is there
    }
};

QTEST_APPLESS_MAIN(TestSampleStore)
#include "tst_scopestore.moc"
