// Reading a recording in the scope dock, offscreen with no drive: the measurements between the
// cursors beside the chart and in the CSV export, each checked against what the test works
// out from the signal it recorded; the spectrum window opened from the dock.
#include "tst_scopesupport.h"

#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeCursorTable.h"
#include "scope/ScopeDock.h"
#include "scope/ScopeFileFormat.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeMathChannels.h"
#include "scope/ScopeMathDialog.h"
#include "scope/ScopeMathTraces.h"
#include "scope/ScopeMeasurementTable.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeSpectrumView.h"

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QLocale>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <cmath>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;
using namespace DriveDesk::ScopeDockTest;

namespace {

constexpr quint16 kHz = 18;

// ru.03 in 0.01 Hz: a trapezoid, up from 0 to 50 Hz over 0..100 ms, 50 Hz until 300 ms, down
// to 0 by 400 ms, then 0 until 1000 ms; one sample a ms. Channel 2 is raw: the sample's index.
ScopeRecording trapezoid()
{
    ScopeRecording recording;
    ScopeChannel frequency;
    frequency.source = 0x0203;
    frequency.id = QStringLiteral("ru.03");
    frequency.name = QStringLiteral("Actual frequency");
    frequency.scaling = DisplayScaling(DisplayScalingData { 0x0203, 100, 1, 0, quint16(kHz | (1 << 8)) });
    recording.channels[0] = frequency;
    recording.channels[2].enabled = false;
    recording.channels[3].enabled = false;
    for (qint64 t = 0; t <= 1000; ++t) {
        const double hz = t < 100 ? 0.5 * double(t)
            : t < 300             ? 50.0
            : t < 400             ? 50.0 - 0.5 * double(t - 300)
                                  : 0.0;
        ScopeSample sample;
        sample.time = 5000 + t; // a recording's time need not start at 0
        sample.wide = { qint32(std::lround(hz * 100)), qint32(t) };
        recording.buffer.append(sample);
    }
    return recording;
}

bool writeRecording(const QString &path, const ScopeRecording &recording)
{
    ScopeFileWriter writer;
    QString error;
    const bool written = writer.open(path, ScopeFileHeader::of(recording), &error)
        && writer.append(recording.buffer.samples(), 0, recording.buffer.count(), &error)
        && writer.close(&error);
    if (!written)
        qWarning("%s", qPrintable(error));
    return written;
}

QString withUnit(double value, int decimals, const QString &unit)
{
    return QStringLiteral("%1 %2").arg(QLocale().toString(value, 'f', decimals), unit);
}

} // namespace

class TestScopeAnalysis : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;

