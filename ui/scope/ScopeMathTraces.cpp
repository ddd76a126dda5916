#include "ScopeMathTraces.h"

#include "ScopeGraph.h"

#include "QCustomPlotInclude.h"

#include <algorithm>
#include <cmath>

namespace DriveDesk {

ScopeMathTraces::ScopeMathTraces(QCustomPlot *plot)
    : m_plot(plot)
{ }

QColor ScopeMathTraces::defaultColor(int index)
{
    static const QColor colors[] = { QColor(0xE6, 0x9F, 0x00), QColor(0x56, 0xB4, 0xE9),
                                     QColor(0x00, 0x00, 0x00) };
    return colors[index % 3];
}

void ScopeMathTraces::setSeries(const QList<std::shared_ptr<const ScopeSeries>> &series,
                                const QList<std::shared_ptr<const ScopeSeriesLevels>> &levels)
{
    // The graphs are kept where the traces only got new values (a growing recording).
    while (m_traces.size() > series.size()) {
        const Trace trace = m_traces.takeLast();
        m_plot->removeGraph(trace.graph); // before the axis it is drawn against
        m_plot->axisRect()->removeAxis(trace.axis);
    }
    while (m_traces.size() < series.size()) {
        Trace trace;
        trace.axis = m_plot->axisRect()->addAxis(QCPAxis::atRight);
        trace.graph = ScopeGraph::add(m_plot, m_plot->xAxis, trace.axis);
        const QColor color = defaultColor(int(m_traces.size()));
        // Solid: its colour, its own axis and its legend entry tell it from the channels, and
        // a dashed pen of thousands of segments took longer to draw than the four channels.
        trace.graph->setPen(QPen(color, 1.0));
        trace.axis->setBasePen(QPen(color));
        trace.axis->setTickPen(QPen(color));
        trace.axis->setSubTickPen(QPen(color));
        trace.axis->setLabelColor(color);
        trace.axis->setTickLabelColor(color);
        m_traces.append(trace);
    }
    m_series = series;
    m_levels = levels;
    for (qsizetype i = 0; i < m_traces.size(); ++i) {
        const QString label = m_series.at(i)->label();
        m_traces[i].graph->setName(label);
        m_traces[i].axis->setLabel(label);
    }
}

void ScopeMathTraces::fill(const ScopeTraceWindow &window)
{
    const double from = double(window.fromMs);
    const double width = std::max(1.0, double(window.toMs - window.fromMs)) / window.columns;
    for (qsizetype i = 0; i < m_traces.size(); ++i) {
        const ScopeSeries &series = *m_series.at(i);
        Trace &trace = m_traces[i];
        trace.extent.reset();
        QVector<QCPGraphData> points;
        const auto add = [&](double timeMs, double value, bool inView) {
            points.append(QCPGraphData((timeMs - double(window.originMs)) / 1000.0, value));
            if (!inView)
                return;
            trace.extent = trace.extent
                ? ScopeValueSpan { std::min(trace.extent->low, value),
                                   std::max(trace.extent->high, value) }
                : ScopeValueSpan { value, value };
        };
        // The values just outside the view too, so that the line reaches its edges.
        const qsizetype begin = series.lowerBound(from);
        const qsizetype end = series.upperBound(double(window.toMs));
        if (begin > 0)
            add(series.timeMs[std::size_t(begin - 1)], series.values[std::size_t(begin - 1)], false);
        // Each column's end found by binary search, its min and max read from the levels
        // where they were built: O(columns * log n) a fill, not O(samples in view).
        const ScopeSeriesLevels *levels = i < m_levels.size() ? m_levels.at(i).get() : nullptr;
        if (levels && levels->count() != series.count())
            levels = nullptr;
        const auto timeAt = [&](qsizetype k) { return series.timeMs[std::size_t(k)]; };
        const auto valueAt = [&](qsizetype k) { return series.values[std::size_t(k)]; };
        qsizetype at = begin;
        while (at < end) {
            const qint64 column = qint64((timeAt(at) - from) / width);
            const double columnEnd = from + double(column + 1) * width;
            const qsizetype next = qsizetype(
                std::lower_bound(series.timeMs.begin() + at + 1, series.timeMs.begin() + end,
                                 columnEnd)
                - series.timeMs.begin());
            const qsizetype last = next - 1;
            if (last - at < 2) {
                for (qsizetype k = at; k <= last; ++k)
                    add(timeAt(k), valueAt(k), true);
            } else {
                ScopeSeriesLevels::MinMax extremes;
                if (levels) {
                    extremes = levels->minMax(series.values, at, next);
                } else {
                    const auto [low, high] = std::minmax_element(
                        series.values.begin() + at, series.values.begin() + next);
                    extremes = { *low, *high };
                }
                const double time = (timeAt(at) + timeAt(last)) / 2;
                const bool fromHigh = !points.isEmpty()
                    && std::abs(points.last().value - extremes.max)
                        < std::abs(points.last().value - extremes.min);
                add(time, fromHigh ? extremes.max : extremes.min, true);
                add(time, fromHigh ? extremes.min : extremes.max, true);
            }
            at = next;
        }
        if (end < series.count())
            add(series.timeMs[std::size_t(end)], series.values[std::size_t(end)], false);
        trace.graph->data()->set(points, true);
    }
}

void ScopeMathTraces::clear()
{
    for (Trace &trace : m_traces) {
        trace.graph->data()->clear();
        trace.extent.reset();
    }
}

void ScopeMathTraces::fitAxes(double margin)
{
    for (const Trace &trace : std::as_const(m_traces)) {
        if (!trace.extent)
            continue;
        const ScopeValueSpan &span = *trace.extent;
        const double room = span.high > span.low ? (span.high - span.low) * margin
                                                 : std::max(std::abs(span.high) * margin, 0.5);
        trace.axis->setRange(span.low - room, span.high + room);
    }
}

} // namespace DriveDesk
