#include "ScopeSpectrum.h"

#include "ScopeFftw.h"
#include "ScopeSampleWindow.h"

#include <QCoreApplication>

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace DriveDesk {

namespace {

// The largest 2^a 3^b 5^c 7^d <= n: a size FFTW transforms quickly (a prime one takes it ten
// times as long).
qsizetype smoothCount(qsizetype n)
{
    qint64 best = 1;
    for (qint64 p2 = 1; p2 <= n; p2 *= 2) {
        for (qint64 p3 = p2; p3 <= n; p3 *= 3) {
            for (qint64 p5 = p3; p5 <= n; p5 *= 5) {
                for (qint64 p7 = p5; p7 <= n; p7 *= 7)
                    best = std::max(best, p7);
            }
        }
    }
    return qsizetype(best);
}

// The window's samples as `points` evenly spaced values in `out`; false where they come
// unevenly, with nothing written.
template<typename Window>
bool takeEven(const Window &window, qsizetype points, double *out, ScopeSpectrum &spectrum)
{
    const double step = window.time(window.begin + 1) - window.time(window.begin);
    const double tolerance = step * 1e-9;
    for (qsizetype i = window.begin + 1; i < window.end; ++i) {
        if (step <= 0 || std::abs(window.time(i) - window.time(i - 1) - step) > tolerance)
            return false;
    }
    for (qsizetype k = 0; k < points; ++k)
        out[k] = window.value(window.begin + k);
    spectrum.fromMs = window.time(window.begin);
    spectrum.toMs = window.time(window.begin + points - 1);
    spectrum.sampleRateHz = 1000.0 / step;
    return true;
}

// Uneven samples resampled to `points` evenly over the window by linear interpolation. A run
// of samples in one ms is spread evenly over it (no wider than the step to the next time; the
// last run as wide as the step before it), so the times strictly increase.
template<typename Window>
void resample(const Window &window, qsizetype points, double *out, ScopeSpectrum &spectrum)
{
    const qsizetype n = window.end - window.begin;
    std::vector<double> times(static_cast<std::size_t>(n));
    double previousStep = 1.0;
    for (qsizetype run = 0; run < n;) {
        const double t = window.time(window.begin + run);
        qsizetype next = run + 1;
        while (next < n && window.time(window.begin + next) == t)
            ++next;
        const double width
            = std::min(1.0, next < n ? window.time(window.begin + next) - t : previousStep);
        for (qsizetype j = run; j < next; ++j)
            times[std::size_t(j)] = t + width * double(j - run) / double(next - run);
        previousStep = width;
        run = next;
    }
    const double first = times.front();
    const double step = (times.back() - first) / double(points - 1);
    std::size_t j = 0;
    for (qsizetype k = 0; k < points; ++k) {
        const double t = k + 1 == points ? times.back() : first + step * double(k);
        while (j + 2 < times.size() && times[j + 1] <= t)
            ++j;
        const double a = window.value(window.begin + qsizetype(j));
        const double b = window.value(window.begin + qsizetype(j) + 1);
        const double share = (t - times[j]) / (times[j + 1] - times[j]);
        out[k] = a + (b - a) * std::clamp(share, 0.0, 1.0);
    }
    spectrum.fromMs = first;
    spectrum.toMs = times.back();
    spectrum.sampleRateHz = 1000.0 / step;
    spectrum.resampled = true;
}

// The periodic Hann window after the mean is removed; returns the window's sum. The cosine is
// stepped by rotation, seeded afresh every 1024 points (std::cos a point costs more than the
// transform).
double removeMeanAndWindow(double *values, qsizetype n)
{
    double mean = 0;
    for (qsizetype k = 0; k < n; ++k)
        mean += values[k];
    mean /= double(n);
    const double angle = 2 * std::numbers::pi / double(n);
    const double stepCos = std::cos(angle);
    const double stepSin = std::sin(angle);
    double c = 1;
    double s = 0;
    double sum = 0;
    for (qsizetype k = 0; k < n; ++k) {
        if (k % 1024 == 0) {
            c = std::cos(angle * double(k));
            s = std::sin(angle * double(k));
        }
        const double w = 0.5 - 0.5 * c;
        values[k] = (values[k] - mean) * w;
        sum += w;
        const double nextC = c * stepCos - s * stepSin;
        s = s * stepCos + c * stepSin;
        c = nextC;
    }
    return sum;
}

// |X_k| scaled to the amplitude of a sine at bin k: 2 |X_k| / sum(w), the bins at 0 and
// n / 2 once. In place: `values` holds n reals padded to n / 2 + 1 complex numbers, which the
// transform overwrites (fresh memory costs page faults: one buffer, not two).
//
// An even n is transformed as n / 2 complex numbers z_k = x_2k + i x_2k+1 (the same memory),
// and the real transform's bins are unpicked from theirs:
//   X_k = (Z_k + conj Z_(n/2-k)) / 2 - i e^(-2 pi i k / n) (Z_k - conj Z_(n/2-k)) / 2.
// FFTW's own real-to-complex plan of a million points takes it ten times as long to make as
// the complex plan of half a million (FFTW 3.3.10, FFTW_ESTIMATE; docs/performance.md), and
// the transform is no quicker. An odd n (a few small counts) takes the real plan.
std::vector<double> amplitudes(double *values, qsizetype n, double windowSum)
{
    const qsizetype bins = n / 2 + 1;
    auto *transformed = reinterpret_cast<fftw_complex *>(values);
    std::vector<double> amplitude;
    amplitude.reserve(std::size_t(bins));
    ScopeFftw::adviseHugePages(amplitude.data(), std::size_t(bins) * sizeof(double));
    const auto add = [&](qsizetype k, double re, double im) {
        const bool once = k == 0 || 2 * k == n;
        amplitude.push_back(std::sqrt(re * re + im * im) * (once ? 1 : 2) / windowSum);
    };
    // Kept plans run on the arrays they were made on, or on others of FFTW's alignment.
    const ScopeFftw::Plan plan = ScopeFftw::plan(int(n), values);
    if (n % 2 != 0) {
        fftw_execute_dft_r2c(plan.get(), values, transformed);
        for (qsizetype k = 0; k < bins; ++k)
            add(k, transformed[k][0], transformed[k][1]);
        return amplitude;
    }
    fftw_execute_dft(plan.get(), transformed, transformed);
    const qsizetype half = n / 2;
    // e^(-2 pi i k / n) stepped by rotation, seeded afresh every 1024 bins.
    const double angle = -2 * std::numbers::pi / double(n);
    const double stepCos = std::cos(angle);
    const double stepSin = std::sin(angle);
    double c = 1;
    double s = 0;
    for (qsizetype k = 0; k < bins; ++k) {
        if (k % 1024 == 0) {
            c = std::cos(angle * double(k));
            s = std::sin(angle * double(k));
        }
        const fftw_complex &a = transformed[k % half];
        const fftw_complex &b = transformed[(half - k % half) % half];
        // even = (a + conj b) / 2, odd = -i (a - conj b) / 2
        const double evenRe = (a[0] + b[0]) / 2;
        const double evenIm = (a[1] - b[1]) / 2;
        const double oddRe = (a[1] + b[1]) / 2;
        const double oddIm = -(a[0] - b[0]) / 2;
        add(k, evenRe + c * oddRe - s * oddIm, evenIm + c * oddIm + s * oddRe);
        const double nextC = c * stepCos - s * stepSin;
        s = s * stepCos + c * stepSin;
        c = nextC;
    }
    return amplitude;
}

template<typename Window>
std::optional<ScopeSpectrum> compute(const Window &window, const ScopeSpectrumOptions &options,
                                     ScopeSpectrum spectrum, QString *error)
{
    const auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    spectrum.samples = window.end - window.begin;
    if (spectrum.samples < ScopeSpectrum::kMinSamples) {
        return fail(QCoreApplication::translate(
                        "ScopeSpectrum",
                        "too few samples for a spectrum: %1 in the window, at least %2 needed")
                        .arg(spectrum.samples)
                        .arg(ScopeSpectrum::kMinSamples));
    }
    if (window.time(window.end - 1) <= window.time(window.begin)) {
        return fail(QCoreApplication::translate("ScopeSpectrum",
                                                "the samples span no time: all %1 are in one ms")
                        .arg(spectrum.samples));
    }

    spectrum.points = smoothCount(spectrum.samples);
    // The points, then (in place) their transform: n / 2 + 1 complex numbers.
    const ScopeFftw::Buffer values = ScopeFftw::allocateBuffer(2 * std::size_t(spectrum.points / 2 + 1));
    if (!values)
        return fail(
            QCoreApplication::translate("ScopeSpectrum", "not enough memory for a spectrum"));
    if (!takeEven(window, spectrum.points, values.get(), spectrum))
        resample(window, spectrum.points, values.get(), spectrum);
    spectrum.binHz = spectrum.sampleRateHz / double(spectrum.points);
    const double windowSum = removeMeanAndWindow(values.get(), spectrum.points);
    spectrum.amplitude = amplitudes(values.get(), spectrum.points, windowSum);
    spectrum.peaks = scopeSpectrumPeaks(spectrum.amplitude, spectrum.binHz, options.peaks);
    return spectrum;
}

// The Hann window's response at `offset` bins from a sine's frequency, relative to on it:
// sinc(offset) / (1 - offset²).
double hannResponse(double offset)
{
    if (offset < 1e-9)
        return 1;
    const double x = std::numbers::pi * offset;
    return std::sin(x) / x / (1 - offset * offset);
}

} // namespace

QList<ScopeSpectrumPeak> scopeSpectrumPeaks(const std::vector<double> &amplitude, double binHz,
                                            int count)
{
    // Below this share of the highest amplitude a maximum is the transform's rounding (about
    // 1e-15 of it), not the signal: a 32-bit channel's smallest step is 2e-10 of its range.
    constexpr double kRounding = 1e-12;
    const double highest
        = amplitude.empty() ? 0.0 : *std::max_element(amplitude.begin(), amplitude.end());
    std::vector<std::size_t> maxima;
    for (std::size_t k = 1; k + 1 < amplitude.size(); ++k) {
        if (amplitude[k] > amplitude[k - 1] && amplitude[k] >= amplitude[k + 1]
            && amplitude[k] > kRounding * highest)
            maxima.push_back(k);
    }
    const auto higher = [&](std::size_t a, std::size_t b) { return amplitude[a] > amplitude[b]; };
    const std::size_t taken = std::min(maxima.size(), std::size_t(std::max(count, 0)));
    std::partial_sort(maxima.begin(), maxima.begin() + std::ptrdiff_t(taken), maxima.end(), higher);

    QList<ScopeSpectrumPeak> peaks;
    for (std::size_t i = 0; i < taken; ++i) {
        const std::size_t k = maxima[i];
        // A sine between bins k and k +- 1 under a Hann window: the ratio of the higher
        // neighbour to the peak, r, puts it (2r - 1) / (r + 1) bins towards that neighbour.
        const double left = amplitude[k - 1];
        const double right = amplitude[k + 1];
        const double ratio = std::max(left, right) / amplitude[k];
        const double offset = std::clamp((2 * ratio - 1) / (ratio + 1), 0.0, 0.5);
        const double direction = right >= left ? 1 : -1;
        peaks << ScopeSpectrumPeak { (double(k) + direction * offset) * binHz,
                                     amplitude[k] / hannResponse(offset) };
    }
    return peaks;
}

std::optional<ScopeSpectrum>
computeScopeSpectrum(const ScopeSeries &series, const ScopeSpectrumOptions &options, QString *error)
{
    ScopeSpectrum spectrum;
    spectrum.title = series.title;
    spectrum.unit = series.unit;
    return compute(ScopeSampleWindow::OfSeries(series, options.fromMs, options.toMs), options,
                   std::move(spectrum), error);
}

std::optional<ScopeSpectrum> computeScopeSpectrum(const ScopeRecording &recording, int channel,
                                                  const ScopeSpectrumOptions &options,
                                                  QString *error)
{
    Q_ASSERT(channel >= 0 && channel < recording.channels.size());
    ScopeSpectrum spectrum;
    spectrum.title = recording.channels.at(channel).title(channel);
    spectrum.unit = recording.channels.at(channel).unit();
    return compute(ScopeSampleWindow::OfRecording(recording, channel, options.fromMs, options.toMs),
                   options, std::move(spectrum), error);
}

std::optional<ScopeSpectrum> computeScopeSpectrum(const ScopeSnapshot &snapshot, int channel,
                                                  const ScopeSpectrumOptions &options,
                                                  QString *error)
{
    Q_ASSERT(channel >= 0 && channel < snapshot.channels.size());
    ScopeSpectrum spectrum;
    spectrum.title = snapshot.channels.at(channel).title(channel);
    spectrum.unit = snapshot.channels.at(channel).unit();
    return compute(ScopeSampleWindow::OfRecording(snapshot, channel, options.fromMs, options.toMs),
                   options, std::move(spectrum), error);
}

} // namespace DriveDesk
