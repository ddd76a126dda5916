#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeColumnGrid.h"
#include "scope/ScopeCursorTable.h"

#include <QApplication>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <limits>

using namespace DriveDesk;

namespace {

constexpr qint64 kStartMs = 5000; // the first sample's time: the chart counts from here
constexpr qsizetype kSpikeAt = 654'321;
constexpr qint32 kSpike = 1'000'000;
constexpr qint16 kDip = -30'000;

// Channel 0 in Hz with two decimals (raw 1 = 0.01 Hz); the others unknown, shown raw.
void describeChannels(ScopeRecording &recording)
{
    ScopeChannel &frequency = recording.channels[0];
    frequency.source = 0x0203;
    frequency.id = QStringLiteral("ru.03");
    frequency.name = QStringLiteral("Actual frequency");
    frequency.scaling
        = DisplayScaling(DisplayScalingData { 0x0203, 100, 1, 0, quint16(18 | (2 << 8)) });
}

// One sample a ms from kStartMs: small patterns, one spike on channel 0 and one dip on
// channel 3, a single sample each in a million.
void fill(ScopeRecording &recording, qsizetype count)
{
    ScopeSample sample;
    for (qsizetype i = recording.buffer.count(); i < count; ++i) {
        sample.time = kStartMs + i;
        sample.wide = { i == kSpikeAt ? kSpike : qint32(i % 7), qint32(i % 1000) };
        sample.narrow = { qint16(i % 100 - 50), i == kSpikeAt + 1000 ? kDip : qint16(i % 5) };
        QVERIFY(recording.buffer.append(sample));
    }
}

double maxValue(const QCPGraph *graph)
{
    double result = -std::numeric_limits<double>::infinity();
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        result = std::max(result, it->value);
    return result;
}

double minValue(const QCPGraph *graph)
{
    double result = std::numeric_limits<double>::infinity();
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        result = std::min(result, it->value);
    return result;
}

double lastKey(const QCPGraph *graph)
{
    return graph->data()->isEmpty() ? 0 : (graph->data()->constEnd() - 1)->key;
}

QPoint plotPoint(const ScopeChart &chart, double seconds)
{
    const QRect rect = chart.plot()->axisRect()->rect();
    return { int(std::lround(chart.plot()->xAxis->coordToPixel(seconds))), rect.center().y() };
}

void turnWheel(ScopeChart &chart, Qt::KeyboardModifiers modifiers)
{
    const QPointF at = chart.plot()->axisRect()->rect().center();
    QWheelEvent wheel(at, chart.plot()->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      modifiers, Qt::NoScrollPhase, false);
    QApplication::sendEvent(chart.plot(), &wheel);
}

void sendMouse(ScopeChart &chart, QEvent::Type type, QPoint at, Qt::MouseButton button,
               Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    const Qt::MouseButtons buttons = type == QEvent::MouseButtonRelease ? Qt::NoButton : button;
    QMouseEvent event(type, at, chart.plot()->mapToGlobal(at),
                      type == QEvent::MouseMove ? Qt::NoButton : button, buttons, modifiers);
    QApplication::sendEvent(chart.plot(), &event);
}

} // namespace

