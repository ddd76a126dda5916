// ScopeChart: which part of the recording is shown (roll, whole, fixed), zoom and pan, and the
// value axes' fitting.
#include "ScopeChart.h"

#include "ScopeMathTraces.h"
#include "ScopeOverlayTraces.h"
#include "ScopeTraces.h"

#include "QCustomPlotInclude.h"

#include <QScopedValueRollback>

#include <algorithm>
#include <cmath>

namespace DriveDesk {

namespace {

constexpr double kFitMargin = 0.05; // of the data's span, above and below, when fitting values

} // namespace

void ScopeChart::setFollow(bool follow)
{
    if (follow == follows())
        return;
    setView(follow ? View::Roll : View::Fixed);
    applyView();
    replotSoon();
}

void ScopeChart::setRollSeconds(double seconds)
{
    if (!(seconds > 0))
        return;
    m_rollSeconds = seconds;
    applyView();
    replotSoon();
}

void ScopeChart::showAll()
{
    setView(View::All);
    applyView();
    replotSoon();
}

void ScopeChart::showTimeRange(qint64 fromMs, qint64 toMs)
{
    if (toMs < fromMs)
        std::swap(fromMs, toMs);
    setView(View::Fixed);
    followOrigin();
    // A span of one sample still gets a millisecond of width.
    setTimeRange(double(fromMs - m_originMs) / 1000.0,
                 double(std::max(toMs, fromMs + 1) - m_originMs) / 1000.0);
    replotSoon();
}

ScopeTimeRange ScopeChart::visibleTimeRange() const
{
    const QCPRange range = m_plot->xAxis->range();
    // Sample times are whole ms; the tolerance keeps a sample on an edge inside.
    constexpr double kTolerance = 1e-6;
    return { qint64(std::ceil(double(m_originMs) + range.lower * 1000.0 - kTolerance)),
             qint64(std::floor(double(m_originMs) + range.upper * 1000.0 + kTolerance)) };
}

void ScopeChart::zoomTime(double factor)
{
    m_plot->xAxis->scaleRange(factor, m_plot->xAxis->range().center());
    replotSoon();
}

void ScopeChart::panTime(double fraction)
{
    m_plot->xAxis->moveRange(m_plot->xAxis->range().size() * fraction);
    replotSoon();
}

void ScopeChart::zoomValues(double factor)
{
    for (QCPAxis *axis : m_traces->valueAxes())
        axis->scaleRange(factor, axis->range().center());
    replotSoon();
}

void ScopeChart::panValues(double fraction)
{
    for (QCPAxis *axis : m_traces->valueAxes())
        axis->moveRange(axis->range().size() * fraction);
    replotSoon();
}

void ScopeChart::setAutoScale(bool on)
{
    if (on == m_autoScale)
        return;
    m_autoScale = on;
    if (on) {
        fitValueAxes();
        replotSoon();
    }
    emit autoScaleChanged(on);
}

void ScopeChart::autoScaleValues()
{
    // The extents come from the last fill: bring it up to date first.
    refreshData();
    if (m_autoScale)
        fitValueAxes();
    else
        setAutoScale(true);
    replotSoon();
}

void ScopeChart::setView(View view)
{
    if (view == m_view)
        return;
    const bool followed = follows();
    m_view = view;
    if (followed != follows())
        emit followChanged(follows());
}

void ScopeChart::applyView()
{
    if (m_view == View::Fixed)
        return;
    const qsizetype count = shownSampleCount();
    const double last = count == 0
        ? 0
        : double(m_recording->buffer.samples().time(count - 1) - m_originMs) / 1000.0;
    if (m_view == View::Roll)
        setTimeRange(std::max(0.0, last - m_rollSeconds), std::max(last, m_rollSeconds));
    else
        setTimeRange(0, last > 0 ? last : 1.0);
}

void ScopeChart::setTimeRange(double fromSeconds, double toSeconds)
{
    const QScopedValueRollback guard(m_settingRanges, m_settingRanges + 1);
    m_plot->xAxis->setRange(fromSeconds, toSeconds);
}

void ScopeChart::timeRangeChanged()
{
    m_dataStale = true;
    if (m_settingRanges == 0)
        setView(View::Fixed);
}

void ScopeChart::valueRangeChanged()
{
    if (m_settingRanges == 0)
        setAutoScale(false);
}

void ScopeChart::fitValueAxes()
{
    const QScopedValueRollback guard(m_settingRanges, m_settingRanges + 1);
    for (QCPAxis *axis : m_traces->valueAxes()) {
        std::optional<ScopeValueSpan> span;
        for (const int channel : m_traces->drawnChannels()) {
            const std::optional<ScopeValueSpan> extent = m_traces->extent(channel);
            if (m_traces->valueAxis(channel) != axis || !extent)
                continue;
            span = span ? ScopeValueSpan { std::min(span->low, extent->low),
                                           std::max(span->high, extent->high) }
                        : *extent;
        }
        if (const std::optional<ScopeValueSpan> overlay = m_overlay->extentOn(axis)) {
            span = span ? ScopeValueSpan { std::min(span->low, overlay->low),
                                           std::max(span->high, overlay->high) }
                        : *overlay;
        }
        if (!span)
            continue;
        const double margin = span->high > span->low
            ? (span->high - span->low) * kFitMargin
            : std::max(std::abs(span->high) * kFitMargin, 0.5);
        axis->setRange(span->low - margin, span->high + margin);
    }
    m_math->fitAxes(kFitMargin);
}

void ScopeChart::placeLegend()
{
    // The legend names the channels in a row of its own above the traces, never over them.
    m_plot->legend->setVisible(true);
    m_plot->axisRect()->insetLayout()->take(m_plot->legend);
    m_plot->axisRect()->insetLayout()->simplify();
    m_plot->plotLayout()->insertRow(0);
    m_plot->plotLayout()->addElement(0, 0, m_plot->legend);
    m_plot->plotLayout()->setRowStretchFactor(0, 0.001);
    m_plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    m_plot->legend->setBorderPen(Qt::NoPen);
    m_plot->legend->setMargins(QMargins(4, 2, 4, 0));
    // An empty legend (no channel drawn: a drive whose channels are off) is as wide as its
    // margins at most, and the column it shares with the traces would be capped to that. A
    // width set below QWIDGETSIZE_MAX (margins included) is taken as it is, whatever the items.
    m_plot->legend->setMaximumSize(QWIDGETSIZE_MAX / 2, QWIDGETSIZE_MAX);
}

} // namespace DriveDesk
