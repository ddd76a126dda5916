#include "tst_scopesupport.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"
#include "scope/ScopeFileReader.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeChannelPanel.h"
#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeChart.h"
#include "monitor/TelegramMonitor.h"
#include "monitor/TrafficModel.h"
#include "scope/ScopeDock.h"
#include "Translations.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QToolBar>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;
using namespace DriveDesk::ScopeDockTest;

namespace {

constexpr quint16 kChannel1Source = 0x0010;  // Sy.16
constexpr quint16 kChannel3Source = 0x0014;  // Sy.20
constexpr quint16 kChannel4Source = 0x0016;  // Sy.22

QString status(ScopeDock &dock)
{
    return dock.findChild<QLabel *>(QStringLiteral("scopeStatus"))->text();
}

// The header and the samples' rows: up to the empty line before the measurements between the
// cursors, which follow where both are placed.
QStringList csvLines(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QStringList lines = QString::fromUtf8(file.readAll()).split(QStringLiteral("\r\n"));
    const qsizetype end = lines.indexOf(QString());
    if (end >= 0)
        lines = lines.mid(0, end);
    return lines;
}

// Chooses `path` in the file dialog the window shows now (to open, or to save).
bool chooseFile(MainWindow &window, QFileDialog::AcceptMode mode, const QString &path)
{
    QFileDialog *dialog = nullptr;
    const bool shown = QTest::qWaitFor(
        [&] {
            const auto dialogs
                = window.findChildren<QFileDialog *>(QStringLiteral("parameterFileDialog"));
            for (QFileDialog *candidate : dialogs) {
                if (candidate->isVisible() && candidate->acceptMode() == mode)
                    dialog = candidate;
            }
            return dialog != nullptr;
        },
        kWaitMs);
    if (!shown)
        return false;
    dialog->selectFile(path);
    static_cast<QDialog *>(dialog)->accept(); // QFileDialog::accept() is protected
    return true;
}

// The question before a recording is replaced, as shown now; nullptr when none is.
QMessageBox *shownQuestion(ScopeDock &dock)
{
    const auto boxes = dock.findChildren<QMessageBox *>(QStringLiteral("scopeReplaceQuestion"));
    for (QMessageBox *box : boxes) {
        if (box->isVisible())
            return box;
    }
    return nullptr;
}

QMessageBox *replaceQuestion(ScopeDock &dock)
{
    QMessageBox *question = nullptr;
    // Null when none came: the caller's QVERIFY names what was expected.
    if (!QTest::qWaitFor([&] { return (question = shownQuestion(dock)) != nullptr; }, kWaitMs))
        return nullptr;
    return question;
}

} // namespace

