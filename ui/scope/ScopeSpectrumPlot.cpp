#include "ScopeSpectrumPlot.h"

#include "parameters/DisplayUnit.h"

#include "QCustomPlotInclude.h"

#include <QHeaderView>
#include <QLocale>
#include <QTableWidget>

#include <algorithm>
#include <cmath>

namespace DriveDesk {

namespace {

// Significant digits of an amplitude: a spectrum's amplitudes have no scaling's decimals.
constexpr int kAmplitudeDigits = 4;

} // namespace

ScopeSpectrumPlot::ScopeSpectrumPlot(QWidget *parent)
{
    m_plot = new QCustomPlot(parent);
    m_plot->setObjectName(QStringLiteral("spectrumPlot"));
    m_plot->setMinimumSize(320, 240);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->axisRect()->setRangeDrag(Qt::Horizontal);
    m_plot->axisRect()->setRangeZoom(Qt::Horizontal);
    m_plot->xAxis->setLabel(tr("Frequency [Hz]"));
    m_plot->yAxis->setLabel(tr("Amplitude"));
    m_graph = m_plot->addGraph();
    m_graph->setPen(QPen(QColor(0x00, 0x72, 0xB2), 1.0));
    m_peakMarks = m_plot->addGraph();
    m_peakMarks->setLineStyle(QCPGraph::lsNone);
    m_peakMarks->setScatterStyle(
        QCPScatterStyle(QCPScatterStyle::ssCircle, QColor(0xD5, 0x5E, 0x00), 7));

    m_peaks = new QTableWidget(0, 2, parent);
    m_peaks->setObjectName(QStringLiteral("spectrumPeaks"));
    m_peaks->setHorizontalHeaderLabels({ tr("Frequency"), tr("Amplitude") });
    m_peaks->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_peaks->verticalHeader()->setToolTip(tr("The highest peaks, the highest first"));
    m_peaks->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_peaks->setSelectionMode(QAbstractItemView::ContiguousSelection);
}

int ScopeSpectrumPlot::frequencyDecimals(double binHz)
{
    return std::clamp(int(std::ceil(-std::log10(binHz))) + 1, 0, 6);
}

void ScopeSpectrumPlot::show(const ScopeSpectrum &spectrum, const QList<QCPGraphData> &points)
{
    m_graph->data()->set(points, true);
    m_highest = spectrum.amplitude.empty()
        ? 0
        : *std::max_element(spectrum.amplitude.begin(), spectrum.amplitude.end());
    m_plot->yAxis->setLabel(spectrum.unit.isEmpty() ? tr("Amplitude")
                                                    : tr("Amplitude [%1]").arg(spectrum.unit));
    m_plot->xAxis->setRange(0, spectrum.sampleRateHz / 2);
    showPeaks(spectrum);
    fitAmplitudeAxis();
    m_plot->replot();
}

void ScopeSpectrumPlot::clear()
{
    m_graph->data()->clear();
    m_peakMarks->data()->clear();
    m_peaks->setRowCount(0);
    m_highest = 0;
    m_plot->replot();
}

void ScopeSpectrumPlot::setLogarithmic(bool on)
{
    m_logarithmic = on;
    m_plot->yAxis->setScaleType(on ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
    m_plot->yAxis->setTicker(on ? QSharedPointer<QCPAxisTicker>(new QCPAxisTickerLog)
                                : QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
    fitAmplitudeAxis();
    m_plot->replot();
}

void ScopeSpectrumPlot::showPeaks(const ScopeSpectrum &spectrum)
{
    const QLocale locale;
    const int decimals = frequencyDecimals(spectrum.binHz);
    m_peaks->setRowCount(int(spectrum.peaks.size()));
    QList<QCPGraphData> marks;
    for (int row = 0; row < spectrum.peaks.size(); ++row) {
        const ScopeSpectrumPeak &peak = spectrum.peaks.at(row);
        const auto set = [this, row](int column, const QString &text) {
            auto *item = new QTableWidgetItem(text);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_peaks->setItem(row, column, item);
        };
        set(0, withUnit(locale.toString(peak.frequencyHz, 'f', decimals), tr("Hz")));
        set(1, withUnit(locale.toString(peak.amplitude, 'g', kAmplitudeDigits), spectrum.unit));
        marks.append(QCPGraphData(peak.frequencyHz, peak.amplitude));
    }
    std::sort(marks.begin(), marks.end(),
              [](const QCPGraphData &a, const QCPGraphData &b) { return a.key < b.key; });
    m_peakMarks->data()->set(marks, true);
}

void ScopeSpectrumPlot::fitAmplitudeAxis()
{
    const double highest = std::max(m_highest, 1e-12);
    // Below six decades under the highest lie the window's leakage and the noise.
    if (m_logarithmic)
        m_plot->yAxis->setRange(highest * 1e-6, highest * 2);
    else
        m_plot->yAxis->setRange(0, highest * 1.05);
}

} // namespace DriveDesk
