// Measurements between the cursors: a ramp on uneven timestamps and a square wave, each value
// checked against what the test works out from the signal it made.
#include "ScopeTestRecording.h"
#include "scope/ScopeMeasurements.h"
#include "scope/ScopeSeries.h"
#include "scope/ScopeSnapshot.h"

#include <QTest>

#include <cmath>

using namespace DriveDesk;
using namespace DriveDesk::ScopeTest;

namespace {

// Steps of 1, 2 and 3 ms in turn from t = 0: a drive polled unevenly.
qint64 unevenTime(int i)
{
    return qint64(i / 3) * 6 + (i % 3 == 0 ? 0 : i % 3 == 1 ? 1 : 3);
}

// Channel 0 in Hz (raw tenths) rising 0.5 Hz a ms: raw = 5 * t.
void fillRamp(ScopeRecording &recording, int count)
{
    recording.channels[0] = scaledChannel(0x0203, QStringLiteral("ru.03"),
                                          QStringLiteral("Actual frequency"), 10, kHz);
    for (int i = 0; i < count; ++i)
        append(recording, unevenTime(i), qint32(5 * unevenTime(i)));
}

// Channel 1 in V (raw mV): a square wave of period 20 ms, +1 V for 5 samples and -1 V for 15,
// sampled every ms from t = 0.
void fillSquare(ScopeRecording &recording, int count)
{
    recording.channels[1] = scaledChannel(0x0209, QStringLiteral("ru.09"),
                                          QStringLiteral("Output voltage"), 1000, kVolt);
    for (int i = 0; i < count; ++i)
        append(recording, i, 0, i % 20 < 5 ? 1000 : -1000);
}

} // namespace

class TestScopeMeasurements : public QObject
{
    Q_OBJECT
private slots:
    void rampOnUnevenTimestamps()
    {
        ScopeRecording recording;
        fillRamp(recording, 600);
        // The cursors between samples: the samples from 101 ms to 900 ms count.
        const ScopeMeasurements m = measureScope(recording, 0, 100.5, 900.2);
        qint64 first = -1;
        qint64 last = -1;
        qsizetype inside = 0;
        double sampleSum = 0;
        for (int i = 0; i < 600; ++i) {
            const qint64 t = unevenTime(i);
            if (t < 101 || t > 900)
                continue;
            first = first < 0 ? t : first;
            last = t;
            ++inside;
            sampleSum += 0.5 * double(t);
        }
        QCOMPARE(m.samples, inside);
        QCOMPARE(m.firstMs, double(first));
        QCOMPARE(m.lastMs, double(last));
        const double a = 0.5 * double(first);
        const double b = 0.5 * double(last);
        QCOMPARE(m.minimum, a);
        QCOMPARE(m.maximum, b);
        QCOMPARE(m.minimumMs, double(first));
        QCOMPARE(m.maximumMs, double(last));
        QCOMPARE(m.peakToPeak(), b - a);
        // Weighed by time, the mean of a straight line is its middle, whatever the spacing;
        // the plain mean of the samples is not (more of them sit where the steps are short).
        QVERIFY(std::abs(m.mean - (a + b) / 2) < 1e-9);
        QVERIFY(std::abs(sampleSum / double(inside) - (a + b) / 2) > 0.01);
        QVERIFY(std::abs(m.rms - std::sqrt((a * a + a * b + b * b) / 3)) < 1e-9);

        // 10 % and 90 % of the span, crossed where the line 0.5 * t reaches them.
        QCOMPARE(m.lowLevel, a + 0.1 * (b - a));
        QCOMPARE(m.highLevel, a + 0.9 * (b - a));
        QVERIFY(m.rise);
        QVERIFY(!m.fall);
        QVERIFY(std::abs(m.rise->startMs - m.lowLevel / 0.5) < 1e-9);
        QVERIFY(std::abs(m.rise->endMs - m.highLevel / 0.5) < 1e-9);
        QVERIFY(m.rise->ratePerSecond);
        QVERIFY(std::abs(*m.rise->ratePerSecond - 500.0) < 1e-9); // 0.5 Hz a ms

        // The same trace as a series measures the same; the cursors in either order.
        const ScopeMeasurements fromSeries = measureScope(scopeSeries(recording, 0), 900.2, 100.5);
        QCOMPARE(fromSeries.samples, m.samples);
        QCOMPARE(fromSeries.mean, m.mean);
        QCOMPARE(fromSeries.rms, m.rms);
        QCOMPARE(fromSeries.rise->endMs, m.rise->endMs);

        // A snapshot (what the window measures in a worker) reads the samples it was taken
        // with, whatever comes after.
        const ScopeSnapshot snapshot = scopeSnapshot(recording, recording.buffer.count());
        for (int i = 600; i < 700; ++i)
            append(recording, unevenTime(i), 0);
        const ScopeMeasurements fromSnapshot = measureScope(snapshot, 0, 100.5, 5000);
        const ScopeMeasurements before
            = measureScope(scopeSeries(recording, 0, 0, unevenTime(599)), 100.5, 5000);
        QCOMPARE(fromSnapshot.samples, before.samples);
        QCOMPARE(fromSnapshot.minimum, before.minimum);
        QCOMPARE(fromSnapshot.mean, before.mean);
        QCOMPARE(measureScope(recording, 0, 100.5, 5000).minimum, 0.0); // the zeros came after
    }

