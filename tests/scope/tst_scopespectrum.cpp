// The spectrum: a known sine's frequency within a bin and its amplitude within a few percent,
// on even and uneven timestamps and with several samples a ms; two sines' two peaks; the
// window, the units, and a spectrum that cannot be made; the plans kept by size, in one thread
// and in several.
#include "ScopeTestRecording.h"
#include "scope/ScopeSeries.h"
#include "scope/ScopeSnapshot.h"
#include "scope/ScopeSpectrum.h"

#include <QTest>

#include <cmath>
#include <functional>
#include <thread>

using namespace DriveDesk;
using namespace DriveDesk::ScopeTest;

namespace {

struct Sine
{
    double frequencyHz;
    double amplitude;
};

// `count` samples at the given times (ms) of an offset plus the sines.
ScopeSeries signal(const std::vector<double> &times, const QList<Sine> &sines, double offset = 0)
{
    ScopeSeries series;
    series.title = QStringLiteral("test");
    series.unit = QStringLiteral("A");
    for (const double t : times) {
        double value = offset;
        for (const Sine &sine : sines)
            value += sine.amplitude * std::sin(2 * M_PI * sine.frequencyHz * t / 1000 + 0.3);
        series.timeMs.push_back(t);
        series.values.push_back(value);
    }
    return series;
}

std::vector<double> evenTimes(int count, double stepMs)
{
    std::vector<double> times;
    for (int i = 0; i < count; ++i)
        times.push_back(100 + i * stepMs);
    return times;
}

// Whole ms with steps of 1, 2 or 3 ms at random.
std::vector<double> unevenTimes(int count)
{
    std::vector<double> times;
    quint32 random = 4711;
    double t = 0;
    for (int i = 0; i < count; ++i) {
        times.push_back(t);
        random = random * 1664525u + 1013904223u;
        t += 1 + (random >> 16) % 3;
    }
    return times;
}

QString describe(const ScopeSpectrum &spectrum)
{
    QStringList peaks;
    for (const ScopeSpectrumPeak &peak : spectrum.peaks)
        peaks << QStringLiteral("%1 Hz: %2").arg(peak.frequencyHz).arg(peak.amplitude);
    return QStringLiteral("%1 points, bin %2 Hz, peaks %3")
        .arg(spectrum.points)
        .arg(spectrum.binHz)
        .arg(peaks.join(QStringLiteral(", ")));
}

void verifyPeak(const ScopeSpectrum &spectrum, int index, const Sine &sine, double tolerance)
{
    QVERIFY2(spectrum.peaks.size() > index, qPrintable(describe(spectrum)));
    const ScopeSpectrumPeak &peak = spectrum.peaks.at(index);
    QVERIFY2(std::abs(peak.frequencyHz - sine.frequencyHz) < spectrum.binHz,
             qPrintable(describe(spectrum)));
    QVERIFY2(std::abs(peak.amplitude - sine.amplitude) < tolerance * sine.amplitude,
             qPrintable(describe(spectrum)));
}

} // namespace

class TestScopeSpectrum : public QObject
{
    Q_OBJECT
private slots:
    // 2000 samples a ms apart: 2000 = 2^4 5^3 points, bins of 0.5 Hz. 50.3 Hz lies between
    // two bins, where the Hann window alone would read 10 % low.
    void sineOnEvenTimestamps()
    {
        const Sine sine { 50.3, 3.0 };
        const ScopeSeries series = signal(evenTimes(2000, 1), { sine }, 10);
        QString error;
        const std::optional<ScopeSpectrum> spectrum = computeScopeSpectrum(series, {}, &error);
        QVERIFY2(spectrum, qPrintable(error));
        QCOMPARE(spectrum->samples, qsizetype(2000));
        QCOMPARE(spectrum->points, qsizetype(2000));
        QVERIFY(!spectrum->resampled);
        QCOMPARE(spectrum->sampleRateHz, 1000.0);
        QCOMPARE(spectrum->binHz, 0.5);
        QCOMPARE(spectrum->amplitude.size(), std::size_t(1001));
        QCOMPARE(spectrum->fromMs, 100.0);
        QCOMPARE(spectrum->toMs, 2099.0);
        QCOMPARE(spectrum->unit, QStringLiteral("A"));
        verifyPeak(*spectrum, 0, sine, 0.005);
        // The mean (10 A) is removed: bin 0 holds next to nothing.
        QVERIFY(spectrum->amplitude.front() < 0.01);
        // The nearest bin (101, 0.4 bins off) reads the Hann window's 10 % low; the peak is
        // refined from it and its neighbour.
        const double binAmplitude = spectrum->amplitude[101];
        QVERIFY2(binAmplitude < 0.92 * sine.amplitude && binAmplitude > 0.88 * sine.amplitude,
                 qPrintable(QString::number(binAmplitude)));
        // On a bin, the bin itself reads A.
        const std::optional<ScopeSpectrum> onBin
            = computeScopeSpectrum(signal(evenTimes(2000, 1), { { 50.0, 3.0 } }));
        QVERIFY(std::abs(onBin->amplitude[100] - 3.0) < 1e-6);
        QVERIFY(std::abs(onBin->peaks.first().frequencyHz - 50.0) < 1e-6);
    }

