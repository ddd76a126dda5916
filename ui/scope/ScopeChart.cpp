// ScopeChart: the recording, the refresh timer, the points each replot draws, the channels and
// the cursors. The view is in ScopeChartView.cpp, keys and mouse in ScopeChartInput.cpp, export
// in ScopeChartExport.cpp.
#include "ScopeChart.h"

#include "ScopeCursorTable.h"
#include "ScopeCursors.h"
#include "ScopeMathTraces.h"
#include "ScopeOverlayTraces.h"
#include "ScopeTraces.h"

#include "QCustomPlotInclude.h"

#include <QScopedValueRollback>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace DriveDesk {

ScopeChart::ScopeChart(QWidget *parent)
    : QWidget(parent)
    , m_plot(new QCustomPlot(this))
{
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->axisRect()->setRangeDrag(Qt::Horizontal);
    m_plot->axisRect()->setRangeZoom(Qt::Horizontal);
    // Thin lines over a few thousand points: antialiasing would only cost time.
    m_plot->setNotAntialiasedElements(QCP::aeAll);
    // One paint buffer instead of two: the overlay layer (QCustomPlot's selection rectangle,
    // unused here) would be cleared and composed over the plot on every replot.
    m_plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    m_plot->xAxis->setLabel(tr("Time [s]"));
    m_plot->xAxis->setRange(0, m_rollSeconds);
    m_plot->yAxis->setRange(0, 1);
    placeLegend();
    m_plot->setMouseTracking(true);
    m_plot->setFocusPolicy(Qt::StrongFocus);
    m_plot->setToolTip(helpText());
    setFocusProxy(m_plot);

    m_traces = std::make_unique<ScopeTraces>(m_plot);
    m_math = std::make_unique<ScopeMathTraces>(m_plot);
    m_overlay = std::make_unique<ScopeOverlayTraces>(m_plot);
    m_cursors = new ScopeCursors(m_plot);
    m_triggerLine = new QCPItemStraightLine(m_plot);
    m_triggerLine->setPen(QPen(Qt::darkRed, 1, Qt::DashLine));
    m_triggerLine->setVisible(false);
    m_triggerLabel = new QCPItemText(m_plot);
    m_triggerLabel->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    m_triggerLabel->setPositionAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_triggerLabel->setColor(Qt::darkRed);
    m_triggerLabel->setText(tr("Trigger"));
    m_triggerLabel->setVisible(false);
    m_cursorTable = new ScopeCursorTable(this);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_cursorTable);

    m_refreshTimer.setSingleShot(true);
    m_refreshTimer.setInterval(qRound(1000.0 / m_refreshHz));
    connect(&m_refreshTimer, &QTimer::timeout, this, &ScopeChart::redrawNow);
    // What the user or the API changed is drawn with the next pass of the event loop. Not
    // QCustomPlot's queued replot: that one cannot be called off when redrawNow() came first.
    m_soonTimer.setSingleShot(true);
    m_soonTimer.setInterval(0);
    connect(&m_soonTimer, &QTimer::timeout, this, &ScopeChart::redrawNow);
    // Every replot, the chart's own or one of QCustomPlot's after a drag or a wheel turn,
    // draws up-to-date points.
    connect(m_plot, &QCustomPlot::beforeReplot, this, &ScopeChart::refreshData);
    connect(m_plot, &QCustomPlot::afterLayout, this, &ScopeChart::layoutDone);
    connect(m_plot, &QCustomPlot::mouseWheel, this, &ScopeChart::wheelTurned);
    connect(m_plot, &QCustomPlot::mousePress, this, &ScopeChart::mousePressed);
    connect(m_plot->xAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
            &ScopeChart::timeRangeChanged);
    connect(m_cursors, &ScopeCursors::moved, this, [this] {
        updateReadout();
        replotSoon();
    });
    connectValueAxes();
}

ScopeChart::~ScopeChart() = default;

void ScopeChart::setMathSeries(const QList<std::shared_ptr<const ScopeSeries>> &series,
                               const QList<std::shared_ptr<const ScopeSeriesLevels>> &levels)
{
    m_math->setSeries(series, levels);
    showCursorTable();
    m_dataStale = true;
    replotSoon();
}

QList<std::shared_ptr<const ScopeSeries>> ScopeChart::mathSeries() const
{
    return m_math->series();
}

