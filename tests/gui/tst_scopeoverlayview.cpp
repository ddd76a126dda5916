// A second recording overlaid in the scope dock, offscreen with no drive: drawn over the one
// shown at its trigger (or its start), named in the legend, read by the cursors, kept when
// the recording shown is replaced, and removed.
#include "tst_scopesupport.h"

#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeCursorTable.h"
#include "scope/ScopeDock.h"
#include "scope/ScopeFileFormat.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeOverlayTraces.h"
#include "scope/ScopeRecording.h"

#include <QAction>
#include <QLabel>
#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;
using namespace DriveDesk::ScopeDockTest;

namespace {

constexpr quint16 kHz = 18;

// ru.03 in 0.01 Hz, one sample a ms from `firstMs` for a second: 0 Hz, then `hz` from
// `stepMs` on. A single shot that fired at `stepMs` where `shot`.
ScopeRecording stepRecording(qint64 firstMs, qint64 stepMs, double hz, bool shot = true)
{
    ScopeRecording recording;
    ScopeChannel frequency;
    frequency.source = 0x0203;
    frequency.id = QStringLiteral("ru.03");
    frequency.name = QStringLiteral("Actual frequency");
    frequency.scaling
        = DisplayScaling(DisplayScalingData { 0x0203, 100, 1, 0, quint16(kHz | (2 << 8)) });
    recording.channels[0] = frequency;
    for (int channel = 1; channel < ScopeSample::kChannelCount; ++channel)
        recording.channels[channel].enabled = false;
    for (qint64 t = firstMs; t < firstMs + 1000; ++t) {
        ScopeSample sample;
        sample.time = t;
        sample.wide = { t >= stepMs ? qint32(hz * 100) : 0, 0 };
        recording.buffer.append(sample);
    }
    if (shot)
        recording.triggerMs = stepMs;
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

// The key (s) of a graph's first point at or above `value`; -1 if none.
double firstKeyAtOrAbove(const QCPGraph *graph, double value)
{
    for (auto point = graph->data()->constBegin(); point != graph->data()->constEnd(); ++point) {
        if (point->value >= value)
            return point->key;
    }
    return -1;
}

// The read-out's row named `name`; -1 if none.
int rowNamed(const ScopeCursorTable *table, const QString &name)
{
    for (int row = 0; row < table->rowCount(); ++row) {
        if (table->cellText(row, ScopeCursorTable::NameColumn) == name)
            return row;
    }
    return -1;
}

QString status(const ScopeDock &dock)
{
    return dock.findChild<QLabel *>(QStringLiteral("scopeStatus"))->text();
}

} // namespace

class TestScopeOverlayView : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;

private slots:
    void anOverlayIsAlignedAtTheTriggerAndReadByTheCursors()
    {
        m_settings.clear();
        QTemporaryDir dir;
        // The run shown fired 200 ms after its start; the earlier run, recorded at another
        // time of the drive's clock, 700 ms after its own.
        const QString shownPath = dir.filePath(QStringLiteral("run3.ddscope"));
        const QString overlayPath = dir.filePath(QStringLiteral("run2.ddscope"));
        QVERIFY(writeRecording(shownPath, stepRecording(5000, 5200, 50.0)));
        QVERIFY(writeRecording(overlayPath, stepRecording(40'000, 40'700, 30.0)));
        MainWindow window;
        window.show();
        auto *dock = window.findChild<ScopeDock *>();
        QString error;
        QVERIFY2(dock->openRecording(shownPath, &error), qPrintable(error));
        ScopeChart *chart = dock->chart();
        // the shot's trigger comes with its file
        QCOMPARE(chart->triggerTime(), std::optional<qint64>(5200));

        dock->openOverlay(overlayPath);
        QTRY_VERIFY_WITH_TIMEOUT(chart->overlay() != nullptr, kWaitMs);
        QVERIFY2(status(*dock).contains(QStringLiteral("aligned at its trigger")),
                 qPrintable(status(*dock)));
        QCOMPARE(chart->overlayShift()->alignment, ScopeOverlayAlignment::Trigger);

        // Near the trigger every sample is drawn at its time: both steps at the trigger's x.
        chart->showTimeRange(5190, 5210);
        chart->redrawNow();
        const double triggerKey = (5200.0 - 5000.0) / 1000.0;
        QCOMPARE(firstKeyAtOrAbove(chart->graph(0), 50.0), triggerKey);
        QCOMPARE(firstKeyAtOrAbove(chart->overlayTraces()->graph(0), 30.0), triggerKey);
        // on the value axis of the channel it compares with
        QCOMPARE(chart->overlayTraces()->graph(0)->valueAxis(), chart->valueAxis(0));

        const QString overlayName
            = QStringLiteral("ru.03 Actual frequency (overlay: run2.ddscope) [Hz]");
        QVERIFY2(legendNames(chart->plot()).contains(overlayName),
                 qPrintable(legendNames(chart->plot()).join(QStringLiteral(", "))));

        // The cursors read both: before the trigger both are at 0, after it 50 and 30 Hz.
        chart->setCursorTime(0, 5150);
        chart->setCursorTime(1, 5600);
        ScopeCursorTable *table = chart->cursorTable();
        QTRY_VERIFY(rowNamed(table, overlayName) >= 0);
        const int overlayRow = rowNamed(table, overlayName);
        const int shownRow = rowNamed(table, QStringLiteral("ru.03 Actual frequency [Hz]"));
        QVERIFY(shownRow >= 0);
        const DisplayScaling &scaling = dock->recording()->channels[0].scaling;
        QCOMPARE(table->cellText(shownRow, ScopeCursorTable::SecondColumn),
                 scaling.format(5000, false));
        QCOMPARE(table->cellText(overlayRow, ScopeCursorTable::FirstColumn),
                 scaling.format(0, false));
        QCOMPARE(table->cellText(overlayRow, ScopeCursorTable::SecondColumn),
                 scaling.format(3000, false));
        QCOMPARE(chart->overlayReadout().channels.size(), 1);
        QCOMPARE(chart->overlayReadout().channels[0].value[1], std::optional<double>(30.0));

        // At the start: the overlay's first sample on the shown one's, its step 700 ms on.
        dock->findChild<QAction *>(QStringLiteral("scopeOverlayStartAction"))->trigger();
        QCOMPARE(chart->overlayShift()->alignment, ScopeOverlayAlignment::Start);
        chart->showTimeRange(5690, 5710);
        chart->redrawNow();
        QCOMPARE(firstKeyAtOrAbove(chart->overlayTraces()->graph(0), 30.0), 0.7);
        QCOMPARE(table->cellText(overlayRow, ScopeCursorTable::SecondColumn),
                 scaling.format(0, false));

        // A recording opened anew keeps the overlay, to compare it with the same file.
        dock->findChild<QAction *>(QStringLiteral("scopeOverlayTriggerAction"))->trigger();
        QVERIFY2(dock->openRecording(shownPath, &error), qPrintable(error));
        QVERIFY(chart->overlay() != nullptr);
        chart->redrawNow();
        QVERIFY(legendNames(chart->plot()).contains(overlayName));

        // Removed, it is gone from the chart, the legend and the read-out.
        dock->findChild<QAction *>(QStringLiteral("scopeRemoveOverlayAction"))->trigger();
        QVERIFY(chart->overlay() == nullptr);
        chart->redrawNow();
        QVERIFY(!legendNames(chart->plot()).contains(overlayName));
        QCOMPARE(rowNamed(table, overlayName), -1);
        QVERIFY(chart->overlayTraces()->graph(0)->data()->isEmpty());
    }

