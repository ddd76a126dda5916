// Reading a recording of the simulated drive in the scope dock: an earlier run of the same
// channels overlaid, a math channel, the cursors and the measurements between them, all at
// once (each part alone: tst_scopeoverlayview, tst_scopeanalysis). With
// DRIVEDESK_SCOPE_SCREENSHOT=FILE it records longer and saves the dock as docs/scope.png shows
// it.
#include "tst_scopesupport.h"

#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeCursorTable.h"
#include "scope/ScopeDock.h"
#include "scope/ScopeMathChannels.h"
#include "scope/ScopeMathDialog.h"
#include "scope/ScopeMathTraces.h"
#include "scope/ScopeMeasurementTable.h"
#include "scope/ScopeOverlayTraces.h"
#include "scope/ScopeRecording.h"

#include "Translations.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;
using namespace DriveDesk::ScopeDockTest;

namespace {


// Records until the recording spans `ms`, then stops.
bool record(ScopeDock &dock, qint64 ms)
{
    QAction *record = action(dock, "scopeRecordAction");
    if (!record->isEnabled() || record->isChecked())
        return false;
    record->trigger();
    const bool spans = QTest::qWaitFor(
        [&dock, ms] {
            const ScopeRecording *recording = dock.recording();
            return dock.isRecording() && recording->buffer.count() > 1
                && recording->lastTime() - recording->firstTime() >= ms;
        },
        kWaitMs + int(ms));
    record->trigger();
    const bool stopped = QTest::qWaitFor([&dock] { return !dock.isRecording(); }, kWaitMs);
    if (!spans || !stopped)
        qWarning("%s (recording %d, %lld samples over %lld ms)",
                 qPrintable(dock.findChild<QLabel *>(QStringLiteral("scopeStatus"))->text()),
                 int(dock.isRecording()), qlonglong(dock.recording()->buffer.count()),
                 qlonglong(dock.recording()->lastTime() - dock.recording()->firstTime()));
    return spans && stopped;
}

} // namespace

class TestScopeReading : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;

private slots:
    // As the window is shown: in English with its plural forms ("1 sample", "2 samples").
    void initTestCase() { QVERIFY(installTranslations(QStringLiteral("en"))); }

    void aRunIsReadWithAnEarlierOneAMathChannelAndTheCursors()
    {
        const QString screenshot = qEnvironmentVariable("DRIVEDESK_SCOPE_SCREENSHOT");
        const qint64 runMs = screenshot.isEmpty() ? 1500 : 12000;
        m_settings.clear();
        QTemporaryDir dir;
        MainWindow window;
        window.resize(1500, 900);
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        window.findChild<QAction *>(QStringLiteral("scopeViewAction"))->trigger();
        auto *dock = window.findChild<ScopeDock *>();
        QTRY_VERIFY(dock->isVisible());
        chooseSource(*dock, 0, kActualFrequency);
        chooseSource(*dock, 1, kDcLinkVoltage);
        chooseSource(*dock, 2, kOutputVoltage);
        chooseSource(*dock, 3, kActualSpeed);

        // The earlier run, kept in a file.
        QVERIFY(record(*dock, runMs));
        const QString earlier = dir.filePath(QStringLiteral("earlier.ddscope"));
        QString error;
        QVERIFY2(dock->saveRecording(earlier, &error), qPrintable(error));
        const qsizetype earlierCount = dock->recording()->buffer.count();

        // This run, with the earlier one drawn over it from its start (no trigger in either).
        QVERIFY(record(*dock, runMs));
        ScopeChart *chart = dock->chart();
        dock->openOverlay(earlier);
        QTRY_VERIFY_WITH_TIMEOUT(chart->overlay() != nullptr, kWaitMs);
        action(*dock, "scopeOverlayStartAction")->trigger();
        QCOMPARE(chart->overlay()->recording().buffer.count(), earlierCount);

        // d/dt ru.03, from the dock's menu.
        ScopeMathDialog *dialog = derivativeOfTheFirstChannel(*dock);
        QVERIFY(dialog);
        dialog->accept();
        QTRY_VERIFY_WITH_TIMEOUT(dock->mathChannels()->series().size() == 1
                                     && !dock->mathChannels()->isComputing(),
                                 kWaitMs);
        QTRY_COMPARE_WITH_TIMEOUT(chart->mathTraces()->count(), 1, kWaitMs);

        // The cursors at a third and two thirds of the run.
        chart->showAll();
        const ScopeRecording &recording = *dock->recording();
        const qint64 span = recording.lastTime() - recording.firstTime();
        chart->setCursorTime(0, double(recording.firstTime() + span / 3));
        chart->setCursorTime(1, double(recording.firstTime() + 2 * span / 3));

        // All drawn and named: the four channels, the earlier run's four, the math channel.
        chart->redrawNow();
        const QStringList names = legendNames(chart->plot());
        QCOMPARE(names.size(), 9);
        QCOMPARE(names.filter(QStringLiteral("(overlay: earlier.ddscope)")).size(), 4);
        QVERIFY2(names.last().startsWith(QStringLiteral("d/dt ru.03")), qPrintable(names.last()));
        for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
            QVERIFY(!chart->graph(channel)->data()->isEmpty());
            QVERIFY(!chart->overlayTraces()->graph(channel)->data()->isEmpty());
        }
        QVERIFY(!chart->mathTraces()->graph(0)->data()->isEmpty());
        // The cursors read the channels, the math channel and the earlier run.
        ScopeCursorTable *cursors = chart->cursorTable();
        QTRY_VERIFY_WITH_TIMEOUT(cursors->rowCount() >= 1 + 4 + 1 + 4, kWaitMs);
        QVERIFY(!chart->overlayReadout().channels.isEmpty());
        // The measurements between them: a column a channel and the math channel.
        ScopeMeasurementTable *table = dock->measurementTable();
        QTRY_VERIFY_WITH_TIMEOUT(table->columnCount() == 5 && !table->isMeasuring(), kWaitMs);
        QVERIFY(table->cellText(ScopeMeasurementTable::MeanRow, 1).endsWith(QStringLiteral(" V")));
        QVERIFY(table->cellText(ScopeMeasurementTable::MeanRow, 4).endsWith(QStringLiteral(" Hz/s")));

        if (!screenshot.isEmpty()) {
            QTest::qWait(300);
            QVERIFY(dock->grab().save(screenshot));
        }
    }
};

QTEST_MAIN(TestScopeReading)
#include "tst_scopereading.moc"