void ScopeChart::setRecording(const ScopeRecording *recording)
{
    m_recording = recording;
    m_triggerMs = recording ? recording->triggerMs : std::nullopt;
    if (m_frozenCount)
        m_frozenCount = recording ? recording->buffer.count() : 0;
    reread(true);
}

void ScopeChart::recordingChanged()
{
    reread(false);
}

void ScopeChart::reread(bool newRecording)
{
    const qsizetype count = m_recording ? m_recording->buffer.count() : 0;
    const bool restarted = newRecording || count < m_filledCount
        || (m_recording && m_recording->firstTime() != m_originMs);
    if (m_frozenCount)
        m_frozenCount = std::min(*m_frozenCount, count);
    m_traces->setChannels(m_recording ? m_recording->channels : ScopeChannels(kChannels));
    followOrigin();
    if (restarted)
        m_traces->forgetColumns();
    if (restarted && m_view == View::Fixed)
        setView(View::All);
    m_dataStale = true;
    applyView();
    updateReadout();
    replotSoon();
}

void ScopeChart::samplesAppended()
{
    if (!m_recording || isFrozen())
        return;
    m_dataStale = true;
    scheduleRedraw();
}

void ScopeChart::setRefreshRate(int hz)
{
    m_refreshHz = std::clamp(hz, kMinRefreshHz, kMaxRefreshHz);
    m_refreshTimer.setInterval(qRound(1000.0 / m_refreshHz));
}

void ScopeChart::redrawNow()
{
    m_refreshTimer.stop();
    m_soonTimer.stop();
    // Directly, not queued: the timer has already coalesced the samples of a tick.
    m_plot->replot(QCustomPlot::rpRefreshHint);
}

void ScopeChart::replotSoon()
{
    m_soonTimer.start();
}

void ScopeChart::scheduleRedraw()
{
    if (!m_refreshTimer.isActive())
        m_refreshTimer.start();
}

void ScopeChart::setFrozen(bool frozen)
{
    if (frozen == isFrozen())
        return;
    if (frozen) {
        m_frozenCount = m_recording ? m_recording->buffer.count() : 0;
    } else {
        m_frozenCount.reset();
        m_dataStale = true;
        updateReadout();
        scheduleRedraw();
    }
    emit frozenChanged(frozen);
}

void ScopeChart::setChannelVisible(int channel, bool visible)
{
    m_traces->setVisible(channel, visible);
    m_dataStale = true;
    updateReadout();
    replotSoon();
}

bool ScopeChart::isChannelVisible(int channel) const
{
    return m_traces->isVisible(channel);
}

void ScopeChart::setChannelColor(int channel, const QColor &color)
{
    m_traces->setColor(channel, color);
    replotSoon();
}

QColor ScopeChart::channelColor(int channel) const
{
    return m_traces->color(channel);
}

void ScopeChart::setChannelOwnAxis(int channel, bool own)
{
    {
        const QScopedValueRollback guard(m_settingRanges, m_settingRanges + 1);
        m_traces->setOwnAxis(channel, own);
    }
    connectValueAxes();
    if (m_autoScale)
        fitValueAxes();
    replotSoon();
}

bool ScopeChart::hasChannelOwnAxis(int channel) const
{
    return m_traces->hasOwnAxis(channel);
}

void ScopeChart::setCursorTime(int which, std::optional<double> timeMs)
{
    m_cursors->setTime(which, timeMs);
    updateReadout();
    replotSoon();
}

std::optional<double> ScopeChart::cursorTime(int which) const
{
    return m_cursors->time(which);
}

void ScopeChart::setTriggerTime(std::optional<qint64> timeMs)
{
    m_triggerMs = timeMs;
    placeTriggerMark();
    replotSoon();
}

void ScopeChart::placeTriggerMark()
{
    m_triggerLine->setVisible(m_triggerMs.has_value());
    m_triggerLabel->setVisible(m_triggerMs.has_value());
    if (!m_triggerMs)
        return;
    const double seconds = double(*m_triggerMs - m_originMs) / 1000.0;
    m_triggerLine->point1->setCoords(seconds, 0);
    m_triggerLine->point2->setCoords(seconds, 1);
    m_triggerLabel->position->setCoords(seconds, 0);
}

QCPGraph *ScopeChart::graph(int channel) const
{
    return m_traces->graph(channel);
}

QCPAxis *ScopeChart::valueAxis(int channel) const
{
    return m_traces->valueAxis(channel);
}