    // A recording that is no single shot has no trigger: the overlay goes to the start, and
    // the status says why.
    void withoutATriggerTheOverlayFallsBackToTheStart()
    {
        m_settings.clear();
        QTemporaryDir dir;
        const QString shownPath = dir.filePath(QStringLiteral("run3.ddscope"));
        const QString overlayPath = dir.filePath(QStringLiteral("free.ddscope"));
        QVERIFY(writeRecording(shownPath, stepRecording(5000, 5200, 50.0)));
        QVERIFY(writeRecording(overlayPath, stepRecording(40'000, 40'700, 30.0, false)));
        MainWindow window;
        window.show();
        auto *dock = window.findChild<ScopeDock *>();
        QString error;
        QVERIFY2(dock->openRecording(shownPath, &error), qPrintable(error));
        dock->openOverlay(overlayPath);
        QTRY_VERIFY_WITH_TIMEOUT(dock->chart()->overlay() != nullptr, kWaitMs);
        QCOMPARE(dock->chart()->overlayShift()->alignment, ScopeOverlayAlignment::Start);
        QVERIFY2(status(*dock).contains(QStringLiteral("free.ddscope has no trigger")),
                 qPrintable(status(*dock)));

        // a file that cannot be read is named, and the overlay drawn stays
        dock->openOverlay(dir.filePath(QStringLiteral("missing.ddscope")));
        QTRY_VERIFY_WITH_TIMEOUT(status(*dock).contains(QStringLiteral("missing.ddscope")),
                                 kWaitMs);
        QCOMPARE(dock->chart()->overlay()->fileName(), QStringLiteral("free.ddscope"));
    }
};

QTEST_MAIN(TestScopeOverlayView)
#include "tst_scopeoverlayview.moc"
