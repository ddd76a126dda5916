// Reading a recording of 1,000,000 samples: its spectrum (FFTW), on even timestamps and on
// uneven ones that are resampled first, from a series and from the recording in place; the
// measurements between two cursors at its ends; a derivative and a moving average of it.
// Prints the first run and the spread of the runs after it; asserts nothing.
// Goal: the spectrum of 1,000,000 samples in at most 100 ms.
#include "scope/ScopeMath.h"
#include "scope/ScopeMeasurements.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeSpectrum.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

using namespace DriveDesk;

namespace {

constexpr qsizetype kSamples = 1'000'000;
constexpr int kRuns = 10;

// A drive-like channel in 0.01 Hz: 50 Hz of 12.5 Hz, 130 Hz of 2 Hz and a little noise.
// `uneven`: steps of 1 and 2 ms in turn, else 1 ms.
void fill(ScopeRecording &recording, bool uneven)
{
    recording.channels[0].source = 0x0203;
    recording.channels[0].id = QStringLiteral("ru.03");
    recording.channels[0].name = QStringLiteral("Actual frequency");
    recording.channels[0].scaling
        = DisplayScaling(DisplayScalingData { 0x0203, 100, 1, 0, quint16(18 | (2 << 8)) });
    quint32 noise = 12345;
    qint64 t = 0;
    for (qsizetype i = 0; i < kSamples; ++i) {
        noise = noise * 1664525u + 1013904223u;
        const double s = double(t) / 1000;
        const double hz = 12.5 * std::sin(2 * M_PI * 50 * s) + 2 * std::sin(2 * M_PI * 130 * s);
        ScopeSample sample;
        sample.time = t;
        sample.wide = { qint32(std::lround(hz * 100)) + qint32(noise >> 28) - 8, 0 };
        recording.buffer.append(sample);
        t += uneven && i % 2 ? 2 : 1;
    }
}

// The first run, then the least, the median and the most of the others, in ms.
void report(const char *what, const std::function<void()> &work)
{
    std::vector<double> ms;
    QElapsedTimer timer;
    for (int run = 0; run <= kRuns; ++run) {
        timer.start();
        work();
        ms.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    const double first = ms.front();
    ms.erase(ms.begin());
    std::sort(ms.begin(), ms.end());
    std::printf("%-62s first %6.1f ms, then %6.1f / %6.1f / %6.1f ms (least / median / most "
                "of %d)\n",
                what, first, ms.front(), ms[ms.size() / 2], ms.back(), kRuns);
}

void spectra(const char *label, const ScopeRecording &recording)
{
    const ScopeSeries series = scopeSeries(recording, 0);
    std::optional<ScopeSpectrum> spectrum;
    report(qPrintable(QStringLiteral("spectrum, %1, from a series").arg(QLatin1String(label))),
           [&] { spectrum = computeScopeSpectrum(series); });
    std::printf("  %lld samples, %lld points at %.1f Hz%s; peaks:", qlonglong(spectrum->samples),
                qlonglong(spectrum->points), spectrum->sampleRateHz,
                spectrum->resampled ? " (resampled)" : "");
    for (const ScopeSpectrumPeak &peak : spectrum->peaks.mid(0, 2))
        std::printf(" %.3f Hz %.3f Hz", peak.frequencyHz, peak.amplitude);
    std::printf("\n");
    report(
        qPrintable(
            QStringLiteral("spectrum, %1, from the recording in place").arg(QLatin1String(label))),
        [&] { spectrum = computeScopeSpectrum(recording, 0); });
}

} // namespace

int main()
{
    ScopeRecording even;
    fill(even, false);
    ScopeRecording uneven;
    fill(uneven, true);
    std::printf("%lld samples a recording\n", qlonglong(kSamples));

    report("a channel copied out as a series (scopeSeries())", [&] { scopeSeries(even, 0); });
    spectra("1 ms steps", even);
    spectra("1 and 2 ms steps", uneven);

    ScopeMeasurements measured;
    report("measurements between cursors at the recording's ends", [&] {
        measured = measureScope(even, 0, double(even.firstTime()), double(even.lastTime()));
    });
    std::printf("  min %.2f, max %.2f, mean %.4f, RMS %.4f\n", measured.minimum, measured.maximum,
                measured.mean, measured.rms);

    ScopeMathDefinition math;
    math.kind = ScopeMathDefinition::Kind::Derivative;
    report("math channel: derivative", [&] { computeScopeMath(math, even); });
    math.kind = ScopeMathDefinition::Kind::MovingAverage;
    math.window = 64;
    report("math channel: moving average of 64 samples", [&] { computeScopeMath(math, even); });
    return 0;
}
