#include "ScopeTraces.h"

#include "ScopeGraph.h"
#include "ScopeLegendItem.h"

#include "scope/ScopeColumnGrid.h"

#include "QCustomPlotInclude.h"

#include <algorithm>
#include <cmath>

namespace DriveDesk {

namespace {

// What fill() builds a graph from: points in time order and the range of their values.
class TraceBuilder
{
public:
    TraceBuilder(const ScopeRecording &recording, int channel, qint64 originMs)
        : m_samples(recording.buffer.samples())
        , m_channel(recording.channels.at(channel))
        , m_index(channel)
        , m_originMs(originMs)
    { }

    void reserve(qsizetype count) { m_points.reserve(count); }

    // A sample outside the view (the line's way to the edge) does not count in the extent.
    void addSample(qsizetype index, bool inView = true)
    {
        add(double(m_samples.time(index)), m_channel.toDisplay(m_samples.value(index, m_index)),
            inView);
    }

    void addColumn(const MinMaxPyramid::Column &column)
    {
        if (column.end - column.begin <= 2) {
            for (qsizetype index = column.begin; index < column.end; ++index)
                addSample(index);
            return;
        }
        // Both extremes at the column's middle: a vertical stroke over every sample in it.
        // A scaling may turn the order round (a negative multiplier).
        const double time = (double(column.firstTime) + double(column.lastTime)) / 2;
        double low = m_channel.toDisplay(column.min);
        double high = m_channel.toDisplay(column.max);
        if (low > high)
            std::swap(low, high);
        // Enter the column at the end nearer the line so far, so that it goes up and down once.
        const bool fromHigh = !m_points.isEmpty()
            && std::abs(m_points.last().value - high) < std::abs(m_points.last().value - low);
        add(time, fromHigh ? high : low);
        add(time, fromHigh ? low : high);
    }

    QVector<QCPGraphData> takePoints() { return std::move(m_points); }
    std::optional<ScopeValueSpan> extent() const { return m_extent; }

private:
    void add(double timeMs, double value, bool inView = true)
    {
        m_points.append(QCPGraphData((timeMs - double(m_originMs)) / 1000.0, value));
        if (!inView)
            return;
        if (!m_extent)
            m_extent = ScopeValueSpan { value, value };
        m_extent->low = std::min(m_extent->low, value);
        m_extent->high = std::max(m_extent->high, value);
    }

