#include "ScopeChart.h"

#include "ScopeCursorTable.h"
#include "ScopeCursors.h"
#include "ScopeTraces.h"

#include "QCustomPlotInclude.h"

#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace DriveDesk {

namespace {

constexpr double kFitMargin = 0.05; // of the data's span, above and below, when fitting values

// Holds a counter up while the chart sets axis ranges itself, so that their rangeChanged
// tells a user's zoom from the chart's.
class RangeGuard
{
public:
    explicit RangeGuard(int &depth)
        : m_depth(depth)
    {
        ++m_depth;
    }
    ~RangeGuard() { --m_depth; }
    RangeGuard(const RangeGuard &) = delete;
    RangeGuard &operator=(const RangeGuard &) = delete;

private:
    int &m_depth;
};

} // namespace

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
    m_plot->legend->setVisible(true);
    m_plot->legend->setBrush(QColor(255, 255, 255, 220));
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    m_plot->setMouseTracking(true);
    m_plot->setFocusPolicy(Qt::StrongFocus);
    m_plot->setToolTip(helpText());
    setFocusProxy(m_plot);

    m_traces = std::make_unique<ScopeTraces>(m_plot);
    m_cursors = new ScopeCursors(m_plot);
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

void ScopeChart::setRecording(const ScopeRecording *recording)
{
    m_recording = recording;
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
        const RangeGuard guard(m_settingRanges);
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

QCPGraph *ScopeChart::graph(int channel) const
{
    return m_traces->graph(channel);
}

QCPAxis *ScopeChart::valueAxis(int channel) const
{
    return m_traces->valueAxis(channel);
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
    const RangeGuard guard(m_settingRanges);
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
}

void ScopeChart::refreshData()
{
    if (!m_recording) {
        m_traces->clear();
        m_dataStale = false;
        return;
    }
    followOrigin();
    applyView();
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
    m_dataStale = false;
    m_filledColumns = columns;
    m_filledCount = m_recording->buffer.count();
    if (m_autoScale)
        fitValueAxes();
    updateReadout();
}

void ScopeChart::layoutDone()
{
    // The axis rect changed width (a resize, wider tick labels): one column a pixel again.
    if (m_recording && m_plot->axisRect()->width() != m_filledColumns) {
        m_dataStale = true;
        refreshData();
    }
}

void ScopeChart::fitValueAxes()
{
    const RangeGuard guard(m_settingRanges);
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
        if (!span)
            continue;
        const double margin = span->high > span->low
            ? (span->high - span->low) * kFitMargin
            : std::max(std::abs(span->high) * kFitMargin, 0.5);
        axis->setRange(span->low - margin, span->high + margin);
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
    if (readout == m_readout)
        return;
    m_readout = readout;
    m_cursorTable->showReadout(m_readout,
                               m_recording ? m_recording->channels : ScopeChannels(kChannels));
    emit cursorsChanged(m_readout);
}

qsizetype ScopeChart::shownSampleCount() const
{
    if (!m_recording)
        return 0;
    const qsizetype count = m_recording->buffer.count();
    return m_frozenCount ? std::min(*m_frozenCount, count) : count;
}

} // namespace DriveDesk