void ScopeChart::connectValueAxes()
{
    const QList<QCPAxis *> valueAxes = m_traces->valueAxes();
    for (QCPAxis *axis : valueAxes) {
        connect(axis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
                &ScopeChart::valueRangeChanged, Qt::UniqueConnection);
    }
    m_plot->axisRect()->setRangeDragAxes({ m_plot->xAxis }, valueAxes);
    m_plot->axisRect()->setRangeZoomAxes({ m_plot->xAxis }, valueAxes);
}

void ScopeChart::followOrigin()
{
    const qint64 origin = m_recording ? m_recording->firstTime() : 0;
    if (origin == m_originMs)
        return;
    m_originMs = origin;
    m_cursors->setOriginMs(origin);
    placeTriggerMark();
}

void ScopeChart::refreshData()
{
    if (!m_recording) {
        m_traces->clear();
        m_math->clear();
        m_overlay->clear();
        m_dataStale = false;
        return;
    }
    followOrigin();
    applyView();
    m_overlay->follow(*m_recording, *m_traces);
    // About one column a pixel; the layout of the last replot tells the axis rect's width.
    const int columns = std::max(1, m_plot->axisRect()->width());
    if (!m_dataStale && columns == m_filledColumns)
        return;
    const QCPRange range = m_plot->xAxis->range();
    ScopeTraceWindow window;
    window.originMs = m_originMs;
    window.fromMs = qint64(std::floor(double(m_originMs) + range.lower * 1000.0));
    window.toMs = qint64(std::ceil(double(m_originMs) + range.upper * 1000.0));
    window.columns = columns;
    window.sampleCount = shownSampleCount();
    m_traces->fill(*m_recording, window);
    m_math->fill(window);
    m_overlay->fill(*m_recording, window);
    m_dataStale = false;
    m_filledColumns = columns;
    m_filledCount = m_recording->buffer.count();
    if (m_autoScale)
        fitValueAxes();
    updateReadout();
}

void ScopeChart::fitLegend()
{
    // The names in one row while they fit, two to a row otherwise, one to a row on a narrow
    // chart (beside the telegram monitor): never cut.
    QCPLegend *legend = m_plot->legend;
    QList<int> widths;
    for (int i = 0; i < legend->itemCount(); ++i) {
        // A cell of the grid may be empty.
        if (const QCPAbstractLegendItem *item = legend->item(i))
            widths << item->minimumOuterSizeHint().width() + legend->columnSpacing();
    }
    const int room = m_plot->width() - legend->margins().left() - legend->margins().right();
    const auto fits = [&widths, room](qsizetype perRow) {
        for (qsizetype first = 0; first < widths.size(); first += perRow) {
            int row = 0;
            for (qsizetype i = first; i < std::min(first + perRow, widths.size()); ++i)
                row += widths.at(i);
            if (row > room)
                return false;
        }
        return true;
    };
    const int wrap = fits(std::max<qsizetype>(widths.size(), 1)) ? 0 : fits(2) ? 2 : 1;
    if (wrap == legend->wrap())
        return;
    legend->setWrap(wrap);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    replotSoon();
}

void ScopeChart::layoutDone()
{
    fitLegend();
    // The axis rect changed width (a resize, wider tick labels): one column a pixel again.
    if (m_recording && m_plot->axisRect()->width() != m_filledColumns) {
        m_dataStale = true;
        refreshData();
    }
}

void ScopeChart::updateReadout()
{
    ScopeCursorReadout readout;
    readout.timeMs = m_cursors->times();
    if (m_recording) {
        readout = readScopeCursors(*m_recording, m_cursors->times(), m_traces->drawnChannels(),
                                   shownSampleCount());
    }
    if (!readOverlay() && readout == m_readout)
        return;
    m_readout = readout;
    showCursorTable();
    emit cursorsChanged(m_readout);
}

void ScopeChart::showCursorTable()
{
    m_cursorTable->showReadout(m_readout,
                               m_recording ? m_recording->channels : ScopeChannels(kChannels),
                               m_math->series(), m_overlayReadout,
                               m_overlay->overlay() ? m_overlay->overlay()->recording().channels
                                                    : ScopeChannels());
}

qsizetype ScopeChart::shownSampleCount() const
{
    if (!m_recording)
        return 0;
    const qsizetype count = m_recording->buffer.count();
    return m_frozenCount ? std::min(*m_frozenCount, count) : count;
}

} // namespace DriveDesk