// The scope dock in the window, offscreen against the simulated drive: sources chosen in the
// panel are written to the drive and read back, the recording shows them with their units,
// the cursors read the samples, and the recording goes to CSV, PNG and a file it is read from.
class TestScopeDock : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;

    // Opened while the telegram monitor is docked, at the window's first size: the chart keeps
    // a height and a width to read, its axes do not run into each other, and the tool bars show
    // every button (none behind the overflow arrow).
    void checkTheChartsRoomBesideTheMonitor(Language language)
    {
        m_settings.clear();
        MainWindow window(language);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(connectAndRead(window, simulated()));
        window.findChild<QAction *>(QStringLiteral("monitorAction"))->trigger();
        window.findChild<QAction *>(QStringLiteral("scopeViewAction"))->trigger();
        auto *dock = window.findChild<ScopeDock *>();
        QTRY_VERIFY(dock->isVisible());
        QCustomPlot *plot = dock->chart()->plot();
        QTest::qWait(50); // the docks' layout settles with the event loop
        const int width = window.width();
        // Recording, the counts under the chart grow and the monitor drops its oldest telegrams,
        // saying so: neither widens the window (it grew past a 1400-pixel screen) or squeezes
        // the chart.
        chooseSource(*dock, 0, kActualFrequency);
        chooseSource(*dock, 1, kDcLinkVoltage);
        QAction *record = action(*dock, "scopeRecordAction");
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(dock->isRecording(), kWaitMs);
        auto *monitor = window.findChild<TelegramMonitor *>();
        QVERIFY(monitor);
        QTRY_VERIFY_WITH_TIMEOUT(monitor->model()->droppedCount() > 0, 60000);
        QTest::qWait(300); // the monitor's status follows its batches
        QVERIFY2(window.width() <= width,
                 qPrintable(QStringLiteral("%1 px wide, was %2").arg(window.width()).arg(width)));
        plot->replot();
        QVERIFY2(plot->axisRect()->height() >= 150,
                 qPrintable(QStringLiteral("the traces get %1 px high").arg(plot->axisRect()->height())));
        QVERIFY2(plot->axisRect()->width() >= 250,
                 qPrintable(QStringLiteral("the traces get %1 px wide").arg(plot->axisRect()->width())));
        for (QToolBar *bar : dock->findChildren<QToolBar *>()) {
            const auto *more = bar->findChild<QWidget *>(QStringLiteral("qt_toolbar_ext_button"));
            QVERIFY2(!more || !more->isVisible(), qPrintable(bar->windowTitle()));
        }
        // The legend names every channel whole, above the traces.
        for (int i = 0; i < plot->legend->itemCount(); ++i) {
            QCPAbstractLegendItem *item = plot->legend->item(i);
            if (!item)
                continue; // an empty cell of the grid
            QVERIFY2(item->outerRect().width() >= item->minimumOuterSizeHint().width(),
                     qPrintable(QString::number(i)));
            QVERIFY(!item->outerRect().intersects(plot->axisRect()->rect()));
        }
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);
        // The count after the recording is written as during it: in the window's language
        // ("4.520" in German, not "4520").
        const QString count = QLocale().toString(qlonglong(dock->recording()->buffer.count()));
        QVERIFY2(status(*dock).contains(count),
                 qPrintable(QStringLiteral("%1 / %2").arg(status(*dock), count)));
    }