    void sineOnUnevenTimestamps()
    {
        const Sine sine { 23.7, 1.5 };
        const ScopeSeries series = signal(unevenTimes(6000), { sine });
        QString error;
        const std::optional<ScopeSpectrum> spectrum = computeScopeSpectrum(series, {}, &error);
        QVERIFY2(spectrum, qPrintable(error));
        QVERIFY(spectrum->resampled);
        QCOMPARE(spectrum->points, qsizetype(6000)); // 2^4 3 5^3
        QCOMPARE(spectrum->fromMs, series.timeMs.front());
        QCOMPARE(spectrum->toMs, series.timeMs.back());
        QVERIFY(std::abs(spectrum->sampleRateHz - 5999 * 1000 / (series.timeMs.back())) < 1e-6);
        verifyPeak(*spectrum, 0, sine, 0.03);
    }

    // A drive polled at 4 kHz stamps four samples a ms alike; spread over their ms they give
    // back the 4 kHz the sine was sampled at.
    void severalSamplesAMs()
    {
        const Sine sine { 310.0, 0.8 };
        std::vector<double> exact = evenTimes(8000, 0.25);
        ScopeSeries series = signal(exact, { sine });
        for (double &t : series.timeMs)
            t = std::floor(t);
        const std::optional<ScopeSpectrum> spectrum = computeScopeSpectrum(series);
        QVERIFY(spectrum && spectrum->resampled);
        QVERIFY(std::abs(spectrum->sampleRateHz - 4000) < 1);
        verifyPeak(*spectrum, 0, sine, 0.02);
    }

    // A sine on a bin of its own, nothing else: one peak. The bins beside it hold the
    // transform's rounding (1e-15 of it), which is no peak of the signal.
    void aPureSineHasOnePeak()
    {
        const Sine pure { 50.0, 10.0 };
        const std::optional<ScopeSpectrum> spectrum
            = computeScopeSpectrum(signal(evenTimes(2000, 1), { pure }));
        QVERIFY(spectrum);
        verifyPeak(*spectrum, 0, pure, 0.005);
        QVERIFY2(spectrum->peaks.size() <= 4, qPrintable(describe(*spectrum)));
        for (const ScopeSpectrumPeak &peak : spectrum->peaks)
            QVERIFY2(peak.amplitude > 1e-6, qPrintable(describe(*spectrum)));
    }

    void twoSines()
    {
        const Sine strong { 30.0, 2.0 };
        const Sine weak { 121.4, 0.5 };
        const std::optional<ScopeSpectrum> even
            = computeScopeSpectrum(signal(evenTimes(4096, 1), { weak, strong }));
        QVERIFY(even);
        verifyPeak(*even, 0, strong, 0.005);
        verifyPeak(*even, 1, weak, 0.005);
        // Five asked for, two found: the Hann window's side lobes fall off from the main lobe
        // bin by bin, so leakage makes no peaks of its own.
        QCOMPARE(even->peaks.size(), 2);

        // Steps of 1 to 3 ms (about 500 samples a second): sines well below that rate.
        const Sine slow { 7.0, 2.0 };
        const Sine faster { 19.1, 0.5 };
        ScopeSpectrumOptions two;
        two.peaks = 2;
        const std::optional<ScopeSpectrum> uneven
            = computeScopeSpectrum(signal(unevenTimes(8000), { faster, slow }), two);
        QVERIFY(uneven);
        QCOMPARE(uneven->peaks.size(), 2);
        verifyPeak(*uneven, 0, slow, 0.03);
        verifyPeak(*uneven, 1, faster, 0.03);
    }

