// The scope chart's redraws (offscreen, 1600 x 900): the whole recording of 4 x 1,000,000 and
// 4 x 3,600,000 samples, shown anew; the same million fed to QCustomPlot point by point, for comparison;
// and the roll mode's redraw tick while 4 kHz samples come in, synchronously and on the event
// loop with a direct or a queued replot; the full view and the roll tick again with a math
// channel (a derivative, on an axis of its own); and both once more with an overlay of another
// 4 x 1,000,000 samples read from a recording file, with and without the math channel. Prints
// figures; asserts nothing.
// Goals: the full view <= 8 ms (and no slower for 3.6 million), a roll tick <= 2 ms.
#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeColumnGrid.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeMath.h"
#include "scope/ScopeSeriesLevels.h"
#include "scope/ScopeOverlay.h"
#include "scope/ScopeTraces.h"

#include <QAbstractEventDispatcher>
#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace DriveDesk;

namespace {

constexpr QSize kSize(1600, 900);
constexpr int kRounds = 20;
constexpr int kSamplesPerSecond = 4000;
constexpr int kTickHz = 30;
constexpr int kTicks = 300;

// Four channels that look like a drive's: a noisy sine in 0.01 Hz, a slow ramp, a square
// wave with noise, and rare single-sample spikes.
class SignalSource
{
public:
    ScopeSample sample(qsizetype i, qint64 timeMs)
    {
        m_noise = m_noise * 1664525u + 1013904223u;
        const qint32 noise = qint32(m_noise >> 24) - 128;
        ScopeSample sample;
        sample.time = timeMs;
        sample.wide
            = { qint32(5000 * std::sin(double(i) * 0.0007)) + noise, qint32(i % 2'000'000) };
        sample.narrow = { qint16((i / 5000) % 2 ? 1000 + noise : -1000 + noise),
                          qint16(i % 99'991 == 0 ? 30000 : noise / 16) };
        return sample;
    }

private:
    quint32 m_noise = 12345;
};

// A recording of `count` samples at `perSecond` a second (several share a ms above 1 kHz).
void fill(ScopeRecording &recording, qsizetype count, int perSecond, SignalSource &source)
{
    for (qsizetype i = recording.buffer.count(); i < count; ++i)
        recording.buffer.append(source.sample(i, i * 1000 / perSecond));
}

void describe(ScopeRecording &recording)
{
    recording.channels[0].source = 0x0203;
    recording.channels[0].id = QStringLiteral("ru.03");
    recording.channels[0].name = QStringLiteral("Actual frequency");
    recording.channels[0].scaling
        = DisplayScaling(DisplayScalingData { 0x0203, 100, 1, 0, quint16(18 | (2 << 8)) });
}

struct Figures
{
    double median = 0;
    double max = 0;
};

Figures figures(std::vector<double> ms)
{
    std::sort(ms.begin(), ms.end());
    return { ms[ms.size() / 2], ms.back() };
}

template<typename Work> Figures timeRounds(int rounds, Work work)
{
    std::vector<double> ms;
    QElapsedTimer timer;
    for (int round = 0; round < rounds; ++round) {
        timer.start();
        work();
        ms.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    return figures(ms);
}

// The chart's decimation alone: the column grid and each channel's min/max per column; and
// for comparison MinMaxPyramid::decimateTime() per channel, which searches every column's
// boundary anew for each channel.
struct Decimation
{
    Figures grid;
    Figures decimateTime;
};

Decimation decimation(const ScopeRecording &recording, ScopeTimeRange range, int columns)
{
    const ScopeBuffer &buffer = recording.buffer;
    qint64 sink = 0;
    Decimation result;
    result.grid = timeRounds(kRounds, [&] {
        const ScopeColumnGrid grid(buffer.samples(), range.fromMs, range.toMs, columns,
                                   buffer.count());
        for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
            for (int column = 0; column < grid.count(); ++column) {
                if (!grid.isEmpty(column))
                    sink += grid.column(buffer.pyramid(), channel, column).max;
            }
        }
    });
    result.decimateTime = timeRounds(kRounds, [&] {
        for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
            for (const auto &column :
                 buffer.decimateTime(channel, range.fromMs, range.toMs, columns))
                sink += column.max;
        }
    });
    if (sink == 42)
        std::printf(" ");
    return result;
}

// A derivative of channel 1 and its min/max levels: what the window computes in the thread
// pool, drawn by the chart. BENCH_MATH_NO_LEVELS=1: without the levels (every value in view
// scanned a redraw), for comparison.
void addMath(ScopeChart &chart, const ScopeRecording &recording)
{
    ScopeMathResult derivative = computeScopeMath(ScopeMathDefinition(), recording);
    auto series = std::make_shared<const ScopeSeries>(std::move(derivative.series));
    if (qEnvironmentVariableIntValue("BENCH_MATH_NO_LEVELS") != 0) {
        chart.setMathSeries({ series });
        return;
    }
    auto levels = std::make_shared<const ScopeSeriesLevels>(*series);
    chart.setMathSeries({ series }, { levels });
}

// A second recording of 4 x 1,000,000 samples at 1 kHz (another run: the source starts
// elsewhere), its trigger at 400 s, written to a file and read back as the window reads an
// overlay.
std::shared_ptr<const ScopeOverlay> makeOverlay()
{
    SignalSource source;
    ScopeRecording recording;
    describe(recording);
    for (qsizetype i = 0; i < 1'000'000; ++i)
        recording.buffer.append(source.sample(i + 12345, i));
    recording.triggerMs = 400'000;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("earlier.ddscope"));
    ScopeFileWriter writer;
    const SampleStore &samples = recording.buffer.samples();
    if (!writer.open(path, ScopeFileHeader::of(recording))
        || !writer.append(samples, 0, samples.count()) || !writer.close())
        qFatal("cannot write the overlay's file");
    auto overlay = std::make_shared<const ScopeOverlay>(ScopeOverlay::load(path));
    if (!overlay->isLoaded())
        qFatal("%s", qPrintable(overlay->error()));
    return overlay;
}

// (a) The whole recording, decimated anew each time (as after new samples).
void fullView(qsizetype count, bool withMath = false,
              std::shared_ptr<const ScopeOverlay> overlay = nullptr)
{
    SignalSource source;
    ScopeRecording recording;
    describe(recording);
    fill(recording, count, 1000, source);
    // A shot's trigger, on which an overlay is aligned: 100 s after the overlay's.
    if (overlay)
        recording.triggerMs = 500'000;
    ScopeChart chart;
    chart.resize(kSize);
    chart.show();
    chart.setRecording(&recording);
    chart.showAll();
    if (withMath)
        addMath(chart, recording);
    if (overlay)
        chart.setOverlay(overlay);
    QCustomPlot *plot = chart.plot();
    plot->replot(QCustomPlot::rpImmediateRefresh);

    const Figures full = timeRounds(kRounds, [&] {
        // Shown anew: every column decimated again (a view that only went stale would take
        // its columns over from the last redraw, ScopeColumnMemo).
        chart.setRecording(&recording);
        plot->replot(QCustomPlot::rpImmediateRefresh);
    });
    const Figures drawOnly
        = timeRounds(kRounds, [&] { plot->replot(QCustomPlot::rpImmediateRefresh); });
    const int columns = plot->axisRect()->width();
    const Decimation parts = decimation(recording, chart.visibleTimeRange(), columns);
    int points = 0;
    for (int channel = 0; channel < ScopeChart::kChannels; ++channel)
        points += chart.graph(channel)->data()->size();
    std::printf("full view, 4 x %lld samples%s%s: %.2f ms median, %.2f ms max (goal <= 8 ms)\n"
                "  decimation %.2f ms (decimateTime per channel: %.2f ms), replot without new "
                "data %.2f ms, %d points for %d columns\n",
                qlonglong(count), withMath ? " and a math channel" : "",
                overlay ? ", an overlay of 4 x 1,000,000" : "", full.median, full.max,
                parts.grid.median, parts.decimateTime.median, drawOnly.median, points, columns);
}

// (b) QCustomPlot given every sample of 4 x 1,000,000.
void everyPoint(bool adaptiveSampling, int rounds)
{
    constexpr qsizetype kCount = 1'000'000;
    SignalSource source;
    QCustomPlot plot;
    plot.resize(kSize);
    plot.show();
    // Drawn as the chart draws: no antialiasing, one paint buffer.
    plot.setNotAntialiasedElements(QCP::aeAll);
    plot.layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    QVector<double> keys(kCount);
    std::array<QVector<double>, ScopeChart::kChannels> values;
    for (auto &channel : values)
        channel.resize(kCount);
    for (qsizetype i = 0; i < kCount; ++i) {
        const ScopeSample sample = source.sample(i, i);
        keys[i] = double(i) / 1000.0;
        for (int channel = 0; channel < ScopeChart::kChannels; ++channel)
            values[channel][i] = sample.channel(channel);
    }
    for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
        QCPGraph *graph = plot.addGraph();
        graph->setAdaptiveSampling(adaptiveSampling);
        graph->setPen(QPen(ScopeTraces::defaultColor(channel)));
    }
    const Figures setData = timeRounds(rounds, [&] {
        for (int channel = 0; channel < ScopeChart::kChannels; ++channel)
            plot.graph(channel)->setData(keys, values[channel], true);
    });
    plot.rescaleAxes();
    const Figures replot
        = timeRounds(rounds, [&] { plot.replot(QCustomPlot::rpImmediateRefresh); });
    std::printf("every point, 4 x %lld, adaptive sampling %s: setData %.1f ms, replot %.1f ms "
                "median (%.1f ms max, %d runs)\n",
                qlonglong(kCount), adaptiveSampling ? "on " : "off", setData.median, replot.median,
                replot.max, rounds);
}

// (c) Roll mode, 10 s, 1,000,000 samples there already: a tick's samples, then its redraw.
void rollTicks(bool withMath = false, std::shared_ptr<const ScopeOverlay> overlay = nullptr)
{
    SignalSource source;
    ScopeRecording recording;
    describe(recording);
    fill(recording, 1'000'000, kSamplesPerSecond, source);
    ScopeChart chart;
    chart.resize(kSize);
    chart.show();
    chart.setRecording(&recording);
    chart.setRollSeconds(10);
    // Computed once here; the window computes it again in the thread pool as samples come.
    if (withMath)
        addMath(chart, recording);
    // A recording that runs has no trigger yet: the overlay is drawn from its start.
    if (overlay)
        chart.setOverlay(overlay);
    chart.plot()->replot(QCustomPlot::rpImmediateRefresh);

    std::vector<double> ms;
    QElapsedTimer timer;
    for (int tick = 1; tick <= kTicks; ++tick) {
        // 133 or 134 samples: 4,000 a second at 30 ticks a second.
        fill(recording, 1'000'000 + qsizetype(tick) * kSamplesPerSecond / kTickHz,
             kSamplesPerSecond, source);
        timer.start();
        chart.samplesAppended();
        chart.plot()->replot(QCustomPlot::rpImmediateRefresh);
        ms.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    const Figures tick = figures(ms);
    const Figures drawOnly
        = timeRounds(kRounds, [&] { chart.plot()->replot(QCustomPlot::rpImmediateRefresh); });
    const Decimation parts
        = decimation(recording, chart.visibleTimeRange(), chart.plot()->axisRect()->width());
    std::printf("roll tick, 10 s of 4 kHz after 1,000,000 samples%s%s, %d ticks of %d samples: "
                "%.2f ms median, %.2f ms max (goal <= 2 ms)\n"
                "  decimation %.2f ms (decimateTime per channel: %.2f ms), replot without new "
                "data %.2f ms\n",
                withMath ? " and a math channel" : "",
                overlay ? ", an overlay of 4 x 1,000,000" : "", kTicks, kSamplesPerSecond / kTickHz,
                tick.median, tick.max, parts.grid.median,
                parts.decimateTime.median, drawOnly.median);
}

// (d) The same on the event loop, a 30 Hz tick replotting directly or queued: the time from the
// tick until the event loop waits again after the replot (the samples appended, the replot,
// the widget painted).
void rollOnEventLoop(QApplication &app, bool queued)
{
    SignalSource source;
    ScopeRecording recording;
    describe(recording);
    fill(recording, 1'000'000, kSamplesPerSecond, source);
    ScopeChart chart;
    chart.resize(kSize);
    chart.show();
    chart.setRecording(&recording);
    chart.setRollSeconds(10);
    QCustomPlot *plot = chart.plot();

    QElapsedTimer clock;
    clock.start();
    qint64 tickAt = -1;
    bool replotted = false;
    std::vector<double> busy;
    QObject::connect(plot, &QCustomPlot::afterReplot, [&] { replotted = true; });
    // A queued replot comes with a later pass of the loop: wait for the replot first.
    QObject::connect(QAbstractEventDispatcher::instance(), &QAbstractEventDispatcher::aboutToBlock,
                     [&] {
                         if (tickAt < 0 || !replotted)
                             return;
                         busy.push_back(double(clock.nsecsElapsed() - tickAt) / 1e6);
                         tickAt = -1;
                     });
    QTimer ticker;
    ticker.setTimerType(Qt::PreciseTimer);
    ticker.setInterval(1000 / kTickHz);
    int tick = 0;
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        if (++tick > kTicks / 2) {
            app.quit();
            return;
        }
        tickAt = clock.nsecsElapsed();
        replotted = false;
        fill(recording, 1'000'000 + qsizetype(tick) * kSamplesPerSecond / kTickHz,
             kSamplesPerSecond, source);
        // The chart's own tick replots directly (ScopeChart::redrawNow()). A roll view moves
        // on with the samples, so a replot alone decimates anew.
        plot->replot(queued ? QCustomPlot::rpQueuedReplot : QCustomPlot::rpRefreshHint);
    });
    ticker.start();
    app.exec();
    const Figures ticks = figures(busy);
    std::printf("roll on the event loop, %s replot, %d ticks at %d Hz: %.2f ms from the tick "
                "to an idle loop, median, %.2f ms max\n",
                queued ? "queued" : "direct", kTicks / 2, kTickHz, ticks.median, ticks.max);
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);

    // Parts by name (full, every, roll, loop, math, overlay, and the roll ticks alone:
    // mathroll, overlayroll); all without one.
    const QStringList parts = app.arguments().mid(1);
    const auto wanted
        = [&](const char *part) { return parts.isEmpty() || parts.contains(QLatin1String(part)); };
    if (wanted("full")) {
        fullView(1'000'000);
        fullView(3'600'000);
    }
    if (wanted("every")) {
        everyPoint(true, 5);
        everyPoint(false, 1);
    }
    if (wanted("roll"))
        rollTicks();
    if (wanted("math")) {
        fullView(1'000'000, true);
        rollTicks(true);
    }
    if (wanted("overlay")) {
        const std::shared_ptr<const ScopeOverlay> overlay = makeOverlay();
        fullView(1'000'000, true, overlay);
        rollTicks(true, overlay);
        // The overlay's own part, without the math channel.
        fullView(1'000'000, false, overlay);
        rollTicks(false, overlay);
    }
    if (parts.contains(QLatin1String("mathroll")))
        rollTicks(true);
    if (parts.contains(QLatin1String("overlayroll")))
        rollTicks(true, makeOverlay());
    if (wanted("loop")) {
        rollOnEventLoop(app, false);
        rollOnEventLoop(app, true);
    }
    return 0;
}
