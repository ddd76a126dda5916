#pragma once

#include "scope/ScopeSpectrum.h"

#include <QCoreApplication>
#include <QList>

#include <optional>

class QCPGraph;
class QCPGraphData;
class QCustomPlot;
class QTableWidget;
class QWidget;

namespace DriveDesk {

// What the spectrum window shows of a spectrum: the amplitudes over frequency as a line (0 to
// half the sample rate), the highest peaks marked on it and listed in a table (frequency one
// decimal finer than the bins, amplitude to four significant digits, in the channel's unit).
// The plot and the table belong to their parent widget; this fills them.
class ScopeSpectrumPlot
{
    Q_DECLARE_TR_FUNCTIONS(ScopeSpectrumPlot)
public:
    explicit ScopeSpectrumPlot(QWidget *parent);

    QCustomPlot *plot() const { return m_plot; }
    QTableWidget *peakTable() const { return m_peaks; }

    // `points`: the amplitudes as QCustomPlot's data (made in the worker: half a million).
    void show(const ScopeSpectrum &spectrum, const QList<QCPGraphData> &points);
    void clear();
    // Six decades under the highest peak, or linear from 0.
    void setLogarithmic(bool on);

    // Decimals enough to tell a peak from the next bin: one finer than the bins.
    static int frequencyDecimals(double binHz);

private:
    void showPeaks(const ScopeSpectrum &spectrum);
    void fitAmplitudeAxis();

    QCustomPlot *m_plot = nullptr;
    QCPGraph *m_graph = nullptr;
    QCPGraph *m_peakMarks = nullptr;
    QTableWidget *m_peaks = nullptr;
    bool m_logarithmic = false;
    double m_highest = 0; // the highest amplitude shown
};

} // namespace DriveDesk
