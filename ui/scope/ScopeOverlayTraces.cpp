#include "ScopeOverlayTraces.h"

#include "ScopeGraph.h"
#include "ScopeLegendItem.h"

#include "scope/ScopeColumnGrid.h"

#include "QCustomPlotInclude.h"

#include <algorithm>

namespace DriveDesk {

namespace {

// Halfway to white: the same hue as the channel it compares with, plainly the other one.
QColor lighter(const QColor &color)
{
    return QColor((color.red() + 255) / 2, (color.green() + 255) / 2, (color.blue() + 255) / 2);
}

// The shown recording's channel that carries what overlay channel `channel` carries: the same
// parameter (source and id), at the same place if it is there; -1 where none does.
int matchOf(const ScopeRecording &shown, const ScopeRecording &overlay, int channel)
{
    const ScopeChannel &wanted = overlay.channels.at(channel);
    const auto same = [&wanted](const ScopeChannel &other) {
        return other.enabled && other.source == wanted.source && other.id == wanted.id;
    };
    if (same(shown.channels.at(channel)))
        return channel;
    for (int other = 0; other < shown.channels.size(); ++other) {
        if (same(shown.channels.at(other)))
            return other;
    }
    return -1;
}

} // namespace

ScopeOverlayTraces::ScopeOverlayTraces(QCustomPlot *plot)
    : m_plot(plot)
{
    // Under the recording's own traces: the run shown stays in front.
    m_plot->addLayer(QStringLiteral("scopeOverlay"), m_plot->layer(QStringLiteral("main")),
                     QCustomPlot::limBelow);
    m_layer = m_plot->layer(QStringLiteral("scopeOverlay"));
    m_layer->setMode(QCPLayer::lmLogical);
    for (Trace &trace : m_traces) {
        trace.graph = ScopeGraph::add(m_plot, m_plot->xAxis, m_plot->yAxis);
        trace.graph->setLayer(m_layer);
        trace.graph->setVisible(false);
        showInLegend(trace.graph, false);
    }
}

void ScopeOverlayTraces::setOverlay(std::shared_ptr<const ScopeOverlay> overlay)
{
    m_overlay = std::move(overlay);
    m_memo.clear();
    if (!m_overlay)
        clear();
}

std::optional<ScopeOverlayShift> ScopeOverlayTraces::shiftTo(const ScopeRecording &shown) const
{
    if (!m_overlay)
        return std::nullopt;
    return m_overlay->shiftTo(shown, m_alignment);
}

void ScopeOverlayTraces::follow(const ScopeRecording &shown, const ScopeTraces &traces)
{
    const QList<int> recorded
        = m_overlay ? m_overlay->recording().recordedChannels() : QList<int>();
    for (int channel = 0; channel < kChannels; ++channel) {
        Trace &trace = m_traces[channel];
        const bool wasDrawn = trace.drawn;
        trace.match = m_overlay ? matchOf(shown, m_overlay->recording(), channel) : -1;
        trace.drawn = recorded.contains(channel)
            && (trace.match < 0 || traces.isDrawn(trace.match));
        trace.graph->setVisible(trace.drawn);
        if (!trace.drawn) {
            if (wasDrawn)
                showInLegend(trace.graph, false);
            continue;
        }
        trace.graph->setValueAxis(trace.match >= 0 ? traces.valueAxis(trace.match)
                                                   : m_plot->yAxis);
        trace.graph->setPen(QPen(lighter(trace.match >= 0 ? traces.color(trace.match)
                                                          : ScopeTraces::defaultColor(channel)),
                                 1));
        const ScopeChannel &source = m_overlay->recording().channels.at(channel);
        const QString title = m_overlay->label(source.title(channel));
        trace.graph->setName(source.unit().isEmpty()
                                 ? title
                                 : tr("%1 [%2]", "channel title and unit").arg(title, source.unit()));
        if (!wasDrawn)
            showInLegend(trace.graph, true);
    }
}

void ScopeOverlayTraces::fill(const ScopeRecording &shown, const ScopeTraceWindow &window)
{
    const std::optional<ScopeOverlayShift> shift = shiftTo(shown);
    if (!shift)
        return clear();
    const ScopeRecording &overlay = m_overlay->recording();
    const SampleStore &samples = overlay.buffer.samples();
    // The view in the overlay's own ms; its keys come out in the shown recording's seconds.
    const ScopeColumnGrid grid(samples, window.fromMs - shift->shiftMs,
                               window.toMs - shift->shiftMs, window.columns, samples.count());
    for (int channel = 0; channel < kChannels; ++channel) {
        Trace &trace = m_traces[channel];
        trace.extent.reset();
        if (!trace.drawn) {
            trace.graph->data()->clear();
            continue;
        }
        trace.extent = fillScopeGraph(trace.graph, overlay, channel, grid, samples.count(),
                                      window.originMs - shift->shiftMs, m_memo);
    }
    m_memo.keep(grid);
}

void ScopeOverlayTraces::clear()
{
    for (Trace &trace : m_traces) {
        trace.graph->data()->clear();
        trace.extent.reset();
        if (!m_overlay && trace.drawn) {
            trace.drawn = false;
            trace.graph->setVisible(false);
            showInLegend(trace.graph, false);
        }
    }
}

std::optional<ScopeValueSpan> ScopeOverlayTraces::extentOn(const QCPAxis *axis) const
{
    std::optional<ScopeValueSpan> span;
    for (const Trace &trace : m_traces) {
        if (!trace.drawn || !trace.extent || trace.graph->valueAxis() != axis)
            continue;
        span = span ? ScopeValueSpan { std::min(span->low, trace.extent->low),
                                       std::max(span->high, trace.extent->high) }
                    : *trace.extent;
    }
    return span;
}

ScopeCursorReadout ScopeOverlayTraces::read(const ScopeRecording &shown,
                                            const std::array<std::optional<double>, 2> &timeMs) const
{
    const std::optional<ScopeOverlayShift> shift = shiftTo(shown);
    if (!shift)
        return {};
    // The cursors on the overlay's own time axis, read as a recording's, then back.
    std::array<std::optional<double>, 2> own = timeMs;
    for (std::optional<double> &time : own) {
        if (time)
            *time -= double(shift->shiftMs);
    }
    const ScopeRecording &overlay = m_overlay->recording();
    ScopeCursorReadout readout
        = readScopeCursors(overlay, own, drawnChannels(), overlay.buffer.count());
    readout.originMs += shift->shiftMs;
    readout.timeMs = timeMs;
    for (std::optional<qint64> &time : readout.sampleTimeMs) {
        if (time)
            *time += shift->shiftMs;
    }
    for (ScopeCursorReadout::Channel &row : readout.channels)
        row.title = m_overlay->label(row.title);
    return readout;
}

bool ScopeOverlayTraces::isDrawn(int channel) const
{
    return m_traces[channel].drawn;
}

QList<int> ScopeOverlayTraces::drawnChannels() const
{
    QList<int> channels;
    for (int channel = 0; channel < kChannels; ++channel) {
        if (m_traces[channel].drawn)
            channels.append(channel);
    }
    return channels;
}

} // namespace DriveDesk