    // Resampling by straight lines damps what is not well below the sample rate: at a quarter
    // of the mean rate, the steps of 1 to 3 ms make a sine read about a quarter low. Its
    // frequency is still found (docs/scope.md, "The spectrum").
    void resamplingDampsFastSines()
    {
        const Sine fast { 121.4, 0.5 };
        const std::optional<ScopeSpectrum> uneven
            = computeScopeSpectrum(signal(unevenTimes(8000), { fast }));
        QVERIFY(uneven && uneven->resampled);
        QVERIFY2(std::abs(uneven->peaks.first().frequencyHz - fast.frequencyHz) < uneven->binHz,
                 qPrintable(describe(*uneven)));
        const double share = uneven->peaks.first().amplitude / fast.amplitude;
        QVERIFY2(share > 0.65 && share < 0.85, qPrintable(describe(*uneven)));
    }

    // A recording's channel in its unit, between two times; the window picks its samples.
    void aChannelOfARecording()
    {
        ScopeRecording recording;
        recording.channels[2]
            = scaledChannel(0x0212, QStringLiteral("ru.18"), QStringLiteral("Set value"), 100, kHz);
        // 2 s at 1 kHz: 40 Hz for the first second, 75 Hz for the second.
        for (int i = 0; i < 2000; ++i) {
            const double hz = i < 1000 ? 40 : 75;
            const double value = 5 * std::sin(2 * M_PI * hz * i / 1000);
            append(recording, 5000 + i, 0, 0, qint16(std::lround(value * 100)));
        }
        ScopeSpectrumOptions second;
        second.fromMs = 6000;
        second.toMs = 6999;
        QString error;
        const std::optional<ScopeSpectrum> spectrum
            = computeScopeSpectrum(recording, 2, second, &error);
        QVERIFY2(spectrum, qPrintable(error));
        QCOMPARE(spectrum->title, QStringLiteral("ru.18 Set value"));
        QCOMPARE(spectrum->unit, QStringLiteral("Hz"));
        QCOMPARE(spectrum->samples, qsizetype(1000));
        QCOMPARE(spectrum->points, qsizetype(1000));
        verifyPeak(*spectrum, 0, { 75, 5 }, 0.005);
        // The same window of the same channel as a series.
        const std::optional<ScopeSpectrum> series
            = computeScopeSpectrum(scopeSeries(recording, 2), second);
        QCOMPARE(series->amplitude, spectrum->amplitude);
        // And from a snapshot, as the window's worker reads it.
        const std::optional<ScopeSpectrum> snapshot
            = computeScopeSpectrum(scopeSnapshot(recording, recording.buffer.count()), 2, second);
        QVERIFY(snapshot);
        QCOMPARE(snapshot->title, spectrum->title);
        QCOMPARE(snapshot->amplitude, spectrum->amplitude);
    }

    // The plans are kept by size (the last few): sizes in turn, more of them than are kept and
    // back to the first, each give the spectrum of its own size, with its sine where it is.
    void plansKeptBySizeFitTheirSize()
    {
        const QList<int> counts = { 1000, 2000, 1000, 1200, 1500, 1600, 1800, 2000, 1000 };
        for (const int count : counts) {
            const double hz = 20 + count / 100.0;
            const std::optional<ScopeSpectrum> spectrum
                = computeScopeSpectrum(signal(evenTimes(count, 1), { { hz, 2 } }));
            QVERIFY(spectrum);
            QCOMPARE(spectrum->points, qsizetype(count));
            QCOMPARE(spectrum->amplitude.size(), std::size_t(count / 2 + 1));
            verifyPeak(*spectrum, 0, { hz, 2 }, 0.005);
        }
    }

