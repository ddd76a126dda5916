#include "tst_mainwindow_support.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"
#include "scope/ScopeFileReader.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeChannelPanel.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeDock.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

constexpr quint16 kActualFrequency = 0x0203; // ru.03, 0.01 Hz
constexpr quint16 kDcLinkVoltage = 0x0212;   // ru.18, V
constexpr quint16 kOutputVoltage = 0x0209;   // ru.09, V
constexpr quint16 kMaxSpeedForward = 0x030B; // op.11, 8 sets
constexpr quint16 kChannel1Source = 0x0010;  // Sy.16
constexpr quint16 kChannel3Source = 0x0014;  // Sy.20
constexpr quint16 kChannel4Source = 0x0016;  // Sy.22

void chooseSource(ScopeDock &dock, int channel, int address)
{
    auto *box = dock.findChild<QComboBox *>(QStringLiteral("scopeSource%1").arg(channel + 1));
    QVERIFY(box);
    const int index = box->findData(address);
    QVERIFY2(index >= 0, qPrintable(QStringLiteral("no source %1").arg(address)));
    box->setCurrentIndex(index);
}

QAction *action(ScopeDock &dock, const char *name)
{
    return dock.findChild<QAction *>(QLatin1String(name));
}

QString status(ScopeDock &dock)
{
    return dock.findChild<QLabel *>(QStringLiteral("scopeStatus"))->text();
}

QStringList csvLines(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QStringList lines = QString::fromUtf8(file.readAll()).split(QStringLiteral("\r\n"));
    if (!lines.isEmpty() && lines.constLast().isEmpty())
        lines.removeLast();
    return lines;
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
        QCOMPARE(window.model()->value(kChannel1Source, 0), std::optional<qint32>(kActualFrequency));
        QCOMPARE(window.model()->value(kChannel4Source, 0), std::optional<qint32>(ChannelAssignment::kOff));
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
        QVERIFY(offline->isEnabled());
        offline->trigger();
        QVERIFY(!offline->isEnabled()); // while it reads
        QTRY_VERIFY_WITH_TIMEOUT(offline->isEnabled(), kWaitMs);
        QVERIFY2(status(*dock).startsWith(QStringLiteral("64 ")), qPrintable(status(*dock)));
        const ScopeRecording &recording = *dock->recording();
        QCOMPARE(recording.buffer.count(), 64);
        QCOMPARE(recording.channels[0].id, QStringLiteral("ru.18"));
        QVERIFY(recording.source.contains(QStringLiteral("one a millisecond")));
        QVERIFY(recording.buffer.samples().value(0, 0) > 400); // a DC link's volts
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
};

QTEST_MAIN(TestScopeDock)
#include "tst_scopedock.moc"