private slots:
    void recordsTheChannelsChosenInTheDock()
    {
        m_settings.clear();
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        QVERIFY(dock);
        QAction *view = window.findChild<QAction *>(QStringLiteral("scopeViewAction"));
        view->trigger();
        QVERIFY(dock->isVisible());

        chooseSource(*dock, 0, kActualFrequency);
        chooseSource(*dock, 1, kDcLinkVoltage);
        chooseSource(*dock, 2, kOutputVoltage);
        chooseSource(*dock, 3, ChannelAssignment::kOff);
        QTemporaryDir dir;
        QAction *record = action(*dock, "scopeRecordAction");
        QVERIFY(record->isEnabled());
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(dock->isRecording(), kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(dock->recording()->buffer.count() >= 300, kWaitMs);

        // What the drive delivers now is what was chosen, read back into the recording.
        DriveClient *client = window.session()->client();
        QCOMPARE(driveValue(client, kChannel1Source), qint32(kActualFrequency));
        QCOMPARE(driveValue(client, kChannel3Source), qint32(kOutputVoltage));
        QCOMPARE(driveValue(client, kChannel4Source), ChannelAssignment::kOff);
        // The parameter table shows what the scope wrote, not what it read before.
        QCOMPARE(window.model()->state()->value(kChannel1Source, 0), std::optional<qint32>(kActualFrequency));
        QCOMPARE(window.model()->state()->value(kChannel4Source, 0), std::optional<qint32>(ChannelAssignment::kOff));
        const ScopeRecording &recording = *dock->recording();
        QCOMPARE(recording.channels[0].id, QStringLiteral("ru.03"));
        QCOMPARE(recording.channels[0].unit(), QStringLiteral("Hz"));
        QCOMPARE(recording.channels[1].title(1), QStringLiteral("ru.18 DC link voltage"));
        QVERIFY(!recording.channels[3].enabled);
        QVERIFY2(status(*dock).contains(QStringLiteral("Hz")), qPrintable(status(*dock)));

        record->trigger(); // stop
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);
        QVERIFY(!record->isChecked());
        const qsizetype count = recording.buffer.count();
        QVERIFY2(status(*dock).contains(QStringLiteral("Recorded")), qPrintable(status(*dock)));

        // The cursors read the samples at or before them.
        ScopeChart *chart = dock->chart();
        chart->showAll();
        const qint64 first = recording.firstTime();
        const qint64 last = recording.lastTime();
        chart->setCursorTime(0, double(first));
        chart->setCursorTime(1, double(last));
        const ScopeCursorReadout readout = chart->cursorReadout();
        QCOMPARE(readout.deltaMs(), std::optional<double>(double(last - first)));
        const SampleStore &samples = recording.buffer.samples();
        bool found = false;
        for (const ScopeCursorReadout::Channel &channel : readout.channels) {
            if (channel.channel != 1)
                continue;
            found = true;
            QCOMPARE(channel.unit, QStringLiteral("V"));
            QCOMPARE(channel.raw[0], std::optional<qint32>(samples.value(samples.upperBound(first) - 1, 1)));
            QCOMPARE(channel.raw[1], std::optional<qint32>(samples.value(count - 1, 1)));
        }
        QVERIFY(found);

        // CSV of everything: one row a sample, the chosen channels with their units.
        const QString csv = dir.filePath(QStringLiteral("all.csv"));
        QString error;
        QVERIFY2(dock->exportCsv(csv, false, &error), qPrintable(error));
        const QStringList lines = csvLines(csv);
        QCOMPARE(lines.size(), count + 1);
        QCOMPARE(lines.first(), QStringLiteral("Time [ms],ru.03 Actual frequency [Hz],"
                                               "ru.18 DC link voltage [V],ru.09 Output voltage [V]"));
        // Only the visible range: a zoom into the middle gives fewer rows, all inside it.
        chart->showTimeRange(first + (last - first) / 4, first + (last - first) / 2);
        const ScopeTimeRange visible = chart->visibleTimeRange();
        const QString part = dir.filePath(QStringLiteral("visible.csv"));
        QVERIFY2(dock->exportCsv(part, true, &error), qPrintable(error));
        const QStringList partLines = csvLines(part);
        QVERIFY(partLines.size() > 1 && partLines.size() < lines.size());
        for (const QString &line : partLines.mid(1)) {
            const qint64 time = line.section(QLatin1Char(','), 0, 0).toLongLong() + first;
            QVERIFY(time >= visible.fromMs && time <= visible.toMs);
        }

        // Saved afterwards as a recording file, read back the same; a folder that is not there
        // is named and leaves nothing behind.
        const QString saved = dir.filePath(QStringLiteral("saved.ddscope"));
        QVERIFY2(dock->saveRecording(saved, &error), qPrintable(error));
        ScopeRecording reread;
        QVERIFY2(readScopeFile(saved, reread, &error), qPrintable(error));
        QCOMPARE(reread.buffer.count(), count);
        QCOMPARE(reread.channels, recording.channels);
        QVERIFY(!QFile::exists(saved + QStringLiteral(".part")));
        const QString nowhere = dir.filePath(QStringLiteral("missing/saved.ddscope"));
        QVERIFY(!dock->saveRecording(nowhere, &error));
        QVERIFY2(error.contains(QStringLiteral("missing")), qPrintable(error));

        QVERIFY2(chart->savePng(dir.filePath(QStringLiteral("chart.png")), &error), qPrintable(error));
        QVERIFY(QFileInfo(dir.filePath(QStringLiteral("chart.png"))).size() > 0);
    }

    void aRecordingFileIsViewedWithoutADrive()
    {
        m_settings.clear();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("run.ddscope"));
        qsizetype recorded = 0;
        {
            MainWindow window;
            window.show();
            QVERIFY(connectAndRead(window, simulated()));
            auto *dock = window.findChild<ScopeDock *>();
            chooseSource(*dock, 0, kActualFrequency);
            // Record to File asks for a file; the dock takes the path it is given.
            dock->setRecordFile(path);
            action(*dock, "scopeRecordAction")->trigger();
            QTRY_VERIFY_WITH_TIMEOUT(dock->recording()->buffer.count() >= 200, kWaitMs);
            action(*dock, "scopeRecordAction")->trigger();
            QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);
            recorded = dock->recording()->buffer.count();
            window.close();
        }
        MainWindow window; // no drive
        auto *dock = window.findChild<ScopeDock *>();
        QString error;
        QVERIFY2(dock->openRecording(path, &error), qPrintable(error));
        QCOMPARE(dock->recording()->buffer.count(), recorded);
        QCOMPARE(dock->recording()->channels[0].id, QStringLiteral("ru.03"));
        QVERIFY(!action(*dock, "scopeRecordAction")->isEnabled());
        QVERIFY(dock->chart()->showsAll());

        // A file that is not a recording is refused with its name; the view keeps what it had.
        const QString bad = dir.filePath(QStringLiteral("bad.ddscope"));
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("not a recording");
        file.close();
        QVERIFY(!dock->openRecording(bad, &error));
        QVERIFY2(error.contains(QStringLiteral("bad.ddscope")), qPrintable(error));
        QCOMPARE(dock->recording()->buffer.count(), recorded);
    }

    void readsTheDrivesOfflineRecords()
    {
        m_settings.clear();
        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated(Protocol::Din66019II)));
        auto *dock = window.findChild<ScopeDock *>();
        chooseSource(*dock, 0, kDcLinkVoltage);
        QAction *record = action(*dock, "scopeRecordAction");
        record->trigger(); // assigns the channel; the drive records it offline from then on
        QTRY_VERIFY_WITH_TIMEOUT(dock->recording()->buffer.count() >= 10, kWaitMs);
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);
        QTest::qWait(800); // 64 records, one each 10 ms

        QAction *offline = action(*dock, "scopeOfflineAction");
        QVERIFY(offline->isVisible());
        QVERIFY(offline->isEnabled());
        // The recording shown is in memory only: the dock asks before replacing it, without
        // blocking, and a cancel keeps it.
        const qsizetype recorded = dock->recording()->buffer.count();
        offline->trigger();
        auto *question = dock->findChild<QMessageBox *>(QStringLiteral("scopeReplaceQuestion"));
        QVERIFY(question);
        QTRY_VERIFY(question->isVisible());
        QVERIFY(!question->isModal() || question->windowModality() != Qt::ApplicationModal);
        QVERIFY(offline->isEnabled()); // nothing read yet
        question->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY(!dock->findChild<QMessageBox *>(QStringLiteral("scopeReplaceQuestion")));
        QCOMPARE(dock->recording()->buffer.count(), recorded);
        offline->trigger();
        question = dock->findChild<QMessageBox *>(QStringLiteral("scopeReplaceQuestion"));
        QVERIFY(question);
        question->button(QMessageBox::Discard)->click();
        QVERIFY(!offline->isEnabled()); // while it reads
        QTRY_VERIFY_WITH_TIMEOUT(offline->isEnabled(), kWaitMs);
        QVERIFY2(status(*dock).startsWith(QStringLiteral("64 ")), qPrintable(status(*dock)));
        const ScopeRecording &recording = *dock->recording();
        QCOMPARE(recording.buffer.count(), 64);
        QCOMPARE(recording.channels[0].id, QStringLiteral("ru.18"));
        QVERIFY(recording.source.contains(QStringLiteral("one a millisecond")));
        QVERIFY(recording.buffer.samples().value(0, 0) > 400); // a DC link's volts

        // Read but not saved: asked again before another read replaces them.
        offline->trigger();
        QVERIFY(dock->findChild<QMessageBox *>(QStringLiteral("scopeReplaceQuestion")));
    }

    // Record (F9) and Recording > Open Recording replace the recording shown: one held in
    // memory only goes no sooner than the user says so (Save / Discard / Cancel, without
    // blocking the window); a saved one goes without a question.
    void anUnsavedRecordingIsNotReplacedUnasked()
    {
        m_settings.clear();
        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        window.findChild<QAction *>(QStringLiteral("scopeViewAction"))->trigger();
        chooseSource(*dock, 0, kDcLinkVoltage);
        QAction *record = action(*dock, "scopeRecordAction");
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(dock->recording()->buffer.count() >= 10, kWaitMs);
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);
        const ScopeRecording *recorded = dock->recording();
        const qsizetype samples = recorded->buffer.count();

        // Record again: asked first, and Cancel records nothing.
        record->trigger();
        QMessageBox *question = replaceQuestion(*dock);
        QVERIFY(question);
        QVERIFY(question->windowModality() != Qt::ApplicationModal);
        QVERIFY(question->button(QMessageBox::Save) && question->button(QMessageBox::Discard));
        QVERIFY(!record->isChecked()); // nothing records while it asks
        question->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY(!shownQuestion(*dock));
        QVERIFY(!dock->isRecording() && !record->isChecked());
        QCOMPARE(dock->recording(), recorded);
        QCOMPARE(dock->recording()->buffer.count(), samples);

        // Open Recording: asked first; Save keeps it in a file, then the file to open is asked.
        QTemporaryDir dir;
        const QString saved = dir.filePath(QStringLiteral("kept.ddscope"));
        action(*dock, "scopeOpenAction")->trigger();
        question = replaceQuestion(*dock);
        QVERIFY(question);
        question->button(QMessageBox::Save)->click();
        QVERIFY(chooseFile(window, QFileDialog::AcceptSave, saved));
        QTRY_VERIFY(QFileInfo::exists(saved));
        QCOMPARE(dock->recording(), recorded); // still shown until a file is opened
        QVERIFY(chooseFile(window, QFileDialog::AcceptOpen, saved));
        QTRY_VERIFY(dock->recording() != recorded);
        QCOMPARE(dock->recording()->buffer.count(), samples);

        // Opened from a file, it is saved: Record replaces it without a question.
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(dock->isRecording(), kWaitMs);
        QVERIFY(!shownQuestion(*dock));
        QTRY_VERIFY_WITH_TIMEOUT(dock->recording()->buffer.count() >= 10, kWaitMs);
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);

        // Recorded but not saved: Discard lets Record go ahead.
        const ScopeRecording *second = dock->recording();
        record->trigger();
        question = replaceQuestion(*dock);
        QVERIFY(question);
        question->button(QMessageBox::Discard)->click();
        QTRY_VERIFY_WITH_TIMEOUT(dock->isRecording(), kWaitMs);
        QVERIFY(dock->recording() != second);
        QTRY_VERIFY_WITH_TIMEOUT(dock->recording()->buffer.count() >= 10, kWaitMs);
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);

        // Closing the window with that recording unsaved: asked; Cancel keeps the window and
        // the recording, Discard closes.
        const ScopeRecording *third = dock->recording();
        QVERIFY(!window.close());
        question = replaceQuestion(*dock);
        QVERIFY(question);
        QVERIFY(question->text().contains(QStringLiteral("Closing DriveDesk")));
        question->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY(!shownQuestion(*dock));
        QVERIFY(window.isVisible());
        QCOMPARE(dock->recording(), third);
        QVERIFY(!window.close());
        question = replaceQuestion(*dock);
        QVERIFY(question);
        question->button(QMessageBox::Discard)->click();
        QTRY_VERIFY(!window.isVisible());
    }

    // HSP5 (seed 000) has no service 21: the offline records are not offered.
    void offlineRecordsAreOfferedWhereTheProtocolHasThem()
    {
        m_settings.clear();
        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        QAction *offline = action(*dock, "scopeOfflineAction");
        QVERIFY(!offline->isVisible());
        QVERIFY(!offline->isEnabled());
    }

    // A single shot keeps the shot and its pre-trigger time, not the wait before it: what is
    // saved and exported is the shot, the chart marks where it fired, and the cursors are in it.
    void aSingleShotKeepsTheShot()
    {
        m_settings.clear();
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        chooseSource(*dock, 0, kDcLinkVoltage);
        QAction *record = action(*dock, "scopeRecordAction");
        record->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(dock->recording()->buffer.count() >= 300, kWaitMs);
        ScopeChart *chart = dock->chart();
        const qint64 waitStart = dock->recording()->firstTime();
        chart->setCursorTime(0, double(waitStart));
        chart->setCursorTime(1, double(waitStart + 5));

        // A level the DC link's ripple crosses every few ms; a shot of 200 ms, 20 % before.
        const ScopeRecording &waited = *dock->recording();
        const double level = waited.displayValue(waited.buffer.count() - 1, 0);
        dock->findChild<QDoubleSpinBox *>(QStringLiteral("scopeTriggerLevel"))->setValue(level);
        dock->findChild<QSpinBox *>(QStringLiteral("scopeTriggerPre"))->setValue(20);
        dock->findChild<QDoubleSpinBox *>(QStringLiteral("scopeTriggerWindow"))->setValue(0.2);
        action(*dock, "scopeTriggerAction")->trigger(); // armed while recording: from now on
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);

        const ScopeRecording &shot = *dock->recording();
        const std::optional<qint64> trigger = chart->triggerTime();
        QVERIFY(trigger);
        QVERIFY2(shot.firstTime() >= *trigger - 40 && shot.firstTime() < *trigger,
                 qPrintable(QStringLiteral("%1 .. %2, trigger %3")
                                .arg(shot.firstTime()).arg(shot.lastTime()).arg(*trigger)));
        QVERIFY2(shot.lastTime() <= *trigger + 160 && shot.lastTime() > *trigger + 100,
                 qPrintable(QStringLiteral("%1 .. %2, trigger %3")
                                .arg(shot.firstTime()).arg(shot.lastTime()).arg(*trigger)));
        QVERIFY(shot.firstTime() > waitStart);
        QCOMPARE(chart->cursorTime(0), std::optional<double>(double(*trigger)));
        QCOMPARE(chart->cursorTime(1), std::optional<double>(double(shot.lastTime())));
        const ScopeTimeRange visible = chart->visibleTimeRange();
        QVERIFY(visible.fromMs <= shot.firstTime() && visible.toMs >= shot.lastTime());
        QVERIFY2(status(*dock).contains(QStringLiteral("Shot")), qPrintable(status(*dock)));

        // Another shot while this one is not saved: the question is titled after what was
        // asked for (it said "Record").
        action(*dock, "scopeTriggerAction")->trigger();
        QMessageBox *question = nullptr;
        QTRY_VERIFY((question = shownQuestion(*dock)) != nullptr);
        QCOMPARE(question->windowTitle(), QStringLiteral("Single Shot"));
        question->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY(!shownQuestion(*dock));
        QVERIFY(!dock->isRecording());

        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("shot.csv"));
        QString error;
        QVERIFY2(dock->exportCsv(csv, false, &error), qPrintable(error));
        QCOMPARE(csvLines(csv).size(), shot.buffer.count() + 1);
        const QString saved = dir.filePath(QStringLiteral("shot.ddscope"));
        QVERIFY2(dock->saveRecording(saved, &error), qPrintable(error));
        ScopeRecording reread;
        QVERIFY2(readScopeFile(saved, reread, &error), qPrintable(error));
        QCOMPARE(reread.buffer.count(), shot.buffer.count());
        // where it fired goes with it (an overlay is aligned at it), and is marked again
        QCOMPARE(shot.triggerMs, trigger);
        QCOMPARE(reread.triggerMs, trigger);
        QVERIFY2(dock->openRecording(saved, &error), qPrintable(error));
        QCOMPARE(chart->triggerTime(), trigger);
    }

    void theSourcesAndLooksAreRemembered()
    {
        m_settings.clear();
        {
            MainWindow window;
            window.show();
            QVERIFY(connectAndRead(window, simulated()));
            auto *dock = window.findChild<ScopeDock *>();
            chooseSource(*dock, 2, kOutputVoltage);
            // A set only for a set-programmable source.
            auto *set1 = dock->findChild<QComboBox *>(QStringLiteral("scopeSet1"));
            chooseSource(*dock, 0, kActualFrequency);
            QVERIFY(!set1->isEnabled());
            chooseSource(*dock, 0, kMaxSpeedForward);
            QVERIFY(set1->isEnabled());
            set1->setCurrentIndex(2);
            dock->channelPanel()->setChannelColor(2, QColor(Qt::darkRed));
            dock->channelPanel()->setChannelVisible(1, false);
            dock->channelPanel()->setOwnAxis(2, true);
            window.close(); // the window saves its features' settings
        }
        MainWindow window;
        window.show();
        auto *dock = window.findChild<ScopeDock *>();
        QCOMPARE(dock->channelPanel()->channelColor(2), QColor(Qt::darkRed));
        QVERIFY(!dock->channelPanel()->isChannelVisible(1));
        QVERIFY(!dock->chart()->isChannelVisible(1));
        QVERIFY(dock->chart()->hasChannelOwnAxis(2));
        QVERIFY(connectAndRead(window, simulated()));
        QCOMPARE(dock->channelPanel()->choices()[2],
                 std::optional<ChannelAssignment>(ChannelAssignment{kOutputVoltage, 0x01}));
        QCOMPARE(dock->channelPanel()->choices()[0],
                 std::optional<ChannelAssignment>(ChannelAssignment{kMaxSpeedForward, 0x04}));
    }

    void aTriggerWaitsAndCanBeCalledOff()
    {
        m_settings.clear();
        MainWindow window;
        window.show();
        QVERIFY(connectAndRead(window, simulated()));
        auto *dock = window.findChild<ScopeDock *>();
        chooseSource(*dock, 0, kDcLinkVoltage);
        dock->findChild<QDoubleSpinBox *>(QStringLiteral("scopeTriggerLevel"))->setValue(100000);
        QAction *shot = action(*dock, "scopeTriggerAction");
        shot->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(dock->isRecording(), kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(status(*dock).contains(QStringLiteral("Waiting for the trigger")),
                                 kWaitMs);
        shot->trigger(); // called off: the recording stops, what it has stays
        QTRY_VERIFY_WITH_TIMEOUT(!dock->isRecording(), kWaitMs);
        QVERIFY(dock->recording()->buffer.count() > 0);
    }

    // Typed as one types it into the parameter table's search, and Enter: the source is chosen
    // (it stayed "As the drive has it").
    void aSourceTypedByItsIdIsChosen()
    {
        m_settings.clear();
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(connectAndRead(window, simulated()));
        window.findChild<QAction *>(QStringLiteral("scopeViewAction"))->trigger();
        auto *dock = window.findChild<ScopeDock *>();
        QTRY_VERIFY(dock->isVisible());
        auto *source = dock->findChild<QComboBox *>(QStringLiteral("scopeSource1"));
        QVERIFY(source && source->isEnabled());
        for (const QString &typed : {QStringLiteral("ru.03"), QStringLiteral("RU.9")}) {
            source->setFocus();
            QTRY_VERIFY(source->lineEdit()->hasFocus());
            source->lineEdit()->selectAll();
            QTest::keyClicks(source->lineEdit(), typed);
            QTest::keyClick(source->lineEdit(), Qt::Key_Return);
            const int wanted = typed == QLatin1String("ru.03") ? 0x0203 : 0x0209;
            QTRY_COMPARE(source->currentData().toInt(), wanted);
            QVERIFY2(source->lineEdit()->text().startsWith(typed.left(3), Qt::CaseInsensitive)
                         && source->lineEdit()->text().contains(QLatin1String("  ")),
                     qPrintable(source->lineEdit()->text()));
        }
        // Not a source: what was chosen stays, and the field says it again.
        source->lineEdit()->selectAll();
        QTest::keyClicks(source->lineEdit(), QStringLiteral("zz.99"));
        QTest::keyClick(source->lineEdit(), Qt::Key_Return);
        QCOMPARE(source->currentData().toInt(), 0x0209);
        QTRY_COMPARE(source->lineEdit()->text(), source->itemText(source->currentIndex()));
    }

    void theChartKeepsItsRoomBesideTheMonitor()
    {
        checkTheChartsRoomBesideTheMonitor(Language::English);
    }

    // Last: the German catalogue stays installed for the rest of the program.
    void theChartKeepsItsRoomBesideTheMonitorInGerman()
    {
        QVERIFY(installTranslations(QStringLiteral("de")));
        QLocale::setDefault(QLocale(QLocale::German)); // as main() does for the language
        checkTheChartsRoomBesideTheMonitor(Language::German);
        QLocale::setDefault(QLocale::c());
    }
};

QTEST_MAIN(TestScopeDock)
#include "tst_scopedock.moc"