    // Threads that each run through several sizes at once, so that one puts a plan out of the
    // cache while another may still be transforming with it: each result as one thread alone.
    void plansOfSeveralSizesInSeveralThreads()
    {
        const QList<int> counts = { 3000, 3200, 3500, 3600, 4000, 4200 };
        std::vector<ScopeSeries> inputs;
        std::vector<ScopeSpectrum> alone;
        for (const int count : counts) {
            inputs.push_back(signal(evenTimes(count, 1), { { 33, 1 }, { 90, 0.5 } }));
            alone.push_back(*computeScopeSpectrum(inputs.back()));
        }
        std::vector<int> wrong(4, 0);
        std::vector<std::thread> threads;
        for (std::size_t t = 0; t < wrong.size(); ++t) {
            threads.emplace_back([&, t] {
                for (int round = 0; round < 10; ++round) {
                    for (std::size_t i = 0; i < inputs.size(); ++i) {
                        const std::size_t which = (i + t) % inputs.size();
                        const std::optional<ScopeSpectrum> result
                            = computeScopeSpectrum(inputs[which]);
                        if (!result || result->amplitude != alone[which].amplitude)
                            ++wrong[t];
                    }
                }
            });
        }
        for (std::thread &thread : threads)
            thread.join();
        QCOMPARE(wrong, std::vector<int>(4, 0));
    }

    // 1009 samples (a prime): the 1008 = 2^4 3^2 7 first are transformed.
    void aPrimeCountLeavesTheLastOut()
    {
        const std::optional<ScopeSpectrum> spectrum
            = computeScopeSpectrum(signal(evenTimes(1009, 2), { { 100, 1 } }));
        QVERIFY(spectrum);
        QCOMPARE(spectrum->samples, qsizetype(1009));
        QCOMPARE(spectrum->points, qsizetype(1008));
        QCOMPARE(spectrum->toMs, 100.0 + 1007 * 2);
        QCOMPARE(spectrum->sampleRateHz, 500.0);
        verifyPeak(*spectrum, 0, { 100, 1 }, 0.005);
    }

    void noSpectrumWhereThereIsNothingToTransform()
    {
        QString error;
        const ScopeSeries series = signal(evenTimes(100, 1), { { 50, 1 } });
        ScopeSpectrumOptions narrow;
        narrow.fromMs = 150;
        narrow.toMs = 160; // 11 samples
        QVERIFY(!computeScopeSpectrum(series, narrow, &error));
        QCOMPARE(
            error,
            QStringLiteral("too few samples for a spectrum: 11 in the window, at least 16 needed"));
        narrow.fromMs = 500;
        narrow.toMs = 600;
        QVERIFY(!computeScopeSpectrum(series, narrow, &error));
        QVERIFY2(error.contains(QStringLiteral(": 0 in the window")), qPrintable(error));

        ScopeSeries oneMs = series;
        std::fill(oneMs.timeMs.begin(), oneMs.timeMs.end(), 7.0);
        QVERIFY(!computeScopeSpectrum(oneMs, {}, &error));
        QCOMPARE(error, QStringLiteral("the samples span no time: all 100 are in one ms"));

        // A flat trace has a spectrum, of zeros, and no peak.
        const std::optional<ScopeSpectrum> flat
            = computeScopeSpectrum(signal(evenTimes(64, 1), {}, 3));
        QVERIFY(flat);
        QVERIFY(flat->peaks.isEmpty());
        QCOMPARE(*std::max_element(flat->amplitude.begin(), flat->amplitude.end()), 0.0);
    }

    // Spectra in several threads at once (FFTW's planner is guarded) give each the result one
    // thread alone gives.
    void spectraInSeveralThreads()
    {
        const ScopeSeries series = signal(unevenTimes(30000), { { 42, 1 }, { 7, 3 } });
        const std::optional<ScopeSpectrum> alone = computeScopeSpectrum(series);
        QVERIFY(alone);
        std::vector<std::optional<ScopeSpectrum>> results(4);
        std::vector<std::thread> threads;
        for (std::size_t i = 0; i < results.size(); ++i) {
            threads.emplace_back([&series, &results, i] {
                for (int round = 0; round < 5; ++round)
                    results[i] = computeScopeSpectrum(series);
            });
        }
        for (std::thread &thread : threads)
            thread.join();
        for (const std::optional<ScopeSpectrum> &result : results) {
            QVERIFY(result);
            QCOMPARE(result->amplitude, alone->amplitude);
            QCOMPARE(result->peaks, alone->peaks);
        }
    }
};

QTEST_GUILESS_MAIN(TestScopeSpectrum)
#include "tst_scopespectrum.moc"