private slots:
    void measurementsBetweenTheCursors()
    {
        m_settings.clear();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("trapezoid.ddscope"));
        QVERIFY(writeRecording(path, trapezoid()));
        MainWindow window;
        window.show();
        auto *dock = window.findChild<ScopeDock *>();
        QString error;
        QVERIFY2(dock->openRecording(path, &error), qPrintable(error));
        ScopeMeasurementTable *table = dock->measurementTable();
        QVERIFY(table->isHidden()); // no cursors yet

        QSignalSpy measured(table, &ScopeMeasurementTable::measured);
        dock->chart()->setCursorTime(0, 5460); // in either order
        dock->chart()->setCursorTime(1, 5050);
        QTRY_VERIFY_WITH_TIMEOUT(measured.count() > 0 && !table->isMeasuring(), kWaitMs);
        QVERIFY(!table->isHidden());
        QCOMPARE(table->columnCount(), 2);
        QCOMPARE(table->horizontalHeaderItem(0)->text(), QStringLiteral("ru.03"));

        // From 50 to 460 ms: up from 25 to 50 Hz (50 ms), 50 Hz (200 ms), down to 0 (100 ms),
        // 0 (60 ms). The mean and RMS of that line over the 410 ms.
        const int decimals = dock->recording()->channels[0].scaling.decimals();
        const QString hz = QStringLiteral("Hz");
        const double mean = (50 * 37.5 + 200 * 50.0 + 100 * 25.0) / 410;
        const double rms = std::sqrt(
            (50 * (25.0 * 25 + 25.0 * 50 + 50.0 * 50) / 3 + 200 * 2500.0 + 100 * 2500.0 / 3)
            / 410);
        using Row = ScopeMeasurementTable::Row;
        QCOMPARE(table->cellText(Row::MinimumRow, 0), withUnit(0, decimals, hz));
        QCOMPARE(table->cellText(Row::MaximumRow, 0), withUnit(50, decimals, hz));
        QCOMPARE(table->cellText(Row::PeakToPeakRow, 0), withUnit(50, decimals, hz));
        QCOMPARE(table->cellText(Row::MeanRow, 0), withUnit(mean, decimals + 1, hz));
        QCOMPARE(table->cellText(Row::RmsRow, 0), withUnit(rms, decimals + 1, hz));
        // Levels 5 and 45 Hz: the window starts above 5 Hz, so it holds no rise; the fall
        // passes 45 Hz at 310 ms and 5 Hz at 390 ms: 40 Hz in 80 ms.
        QCOMPARE(table->cellText(Row::RiseTimeRow, 0), QString());
        QCOMPARE(table->cellText(Row::FallTimeRow, 0), withUnit(80, 1, QStringLiteral("ms")));
        QCOMPARE(table->cellText(Row::FallRateRow, 0),
                 withUnit(-500, decimals + 1, QStringLiteral("Hz/s")));
        // The raw channel: its index, 50 to 460, a rise of 328 counts in 328 ms.
        QCOMPARE(table->cellText(Row::MinimumRow, 1), QLocale().toString(50.0, 'f', 0));
        QCOMPARE(table->cellText(Row::RiseTimeRow, 1), withUnit(328, 1, QStringLiteral("ms")));

        // Moving a cursor measures again.
        measured.clear();
        dock->chart()->setCursorTime(0, 5200);
        QTRY_VERIFY_WITH_TIMEOUT(measured.count() > 0 && !table->isMeasuring(), kWaitMs);
        QCOMPARE(table->cellText(Row::MinimumRow, 0), withUnit(25, decimals, hz));
        QCOMPARE(table->cellText(Row::MaximumRow, 0), withUnit(50, decimals, hz));

        // The export carries them after the samples.
        const QString csv = dir.filePath(QStringLiteral("trace.csv"));
        QVERIFY2(dock->exportCsv(csv, false, &error), qPrintable(error));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY(text.contains(QStringLiteral("\r\n\r\nMeasurement,ru.03 Actual frequency [Hz],")));
        QVERIFY(text.contains(QStringLiteral("\r\nMinimum,25,")));
        QVERIFY(text.contains(QStringLiteral("\r\nFrom [ms],50,")));

        // One cursor removed: nothing to measure between.
        dock->chart()->setCursorTime(1, std::nullopt);
        QTRY_VERIFY_WITH_TIMEOUT(table->isHidden(), kWaitMs);
    }

    // A derivative of ru.03 added from the dock's menu: drawn on an axis of its own in Hz/s,
    // measured with the channels, kept in the recording's file and read back from it.
    void aMathChannelIsComputedDrawnAndKept()
    {
        m_settings.clear();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("trapezoid.ddscope"));
        QVERIFY(writeRecording(path, trapezoid()));
        MainWindow window;
        window.show();
        auto *dock = window.findChild<ScopeDock *>();
        QString error;
        QVERIFY2(dock->openRecording(path, &error), qPrintable(error));
        QVERIFY(dock->mathChannels()->series().isEmpty());

        ScopeMathDialog *dialog = derivativeOfTheFirstChannel(*dock);
        QVERIFY(dialog);
        QSignalSpy computed(dock->mathChannels(), &ScopeMathChannels::seriesChanged);
        dialog->accept();
        QTRY_VERIFY_WITH_TIMEOUT(computed.count() > 0 && !dock->mathChannels()->isComputing(),
                                 kWaitMs);
        QCOMPARE(dock->recording()->math.size(), 1);
        QCOMPARE(dock->mathChannels()->series().size(), 1);
        const ScopeSeries &derivative = *dock->mathChannels()->series().first();
        QCOMPARE(derivative.unit, QStringLiteral("Hz/s"));
        QCOMPARE(derivative.count(), qsizetype(1001));
        // The trapezoid's slopes: +0.5 Hz a ms on the way up, 0 on top, -0.5 on the way down.
        const auto at = [&derivative](qint64 ms) {
            return derivative.values[std::size_t(derivative.lowerBound(double(5000 + ms)))];
        };
        QVERIFY(std::abs(at(50) - 500) < 1e-6);
        QVERIFY(std::abs(at(200)) < 1e-6);
        QVERIFY(std::abs(at(350) + 500) < 1e-6);
        QVERIFY(std::abs(at(700)) < 1e-6);

        // Drawn: a graph with points, named with its unit, on its own axis.
        QTRY_COMPARE_WITH_TIMEOUT(dock->chart()->mathTraces()->count(), 1, kWaitMs);
        QCPGraph *graph = dock->chart()->mathTraces()->graph(0);
        QVERIFY(graph->name().endsWith(QStringLiteral("[Hz/s]")));
        QTRY_VERIFY_WITH_TIMEOUT(!graph->data()->isEmpty(), kWaitMs);
        QVERIFY(dock->chart()->mathTraces()->valueAxis(0) != dock->chart()->plot()->yAxis);

        // Measured with the channels: the steepest slope between the cursors.
        ScopeMeasurementTable *table = dock->measurementTable();
        dock->chart()->setCursorTime(0, 5020);
        dock->chart()->setCursorTime(1, 5380);
        QTRY_VERIFY_WITH_TIMEOUT(table->columnCount() == 3 && !table->isMeasuring(), kWaitMs);
        using Row = ScopeMeasurementTable::Row;
        QCOMPARE(table->cellText(Row::MaximumRow, 2),
                 QStringLiteral("%1 Hz/s").arg(QLocale().toString(500.0, 'g', 5)));
        QCOMPARE(table->cellText(Row::MinimumRow, 2),
                 QStringLiteral("%1 Hz/s").arg(QLocale().toString(-500.0, 'g', 5)));
        // The cursors read it too: its row after the two channels'.
        ScopeCursorTable *cursors = dock->chart()->cursorTable();
        QTRY_COMPARE_WITH_TIMEOUT(cursors->rowCount(), 4, kWaitMs);
        QVERIFY(cursors->cellText(3, ScopeCursorTable::NameColumn).startsWith(QStringLiteral("d/dt")));
        QCOMPARE(cursors->cellText(3, ScopeCursorTable::FirstColumn), QLocale().toString(500.0, 'g', 5));
        QCOMPARE(cursors->cellText(3, ScopeCursorTable::SecondColumn),
                 QLocale().toString(-500.0, 'g', 5));

        // Kept with the recording, and back when it is opened again.
        const QString saved = dir.filePath(QStringLiteral("with math.ddscope"));
        QVERIFY2(dock->saveRecording(saved, &error), qPrintable(error));
        dock->findChild<QAction *>(QStringLiteral("scopeRemoveMathAction"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(dock->mathChannels()->series().isEmpty(), kWaitMs);
        QTRY_COMPARE_WITH_TIMEOUT(dock->chart()->mathTraces()->count(), 0, kWaitMs);
        computed.clear();
        QVERIFY2(dock->openRecording(saved, &error), qPrintable(error));
        QCOMPARE(dock->recording()->math.size(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(computed.count() > 0 && !dock->mathChannels()->isComputing(),
                                 kWaitMs);
        QCOMPARE(dock->mathChannels()->series().size(), 1);
    }

    // Recording > Spectrum... (Ctrl+Shift+F) opens the spectrum window beside the dock, once:
    // the trapezoid's spectrum over the whole recording (1001 samples), no peak at 0 Hz.
    void theSpectrumWindowOpensFromTheDock()
    {
        m_settings.clear();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("trapezoid.ddscope"));
        QVERIFY(writeRecording(path, trapezoid()));
        MainWindow window;
        window.show();
        auto *dock = window.findChild<ScopeDock *>();
        QString error;
        QVERIFY2(dock->openRecording(path, &error), qPrintable(error));
        auto *action = dock->findChild<QAction *>(QStringLiteral("scopeSpectrumAction"));
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
        action->trigger();
        ScopeSpectrumView *view = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT((view = dock->findChild<ScopeSpectrumView *>()) != nullptr
                                     && view->isVisible() && view->spectrum(),
                                 kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(!view->isComputing(), kWaitMs);
        QCOMPARE(view->spectrum()->samples, qsizetype(1001));
        QCOMPARE(view->spectrum()->title, QStringLiteral("ru.03 Actual frequency"));
        QVERIFY(!view->spectrum()->peaks.isEmpty());
        QVERIFY(view->spectrum()->peaks.first().frequencyHz > 0);
        action->trigger();
        QCOMPARE(dock->findChildren<ScopeSpectrumView *>().size(), 1);
    }
};

QTEST_MAIN(TestScopeAnalysis)
#include "tst_scopeanalysis.moc"