    const SampleStore &m_samples;
    const ScopeChannel &m_channel;
    int m_index = 0;
    qint64 m_originMs = 0;
    QVector<QCPGraphData> m_points;
    std::optional<ScopeValueSpan> m_extent;
};

} // namespace

ScopeTraces::ScopeTraces(QCustomPlot *plot)
    : m_plot(plot)
    , m_channels(kChannels)
{
    for (int channel = 0; channel < kChannels; ++channel) {
        Trace &trace = m_traces[channel];
        trace.graph = ScopeGraph::add(m_plot, m_plot->xAxis, m_plot->yAxis);
        trace.color = defaultColor(channel);
        updateStyle(channel);
    }
    updateLabels();
}

QColor ScopeTraces::defaultColor(int channel)
{
    static const std::array<QColor, kChannels> colors { QColor(0x00, 0x72, 0xB2),
                                                        QColor(0xD5, 0x5E, 0x00),
                                                        QColor(0x00, 0x9E, 0x73),
                                                        QColor(0x88, 0x22, 0x55) };
    return colors.at(std::size_t(channel));
}

QCPAxis *ScopeTraces::valueAxis(int channel) const
{
    return m_traces[channel].ownAxis ? m_traces[channel].ownAxis : m_plot->yAxis;
}

QList<QCPAxis *> ScopeTraces::valueAxes() const
{
    QList<QCPAxis *> axes { m_plot->yAxis };
    for (const Trace &trace : m_traces) {
        if (trace.ownAxis)
            axes.append(trace.ownAxis);
    }
    return axes;
}

void ScopeTraces::setVisible(int channel, bool visible)
{
    m_traces[channel].visible = visible;
    updateStyle(channel);
    updateLabels();
}

void ScopeTraces::setColor(int channel, const QColor &color)
{
    m_traces[channel].color = color;
    updateStyle(channel);
}

void ScopeTraces::setOwnAxis(int channel, bool own)
{
    Trace &trace = m_traces[channel];
    if (own == hasOwnAxis(channel))
        return;
    if (own) {
        trace.ownAxis = m_plot->axisRect()->addAxis(QCPAxis::atRight);
        trace.ownAxis->setRange(trace.extent ? QCPRange(trace.extent->low, trace.extent->high)
                                             : m_plot->yAxis->range());
        trace.graph->setValueAxis(trace.ownAxis);
    } else {
        // The graph leaves the axis before the axis rect deletes it.
        trace.graph->setValueAxis(m_plot->yAxis);
        m_plot->axisRect()->removeAxis(trace.ownAxis);
        trace.ownAxis = nullptr;
    }
    updateStyle(channel);
    updateLabels();
}

void ScopeTraces::setChannels(const ScopeChannels &channels)
{
    m_channels = channels;
    m_channels.resize(kChannels);
    for (int channel = 0; channel < kChannels; ++channel)
        updateStyle(channel);
    updateLabels();
}

bool ScopeTraces::isDrawn(int channel) const
{
    return m_traces[channel].visible && m_channels.at(channel).enabled;
}

QList<int> ScopeTraces::drawnChannels() const
{
    QList<int> channels;
    for (int channel = 0; channel < kChannels; ++channel) {
        if (isDrawn(channel))
            channels.append(channel);
    }
    return channels;
}

std::optional<ScopeValueSpan> fillScopeGraph(QCPGraph *graph, const ScopeRecording &recording,
                                             int channel, const ScopeColumnGrid &grid,
                                             qsizetype count, qint64 originMs,
                                             ScopeColumnMemo &memo)
{
    if (grid.first() >= grid.end()) {
        graph->data()->clear();
        return std::nullopt;
    }
    TraceBuilder builder(recording, channel, originMs);
    builder.reserve(2 * qsizetype(grid.count()) + 2);
    if (grid.first() > 0)
        builder.addSample(grid.first() - 1, false);
    const MinMaxPyramid &pyramid = recording.buffer.pyramid();
    for (int column = 0; column < grid.count(); ++column) {
        if (grid.isEmpty(column))
            continue;
        builder.addColumn(memo.column(grid, pyramid, channel, column));
    }
    if (grid.end() < count)
        builder.addSample(grid.end(), false);
    // The container takes the vector as it is (implicitly shared, no copy, no sort).
    graph->data()->set(builder.takePoints(), true);
    return builder.extent();
}

void ScopeTraces::fill(const ScopeRecording &recording, const ScopeTraceWindow &window)
{
    const SampleStore &samples = recording.buffer.samples();
    const qsizetype count = std::min(window.sampleCount, samples.count());
    const ScopeColumnGrid grid(samples, window.fromMs, window.toMs, window.columns, count);
    for (int channel = 0; channel < kChannels; ++channel) {
        Trace &trace = m_traces[channel];
        trace.extent.reset();
        if (!isDrawn(channel)) {
            trace.graph->data()->clear();
            continue;
        }
        trace.extent = fillScopeGraph(trace.graph, recording, channel, grid, count,
                                      window.originMs, m_memo);
    }
    m_memo.keep(grid);
}

void ScopeTraces::clear()
{
    for (Trace &trace : m_traces) {
        trace.graph->data()->clear();
        trace.extent.reset();
    }
}

std::optional<ScopeValueSpan> ScopeTraces::extent(int channel) const
{
    return m_traces[channel].extent;
}

int ScopeTraces::pointCount() const
{
    int count = 0;
    for (const Trace &trace : m_traces)
        count += trace.graph->data()->size();
    return count;
}

void ScopeTraces::updateStyle(int channel)
{
    Trace &trace = m_traces[channel];
    trace.graph->setPen(QPen(trace.color, 1));
    trace.graph->setName(label(channel));
    trace.graph->setVisible(isDrawn(channel));
    if (isDrawn(channel))
        showInLegend(trace.graph, true);
    else
        showInLegend(trace.graph, false);
    if (trace.ownAxis) {
        const QPen pen(trace.color);
        trace.ownAxis->setBasePen(pen);
        trace.ownAxis->setTickPen(pen);
        trace.ownAxis->setSubTickPen(pen);
        trace.ownAxis->setLabelColor(trace.color);
        trace.ownAxis->setTickLabelColor(trace.color);
        trace.ownAxis->setVisible(isDrawn(channel));
    }
}

void ScopeTraces::updateLabels()
{
    // The shared axis names the units of its channels; the legend names the channels. Their
    // names joined would not fit the axis' height.
    QStringList units;
    for (int channel = 0; channel < kChannels; ++channel) {
        if (m_traces[channel].ownAxis) {
            m_traces[channel].ownAxis->setLabel(label(channel));
            continue;
        }
        const QString unit = m_channels.at(channel).unit();
        if (isDrawn(channel) && !unit.isEmpty() && !units.contains(unit))
            units.append(unit);
    }
    m_plot->yAxis->setLabel(units.isEmpty()
                                ? QString()
                                : tr("Value [%1]", "the units of the channels on the shared axis")
                                      .arg(units.join(QStringLiteral(", "))));
}

QString ScopeTraces::label(int channel) const
{
    const ScopeChannel &source = m_channels.at(channel);
    const QString unit = source.unit();
    return unit.isEmpty()
        ? source.title(channel)
        : tr("%1 [%2]", "channel title and unit").arg(source.title(channel), unit);
}

} // namespace DriveDesk