// The scope chart on a recording it reads through its min/max levels (offscreen).
class TestScopeChart : public QObject
{
    Q_OBJECT

private:
    // A chart of a recording of `count` samples, shown and drawn once.
    std::unique_ptr<ScopeChart> shownChart(const ScopeRecording &recording)
    {
        auto chart = std::make_unique<ScopeChart>();
        chart->resize(1000, 500);
        chart->show();
        if (!QTest::qWaitForWindowExposed(chart.get()))
            return nullptr;
        chart->setRecording(&recording);
        chart->redrawNow();
        return chart;
    }

private slots:
    void everyPeakSurvivesTheFullView()
    {
        ScopeRecording recording;
        describeChannels(recording);
        fill(recording, 1'000'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        chart->showAll();
        chart->redrawNow();

        QCOMPARE(chart->visibleTimeRange(), (ScopeTimeRange { kStartMs, kStartMs + 999'999 }));
        // Scaled: raw 1,000,000 is 10,000.00 Hz.
        QCOMPARE(maxValue(chart->graph(0)), 10'000.0);
        QCOMPARE(minValue(chart->graph(3)), double(kDip));
        QCOMPARE(maxValue(chart->graph(1)), 999.0);
        // About two points a pixel column, whatever the million samples.
        const int width = chart->plot()->axisRect()->width();
        for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
            const int points = chart->graph(channel)->data()->size();
            QVERIFY2(points > width && points <= 2 * width + 4,
                     qPrintable(QStringLiteral("%1 points, %2 px").arg(points).arg(width)));
        }
        // The values axis is fitted to what is drawn, the spike included.
        QVERIFY(chart->autoScales());
        QVERIFY(chart->plot()->yAxis->range().contains(10'000.0));
        QVERIFY(chart->plot()->yAxis->range().contains(kDip));

        // Zoomed in to a few ms the samples themselves are drawn, at their times.
        chart->showTimeRange(kStartMs + kSpikeAt - 5, kStartMs + kSpikeAt + 5);
        chart->redrawNow();
        QCOMPARE(maxValue(chart->graph(0)), 10'000.0);
        const QCPGraphData spike = *std::max_element(
            chart->graph(0)->data()->constBegin(), chart->graph(0)->data()->constEnd(),
            [](const QCPGraphData &a, const QCPGraphData &b) { return a.value < b.value; });
        QCOMPARE(spike.key, kSpikeAt / 1000.0);
        QVERIFY(chart->graph(0)->data()->size() <= 11 + 2);
    }

    void rollModeFollowsAppendedSamplesOnTheTimer()
    {
        ScopeRecording recording;
        fill(recording, 20'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        QVERIFY(chart->follows());
        chart->setRollSeconds(5);
        chart->redrawNow();
        QCOMPARE(chart->visibleTimeRange(),
                 (ScopeTimeRange { kStartMs + 14'999, kStartMs + 19'999 }));
        // The last column's min and max stand in its middle, within a few ms of its end.
        QVERIFY(lastKey(chart->graph(1)) > 19.99 && lastKey(chart->graph(1)) <= 19.999);

        fill(recording, 23'000);
        chart->samplesAppended();
        chart->samplesAppended();
        // Appending only marks the chart stale; the refresh timer draws.
        QVERIFY(lastKey(chart->graph(1)) <= 19.999);
        QSignalSpy replots(chart->plot(), &QCustomPlot::afterReplot);
        QTRY_VERIFY(lastKey(chart->graph(1)) > 22.99);
        QCOMPARE(replots.count(), 1);
        QCOMPARE(chart->visibleTimeRange(),
                 (ScopeTimeRange { kStartMs + 17'999, kStartMs + 22'999 }));
        QCOMPARE(chart->refreshRate(), ScopeChart::kDefaultRefreshHz);
    }

    void aShortRecordingRollsFromItsStart()
    {
        ScopeRecording recording;
        fill(recording, 2'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        QCOMPARE(chart->visibleTimeRange(), (ScopeTimeRange { kStartMs, kStartMs + 10'000 }));
    }

    void aManualZoomLeavesRollMode()
    {
        ScopeRecording recording;
        fill(recording, 20'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        QSignalSpy follow(chart.get(), &ScopeChart::followChanged);
        QSignalSpy autoScale(chart.get(), &ScopeChart::autoScaleChanged);

        // Ctrl+wheel zooms the values only: the time keeps rolling, the fitting stops.
        const QCPRange values = chart->plot()->yAxis->range();
        turnWheel(*chart, Qt::ControlModifier);
        QVERIFY(chart->plot()->yAxis->range().size() < values.size());
        QVERIFY(chart->follows());
        QCOMPARE(autoScale.count(), 1);
        QCOMPARE(autoScale.at(0).at(0).toBool(), false);

        const QCPRange time = chart->plot()->xAxis->range();
        turnWheel(*chart, Qt::NoModifier);
        QVERIFY(chart->plot()->xAxis->range().size() < time.size());
        QVERIFY(!chart->follows());
        QCOMPARE(follow.count(), 1);
        QCOMPARE(follow.at(0).at(0).toBool(), false);

        // New samples no longer move the view.
        const ScopeTimeRange zoomed = chart->visibleTimeRange();
        fill(recording, 21'000);
        chart->samplesAppended();
        chart->redrawNow();
        QCOMPARE(chart->visibleTimeRange(), zoomed);

        // End follows again, Home shows the whole recording, A fits the values.
        QTest::keyClick(chart->plot(), Qt::Key_End);
        QVERIFY(chart->follows());
        QCOMPARE(chart->visibleTimeRange().toMs, kStartMs + 20'999);
        QTest::keyClick(chart->plot(), Qt::Key_Home);
        QVERIFY(chart->showsAll());
        QCOMPARE(follow.count(), 3);
        QCOMPARE(chart->visibleTimeRange(), (ScopeTimeRange { kStartMs, kStartMs + 20'999 }));
        QTest::keyClick(chart->plot(), Qt::Key_A);
        QVERIFY(chart->autoScales());
        QVERIFY(chart->plot()->yAxis->range().contains(999));

        // Keys zoom and pan the time and leave the whole view.
        QTest::keyClick(chart->plot(), Qt::Key_Plus);
        QVERIFY(!chart->showsAll());
        const ScopeTimeRange half = chart->visibleTimeRange();
        QVERIFY(qAbs((half.toMs - half.fromMs) - 10'500) <= 2);
        QTest::keyClick(chart->plot(), Qt::Key_Right);
        QVERIFY(chart->visibleTimeRange().fromMs > half.fromMs);

        // A drag moves the time.
        chart->setFollow(true);
        chart->redrawNow();
        QVERIFY(chart->follows());
        const QPoint from = chart->plot()->axisRect()->rect().center();
        sendMouse(*chart, QEvent::MouseButtonPress, from, Qt::LeftButton);
        sendMouse(*chart, QEvent::MouseMove, from + QPoint(100, 0), Qt::LeftButton);
        sendMouse(*chart, QEvent::MouseButtonRelease, from + QPoint(100, 0), Qt::LeftButton);
        QVERIFY(!chart->follows());
    }

    void cursorsReadTheSamplesAtOrBeforeThem()
    {
        ScopeRecording recording;
        describeChannels(recording);
        // Uneven times: 5000, 5003, 5003, 5010, 5020 ms.
        const QList<qint64> times { 5000, 5003, 5003, 5010, 5020 };
        for (int i = 0; i < times.size(); ++i) {
            ScopeSample sample;
            sample.time = times[i];
            sample.wide = { qint32(1234 + i), qint32(-i) };
            sample.narrow = { qint16(10 * i), qint16(0) };
            QVERIFY(recording.buffer.append(sample));
        }
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        chart->showAll();
        QVERIFY(!chart->cursorTable()->isVisible());
        QSignalSpy changed(chart.get(), &ScopeChart::cursorsChanged);

        chart->setCursorTime(0, 5009.5); // reads the second sample at 5003
        QCOMPARE(chart->cursorReadout().sampleTimeMs[0], 5003);
        chart->setCursorTime(0, 5009);
        chart->setCursorTime(1, 5020); // exactly on the last
        QCOMPARE(changed.count(), 3);
        const ScopeCursorReadout readout = chart->cursorReadout();
        QCOMPARE(readout.deltaMs(), 11.0);
        QCOMPARE(readout.seconds(0), 0.009);
        QCOMPARE(readout.sampleTimeMs[0], 5003);
        QCOMPARE(readout.sampleTimeMs[1], 5020);
        QCOMPARE(readout.channels.size(), 4);
        QCOMPARE(readout.channels[0].raw[0], 1236);
        QCOMPARE(readout.channels[0].value[0], 12.36);
        QCOMPARE(readout.channels[0].value[1], 12.38);
        QCOMPARE(readout.channels[0].unit, QStringLiteral("Hz"));
        QCOMPARE(readout.channels[1].value[0], -2.0);
        QCOMPARE(readout.channels[2].difference(), 20.0);

        QVERIFY(chart->cursorTable()->isVisible());
        const ScopeCursorTable &table = *chart->cursorTable();
        QCOMPARE(table.rowCount(), 5);
        QCOMPARE(table.cellText(0, ScopeCursorTable::FirstColumn), QStringLiteral("0.009"));
        QCOMPARE(table.cellText(0, ScopeCursorTable::DifferenceColumn), QStringLiteral("0.011"));
        QCOMPARE(table.cellText(1, ScopeCursorTable::NameColumn),
                 QStringLiteral("ru.03 Actual frequency [Hz]"));
        QCOMPARE(table.cellText(1, ScopeCursorTable::FirstColumn), QStringLiteral("12.36"));
        QCOMPARE(table.cellText(1, ScopeCursorTable::DifferenceColumn), QStringLiteral("0.02"));

        // Before the first sample there is nothing to read.
        chart->setCursorTime(0, 4999);
        QVERIFY(!chart->cursorReadout().channels[0].value[0]);
        QVERIFY(!chart->cursorReadout().channels[0].difference());

        // Shift+click places cursor 1 on a whole ms; a drag of its line moves it, not the view.
        chart->redrawNow();
        sendMouse(*chart, QEvent::MouseButtonPress, plotPoint(*chart, 0.010), Qt::LeftButton,
                  Qt::ShiftModifier);
        sendMouse(*chart, QEvent::MouseButtonRelease, plotPoint(*chart, 0.010), Qt::LeftButton,
                  Qt::ShiftModifier);
        QCOMPARE(chart->cursorTime(0), 5010.0);
        QCOMPARE(chart->cursorReadout().channels[0].raw[0], 1237);
        const QCPRange time = chart->plot()->xAxis->range();
        const QPoint grab = plotPoint(*chart, 0.010) + QPoint(2, 0);
        sendMouse(*chart, QEvent::MouseButtonPress, grab, Qt::LeftButton);
        sendMouse(*chart, QEvent::MouseMove, plotPoint(*chart, 0.003), Qt::LeftButton);
        sendMouse(*chart, QEvent::MouseButtonRelease, plotPoint(*chart, 0.003), Qt::LeftButton);
        QCOMPARE(chart->cursorTime(0), 5003.0);
        QCOMPARE(chart->plot()->xAxis->range(), time);
        QVERIFY(chart->showsAll());

        QTest::keyClick(chart->plot(), Qt::Key_Escape);
        QVERIFY(!chart->cursorReadout().hasCursor());
        QVERIFY(!chart->cursorTable()->isVisible());
    }

    void channelsGetTheirOwnAxisOrShareOne()
    {
        ScopeRecording recording;
        describeChannels(recording);
        fill(recording, 5'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        QCustomPlot *plot = chart->plot();
        const int rightAxes = plot->axisRect()->axes(QCPAxis::atRight).size();
        // The shared axis names the unit, the legend the channels, in a row above the traces:
        // the four names joined would not fit the axis, and a legend on the traces hides them.
        QCOMPARE(plot->yAxis->label(), QStringLiteral("Value [Hz]"));
        QCOMPARE(plot->legend->itemCount(), 4);
        QStringList names;
        for (int channel = 0; channel < 4; ++channel)
            names << chart->graph(channel)->name();
        QVERIFY2(names.contains(QStringLiteral("ru.03 Actual frequency [Hz]")),
                 qPrintable(names.join(QLatin1Char('|'))));
        QVERIFY(names.contains(QStringLiteral("Channel 2")));
        plot->replot();
        QVERIFY(plot->legend->visible());
        QVERIFY2(!plot->legend->outerRect().intersects(plot->axisRect()->rect()),
                 qPrintable(QStringLiteral("legend %1,%2 %3x%4 over the traces")
                                .arg(plot->legend->outerRect().x())
                                .arg(plot->legend->outerRect().y())
                                .arg(plot->legend->outerRect().width())
                                .arg(plot->legend->outerRect().height())));
        QVERIFY(QFontMetrics(plot->yAxis->labelFont()).horizontalAdvance(plot->yAxis->label())
                < plot->axisRect()->height());

        chart->setChannelOwnAxis(0, true);
        QVERIFY(chart->hasChannelOwnAxis(0));
        QCPAxis *own = chart->valueAxis(0);
        QVERIFY(own != plot->yAxis);
        QCOMPARE(own->axisType(), QCPAxis::atRight);
        QCOMPARE(chart->graph(0)->valueAxis(), own);
        QCOMPARE(plot->axisRect()->axes(QCPAxis::atRight).size(), rightAxes + 1);
        QCOMPARE(own->label(), QStringLiteral("ru.03 Actual frequency [Hz]"));
        QCOMPARE(plot->yAxis->label(), QString()); // the others have no unit
        chart->redrawNow();
        QVERIFY(own->range().contains(0.06)); // fitted to its own channel: 0..0.06 Hz
        QVERIFY(own->range().upper < 1);
        QVERIFY(plot->yAxis->range().contains(999)); // the others

        chart->setChannelColor(0, Qt::darkCyan);
        QCOMPARE(chart->graph(0)->pen().color(), QColor(Qt::darkCyan));
        QCOMPARE(own->labelColor(), QColor(Qt::darkCyan));

        chart->setChannelOwnAxis(0, false);
        QCOMPARE(chart->valueAxis(0), plot->yAxis);
        QCOMPARE(chart->graph(0)->valueAxis(), plot->yAxis);
        QCOMPARE(plot->axisRect()->axes(QCPAxis::atRight).size(), rightAxes);
        chart->redrawNow();
    }

    void hiddenChannelsAreNotDrawn()
    {
        ScopeRecording recording;
        fill(recording, 5'000);
        recording.channels[3].enabled = false; // the drive delivers nothing on it
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        chart->recordingChanged();
        chart->setChannelVisible(1, false);
        chart->redrawNow();
        QVERIFY(!chart->isChannelVisible(1));
        QVERIFY(!chart->graph(1)->visible());
        QVERIFY(chart->graph(1)->data()->isEmpty());
        QVERIFY(chart->graph(3)->data()->isEmpty());
        QVERIFY(!chart->graph(0)->data()->isEmpty());
        QCOMPARE(chart->plot()->legend->itemCount(), 2);
        chart->setCursorTime(0, kStartMs + 10);
        QCOMPARE(chart->cursorReadout().channels.size(), 2);

        chart->setChannelVisible(1, true);
        chart->redrawNow();
        QVERIFY(!chart->graph(1)->data()->isEmpty());
        QCOMPARE(chart->plot()->legend->itemCount(), 3);
    }

    // A drive whose channels are all off: no legend entry, and the time axis still spans the
    // chart (an empty legend once capped it to a strip a few pixels wide).
    void withEveryChannelOffTheAxesSpanTheChart()
    {
        ScopeRecording recording;
        fill(recording, 5'000);
        for (ScopeChannel &channel : recording.channels)
            channel.enabled = false;
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        chart->recordingChanged();
        chart->redrawNow();
        QCOMPARE(chart->plot()->legend->itemCount(), 0);
        const int plotWidth = chart->plot()->width();
        const int axisWidth = chart->plot()->axisRect()->width();
        QVERIFY2(axisWidth > plotWidth / 2,
                 qPrintable(QStringLiteral("%1 of %2 px").arg(axisWidth).arg(plotWidth)));
    }

    void aFrozenViewKeepsItsSamples()
    {
        ScopeRecording recording;
        fill(recording, 10'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        QSignalSpy frozen(chart.get(), &ScopeChart::frozenChanged);
        QTest::keyClick(chart->plot(), Qt::Key_Space);
        QVERIFY(chart->isFrozen());
        QCOMPARE(frozen.count(), 1);

        fill(recording, 12'000);
        chart->samplesAppended();
        chart->zoomTime(2); // even a zoom out shows only the samples there were
        chart->redrawNow();
        QVERIFY(lastKey(chart->graph(1)) <= 9.999);
        chart->setCursorTime(0, kStartMs + 11'000);
        QCOMPARE(chart->cursorReadout().sampleTimeMs[0], kStartMs + 9'999);

        chart->setFrozen(false);
        chart->setFollow(true);
        QTRY_VERIFY(lastKey(chart->graph(1)) > 11.99);
        QCOMPARE(chart->cursorReadout().sampleTimeMs[0], kStartMs + 11'000);
    }

    void aNewRecordingIsShownWhole()
    {
        ScopeRecording recording;
        fill(recording, 10'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        chart->showTimeRange(kStartMs + 100, kStartMs + 200);
        QCOMPARE(chart->visibleTimeRange(), (ScopeTimeRange { kStartMs + 100, kStartMs + 200 }));
        QVERIFY(!chart->follows());

        ScopeRecording other;
        ScopeSample sample;
        for (qint64 t = 70'000; t < 73'000; ++t) {
            sample.time = t;
            QVERIFY(other.buffer.append(sample));
        }
        chart->setRecording(&other);
        QCOMPARE(chart->visibleTimeRange(), (ScopeTimeRange { 70'000, 72'999 }));
        chart->redrawNow();
        const double firstKey = chart->graph(0)->data()->constBegin()->key;
        QVERIFY(firstKey >= 0 && firstKey < 0.01); // the first column's middle
        chart->setRecording(nullptr);
        chart->redrawNow();
        QVERIFY(chart->graph(0)->data()->isEmpty());
    }

    void exportWritesImagesOrSaysWhyNot()
    {
        ScopeRecording recording;
        fill(recording, 10'000);
        const auto chart = shownChart(recording);
        QVERIFY(chart);
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        QString error;
        const QString png = folder.filePath(QStringLiteral("scope.png"));
        QVERIFY2(chart->savePng(png, &error), qPrintable(error));
        QVERIFY(QFileInfo(png).size() > 0);
        const QString pdf = folder.filePath(QStringLiteral("scope.pdf"));
        QVERIFY2(chart->savePdf(pdf, &error), qPrintable(error));
        QVERIFY(QFileInfo(pdf).size() > 0);

        const QString nowhere = folder.filePath(QStringLiteral("missing/scope.png"));
        QVERIFY(!chart->savePng(nowhere, &error));
        QVERIFY2(error.contains(nowhere) && error.contains(QStringLiteral("does not exist")),
                 qPrintable(error));
        QVERIFY(!chart->savePdf(folder.path(), &error));
        QVERIFY2(error.contains(folder.path()) && error.contains(QStringLiteral("folder")),
                 qPrintable(error));
        QVERIFY(!QFileInfo::exists(nowhere));
    }

    void theColumnGridMatchesDecimateTime()
    {
        // Uneven times (0..3 ms apart, several samples in one ms), spikes anywhere.
        ScopeBuffer buffer;
        QRandomGenerator random(7);
        ScopeSample sample;
        for (int i = 0; i < 200'000; ++i) {
            sample.time += random.bounded(0, 4);
            sample.wide = { qint32(random.generate()), sample.wide[1] + random.bounded(-9, 10) };
            sample.narrow = { qint16(random.bounded(-30000, 30001)), qint16(i % 4000) };
            QVERIFY(buffer.append(sample));
        }
        const qint64 last = buffer.samples().time(buffer.count() - 1);
        struct Case
        {
            qint64 fromMs;
            qint64 toMs;
            int columns;
        };
        for (const Case &view : { Case { 0, last, 1500 }, Case { 1234, 5678, 700 },
                                  Case { 100'000, 100'300, 1000 }, Case { -500, 2000, 300 } }) {
            const ScopeColumnGrid grid(buffer.samples(), view.fromMs, view.toMs, view.columns,
                                       buffer.count());
            QVERIFY(grid.count() <= view.columns + 1);
            QVERIFY(grid.fromMs() <= std::max<qint64>(view.fromMs, 0));
            QVERIFY(grid.fromMs() > view.fromMs - grid.widthMs());
            QCOMPARE(grid.fromMs() % grid.widthMs(), 0);
            // Every sample of the view is in a column.
            QVERIFY(grid.first() <= buffer.samples().lowerBound(view.fromMs));
            QCOMPARE(grid.end(), buffer.samples().upperBound(view.toMs));
            const int n = grid.count();
            for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
                QList<MinMaxPyramid::Column> columns;
                for (int column = 0; column < n - 1; ++column) {
                    if (!grid.isEmpty(column))
                        columns.append(grid.column(buffer.pyramid(), channel, column));
                }
                // decimateTime() over the grid's span makes the same columns; the last one
                // ends at the view's end instead.
                QCOMPARE(columns,
                         buffer.decimateTime(channel, grid.fromMs(),
                                             grid.fromMs() + (n - 1) * grid.widthMs() - 1, n - 1));
                const auto lastColumn = grid.column(buffer.pyramid(), channel, n - 1);
                QCOMPARE(lastColumn, buffer.decimate(channel, lastColumn.begin, grid.end(), 1)[0]);
                QCOMPARE(lastColumn.begin,
                         buffer.samples().lowerBound(grid.fromMs() + (n - 1) * grid.widthMs()));
            }
        }

        // Samples from sampleCount on stay out, even in the same ms as the last one in.
        qsizetype sameMs = 1000;
        while (buffer.samples().time(sameMs) != buffer.samples().time(sameMs - 1))
            ++sameMs;
        const ScopeColumnGrid frozen(buffer.samples(), 0, last, 100, sameMs);
        QCOMPARE(frozen.first(), 0);
        QCOMPARE(frozen.end(), sameMs);
    }

    void theHelpNamesTheKeys()
    {
        const QString help = ScopeChart::helpText();
        for (const char *key : { "Ctrl+wheel", "Shift+click", "Home", "End", "A:", "Space" })
            QVERIFY2(help.contains(QLatin1String(key)), key);
        ScopeChart chart;
        QCOMPARE(chart.plot()->toolTip(), help);
    }
};

QTEST_MAIN(TestScopeChart)
#include "tst_scopechart.moc"