    void squareWave()
    {
        ScopeRecording recording;
        fillSquare(recording, 400);
        // Ten periods, t = 0..200: per period 4 ms at +1, 14 ms at -1 and two 1 ms edges along
        // which the line runs from one level to the other (mean 0, mean square 1/3).
        const ScopeMeasurements m = measureScope(recording, 1, 0, 200);
        QCOMPARE(m.samples, qsizetype(201));
        QCOMPARE(m.minimum, -1.0);
        QCOMPARE(m.maximum, 1.0);
        QCOMPARE(m.minimumMs, 5.0);
        QCOMPARE(m.maximumMs, 0.0);
        QCOMPARE(m.peakToPeak(), 2.0);
        const double mean = (4.0 * 1 + 14.0 * -1) / 20;
        const double meanSquare = (4.0 + 14.0 + 2.0 / 3) / 20;
        QVERIFY2(std::abs(m.mean - mean) < 1e-12, qPrintable(QString::number(m.mean)));
        QVERIFY(std::abs(m.rms - std::sqrt(meanSquare)) < 1e-12);

        // Levels -0.8 and +0.8. The first fall: from t = 4 (+1) to 5 (-1); the first rise
        // after a sample at or below -0.8: from 19 (-1) to 20 (+1).
        QVERIFY(m.fall && m.rise);
        QVERIFY(std::abs(m.lowLevel + 0.8) < 1e-12 && std::abs(m.highLevel - 0.8) < 1e-12);
        QVERIFY(std::abs(m.fall->startMs - 4.1) < 1e-12);
        QVERIFY(std::abs(m.fall->endMs - 4.9) < 1e-12);
        QVERIFY(std::abs(*m.fall->ratePerSecond + 1.6 / 0.8e-3) < 1e-6);
        QVERIFY(std::abs(m.rise->startMs - 19.1) < 1e-12);
        QVERIFY(std::abs(m.rise->endMs - 19.9) < 1e-12);
        QVERIFY(std::abs(m.rise->durationMs() - 0.8) < 1e-12);
        QVERIFY(std::abs(*m.rise->ratePerSecond - 2000.0) < 1e-6); // 1.6 V in 0.8 ms

        // Levels of one's own, in volts: between -0.5 and 0.5 the edge takes 0.5 ms.
        ScopeMeasureOptions options;
        options.lowLevel = 0.5; // given the wrong way round: put in order
        options.highLevel = -0.5;
        const ScopeMeasurements own = measureScope(recording, 1, 0, 200, options);
        QCOMPARE(own.lowLevel, -0.5);
        QVERIFY(std::abs(own.rise->durationMs() - 0.5) < 1e-12);
        QVERIFY(std::abs(own.rise->startMs - 19.25) < 1e-12);
    }

    void aWindowWithoutSamplesMeasuresNothing()
    {
        ScopeRecording recording;
        fillSquare(recording, 100);
        QCOMPARE(measureScope(recording, 1, 200, 300).samples, qsizetype(0));
        QCOMPARE(measureScope(recording, 1, 10.2, 10.8).samples, qsizetype(0));
        QCOMPARE(measureScope(ScopeRecording(), 0, 0, 100).samples, qsizetype(0));
    }

    void aFlatOrSingleSampleWindowHasNoTransition()
    {
        ScopeRecording recording;
        fillSquare(recording, 100);
        const ScopeMeasurements flat = measureScope(recording, 1, 6, 18);
        QCOMPARE(flat.samples, qsizetype(13));
        QCOMPARE(flat.mean, -1.0);
        QCOMPARE(flat.rms, 1.0);
        QVERIFY(!flat.rise && !flat.fall);

        const ScopeMeasurements one = measureScope(recording, 1, 2, 2);
        QCOMPARE(one.samples, qsizetype(1));
        QCOMPARE(one.mean, 1.0);
        QCOMPARE(one.rms, 1.0);
    }

    // Two samples in one ms: a step with no time to it has no rate, and the mean and RMS of
    // samples that stand for no time are the samples' own.
    void samplesInTheSameMs()
    {
        ScopeSeries series;
        series.timeMs = { 5, 5, 5 };
        series.values = { 0, 10, 2 };
        const ScopeMeasurements m = measureScope(series, 0, 10);
        QCOMPARE(m.samples, qsizetype(3));
        QCOMPARE(m.mean, 4.0);
        QVERIFY(std::abs(m.rms - std::sqrt(104.0 / 3)) < 1e-12);
        QVERIFY(m.rise);
        QCOMPARE(m.rise->durationMs(), 0.0);
        QVERIFY(!m.rise->ratePerSecond);
    }
};

QTEST_GUILESS_MAIN(TestScopeMeasurements)
#include "tst_scopemeasurements.moc"
