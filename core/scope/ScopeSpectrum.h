#pragma once

#include <QList>
#include <QString>

#include <limits>
#include <optional>
#include <vector>

namespace DriveDesk {

struct ScopeRecording;
struct ScopeSeries;
struct ScopeSnapshot;

// Which part of a trace a spectrum is made of, and how many peaks to name.
struct ScopeSpectrumOptions
{
    // The samples with fromMs <= time <= toMs, in the trace's own ms; the defaults take all.
    double fromMs = -std::numeric_limits<double>::infinity();
    double toMs = std::numeric_limits<double>::infinity();
    int peaks = 5; // the highest peaks to find, 0 for none
};

// One peak of a spectrum: a local maximum of the amplitudes, its frequency and amplitude
// refined between the bins for the Hann window (so a sine between two bins reads its own).
struct ScopeSpectrumPeak
{
    double frequencyHz = 0;
    double amplitude = 0; // in the trace's unit: a sine of amplitude A reads A
    bool operator==(const ScopeSpectrumPeak &) const = default;
};

// The amplitude spectrum of a trace over a time window.
struct ScopeSpectrum
{
    // The fewest samples a spectrum is made of.
    static constexpr qsizetype kMinSamples = 16;

    QString title; // the trace's
    QString unit; // the trace's: the amplitudes are in it
    qsizetype samples = 0; // the window's samples
    qsizetype points = 0; // the evenly spaced points transformed (at most `samples`)
    double fromMs = 0; // the first and the last point's time
    double toMs = 0;
    double sampleRateHz = 0; // of the points
    double binHz = 0; // the frequency step between bins: sampleRateHz / points
    bool resampled = false; // the samples came unevenly: the points are interpolated
    std::vector<double> amplitude; // bin k (0 .. points / 2) at k * binHz
    QList<ScopeSpectrumPeak> peaks; // the highest first
};

// How a spectrum is made (docs/scope.md, "The spectrum"):
//  1. The samples in the window. Where they are evenly spaced they are taken as they are; else
//     samples that share a ms are spread evenly over it (a drive polled faster than its 1 ms
//     clock stamps several alike), and the trace is resampled to even spacing over the window
//     by linear interpolation.
//  2. The number of points is the largest count of the form 2^a 3^b 5^c 7^d that the samples
//     allow, for FFTW's speed (a prime count takes it ten times as long): about 1 % fewer
//     than the samples at most near a million, up to 9 % in a window of a few dozen. Evenly
//     spaced samples past it are left out at the window's end.
//  3. The mean is removed, a Hann window applied, the real FFT taken (FFTW), and each bin's
//     magnitude scaled so that a sine of amplitude A at a bin's frequency reads A.
//
// Pure: no QObject, nothing shared but FFTW's planner and the last few sizes' plans, kept
// (planning a million points costs more than the transform), both guarded; runs in any
// thread.
// Nothing and *error ("too few samples ...", "the samples span no time") where no spectrum
// can be made.
std::optional<ScopeSpectrum> computeScopeSpectrum(const ScopeSeries &series,
                                                  const ScopeSpectrumOptions &options = {},
                                                  QString *error = nullptr);
// A channel of a snapshot of a recording, read in place: in any thread.
std::optional<ScopeSpectrum> computeScopeSpectrum(const ScopeSnapshot &snapshot, int channel,
                                                  const ScopeSpectrumOptions &options = {},
                                                  QString *error = nullptr);
// A channel of a recording, its window read in place (display values). The recording is
// single-threaded: call this in its thread, or take scopeSeries() there and hand the copy to a
// worker.
std::optional<ScopeSpectrum> computeScopeSpectrum(const ScopeRecording &recording, int channel,
                                                  const ScopeSpectrumOptions &options = {},
                                                  QString *error = nullptr);
// The `count` highest local maxima of `amplitude` (bins 1 .. size - 2, each higher than the bin
// below and at least as high as the one above), refined between the bins for a Hann window,
// the highest first.
QList<ScopeSpectrumPeak> scopeSpectrumPeaks(const std::vector<double> &amplitude, double binHz,
                                            int count);

} // namespace DriveDesk
