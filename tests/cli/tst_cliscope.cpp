#include "CliTestSupport.h"

#include <QFile>
#include <QTemporaryDir>

#include <cmath>
#include <csignal>

using namespace DriveDesk::CliTest;

namespace {

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

// A scope preset as the window saves it: channel 1 on `first`, 2 off, 3 and 4 as the drive
// has them, at most `rateHz` polls a second.
QByteArray presetJson(const QString &first, int rateHz)
{
    return QStringLiteral(R"({
    "channels": [
        {"color": "#0072b2", "ownAxis": false, "source": "%1", "visible": true},
        {"ownAxis": false, "source": "off", "visible": true},
        {"ownAxis": false, "source": null, "visible": true},
        {"ownAxis": false, "source": null, "visible": false}
    ],
    "driveKind": "",
    "format": "drivedesk-scope-preset",
    "name": "DC link",
    "rateLimitHz": %2,
    "rollSeconds": 10,
    "trigger": {"channel": 1, "edge": "rising", "level": 0, "preTrigger": 0.2, "shotMs": 1000},
    "version": 1
}
)").arg(first).arg(rateHz).toUtf8();
}

QString writePreset(const QTemporaryDir &dir, const QByteArray &json)
{
    const QString path = dir.filePath(QStringLiteral("preset.json"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size())
        return {};
    return path;
}

} // namespace

// drivedesk-cli scope against the simulated drive: channels chosen by id, the CSV a user opens
// in a spreadsheet, the achieved rate, every bad input refused before anything is recorded.
class TestCliScope : public QObject
{
    Q_OBJECT
private slots:
    void recordsTheChosenChannelsAsCsv()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("trace.csv"));
        const Run run = sim({QStringLiteral("scope"), QStringLiteral("--channels"),
                             QStringLiteral("op.11,ru.9,dr.4"), QStringLiteral("--duration"),
                             QStringLiteral("300ms"), QStringLiteral("--csv"), csv});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        static const QRegularExpression achieved(QStringLiteral("achieved ([0-9.]+) Hz"));
        const QRegularExpressionMatch rate = achieved.match(run.out);
        QVERIFY2(rate.hasMatch() && rate.captured(1).toDouble() > 0, qPrintable(run.out));

        const QStringList lines = csvLines(csv);
        QVERIFY2(lines.size() > 10, qPrintable(lines.join(QLatin1Char('\n'))));
        QCOMPARE(lines.first(), QStringLiteral("Time [ms],op.11 Maximum speed forward [1/min],"
                                               "ru.09 Output voltage [V],"
                                               "dr.04 Rated motor voltage [V]"));
        // An answer repeating the sample before (the same drive millisecond, the same values)
        // is one row, and the rate counts the rows there are.
        for (qsizetype i = 2; i < lines.size(); ++i)
            QVERIFY2(lines.at(i) != lines.at(i - 1), qPrintable(lines.at(i)));
        const double spanMs = lines.constLast().section(QLatin1Char(','), 0, 0).toDouble();
        QVERIFY(spanMs > 0);
        QVERIFY2(std::abs(rate.captured(1).toDouble() - double(lines.size() - 2) * 1000.0 / spanMs)
                     < 0.11,
                 qPrintable(run.out));
        qint64 previous = -1;
        for (const QString &line : lines.mid(1)) {
            const QStringList fields = line.split(QLatin1Char(','));
            QCOMPARE(fields.size(), 4);
            const qint64 time = fields[0].toLongLong();
            QVERIFY(time >= previous && time <= 300);
            previous = time;
            QCOMPARE(fields[1], QStringLiteral("3000"));
            QCOMPARE(fields[3], QStringLiteral("400"));
        }
        QCOMPARE(lines.at(1).split(QLatin1Char(',')).first(), QStringLiteral("0"));
    }

    void theRateLimitHolds()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("slow.csv"));
        const Run run = sim({QStringLiteral("scope"), QStringLiteral("--channels"),
                             QStringLiteral("ru.18"), QStringLiteral("--duration"),
                             QStringLiteral("1s"), QStringLiteral("--rate"), QStringLiteral("40"),
                             QStringLiteral("--csv"), csv});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList lines = csvLines(csv);
        QCOMPARE(lines.first(), QStringLiteral("Time [ms],ru.18 DC link voltage [V]"));
        QVERIFY2(lines.size() - 1 <= 42, qPrintable(QString::number(lines.size())));
        QVERIFY(lines.size() - 1 >= 10);
    }

    void badInputIsRefusedBeforeAnythingIsRecorded_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("no csv") << QStringList{} << QStringLiteral("--csv");
        QTest::newRow("five channels")
            << QStringList{QStringLiteral("--channels"), QStringLiteral("ru.1,ru.3,ru.7,ru.9,ru.10")}
            << QStringLiteral("one to four");
        QTest::newRow("unknown parameter")
            << QStringList{QStringLiteral("--channels"), QStringLiteral("zz.3")}
            << QStringLiteral("zz");
        QTest::newRow("no process data")
            << QStringList{QStringLiteral("--channels"), QStringLiteral("ru.3,Sy.16")}
            << QStringLiteral("Sy.16");
        QTest::newRow("bad duration")
            << QStringList{QStringLiteral("--duration"), QStringLiteral("ten seconds")}
            << QStringLiteral("duration");
        QTest::newRow("offline with channels")
            << QStringList{QStringLiteral("--offline"), QStringLiteral("--channels"),
                           QStringLiteral("ru.3")}
            << QStringLiteral("--offline");
        QTest::newRow("offline with a preset")
            << QStringList{QStringLiteral("--offline"), QStringLiteral("--preset"),
                           QStringLiteral("preset.json")}
            << QStringLiteral("--offline");
        QTest::newRow("set out of range")
            << QStringList{QStringLiteral("--channels"), QStringLiteral("op.11@9")}
            << QStringLiteral("0..7");
        QTest::newRow("zero rate")
            << QStringList{QStringLiteral("--rate"), QStringLiteral("0")}
            << QStringLiteral("--rate");
    }

    void badInputIsRefusedBeforeAnythingIsRecorded()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("never.csv"));
        QStringList command{QStringLiteral("scope")};
        command << arguments;
        if (QLatin1String(QTest::currentDataTag()) != QLatin1String("no csv"))
            command << QStringLiteral("--csv") << csv;
        const Run run = sim(command);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(message), qPrintable(explain(run)));
        QVERIFY(!QFile::exists(csv));
    }

    void channelsThatAreAllOffAreNoRecording()
    {
        // The simulated F5 starts with every read channel off (Sy.16 = -1).
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("empty.csv"));
        const Run run = sim({QStringLiteral("scope"), QStringLiteral("--csv"), csv});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--channels")), qPrintable(explain(run)));
        QVERIFY(!QFile::exists(csv));
    }

    void readsTheOfflineRecordsOverDin66019II()
    {
        // One drive for both commands: the first puts DC link voltage on channel 1, the drive
        // keeps recording it offline, the second reads those records.
        SimulatorProcess server({QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                                 QStringLiteral("--latency-us"), QStringLiteral("0")});
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QStringList connection{QStringLiteral("--connect"), server.target(),
                                     QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                                     QStringLiteral("--quiet")};
        QTemporaryDir dir;
        const Run assign = cli(connection + QStringList{
            QStringLiteral("scope"), QStringLiteral("--channels"), QStringLiteral("ru.18"),
            QStringLiteral("--duration"), QStringLiteral("50ms"), QStringLiteral("--csv"),
            dir.filePath(QStringLiteral("live.csv"))}, dir.path());
        QVERIFY2(assign.exitCode == 0, qPrintable(explain(assign)));
        QTest::qWait(800); // 64 records, one each 10 ms

        const QString csv = dir.filePath(QStringLiteral("offline.csv"));
        const Run run = cli(connection + QStringList{QStringLiteral("scope"),
                                                     QStringLiteral("--offline"),
                                                     QStringLiteral("--csv"), csv}, dir.path());
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("64 offline records")), qPrintable(run.out));
        const QStringList lines = csvLines(csv);
        QCOMPARE(lines.size(), 65);
        QCOMPARE(lines.first(), QStringLiteral("Time [ms],ru.18 DC link voltage [V]"));
        for (qsizetype i = 1; i < lines.size(); ++i) {
            const QStringList fields = lines.at(i).split(QLatin1Char(','));
            QCOMPARE(fields.at(0), QString::number(i - 1));
            QVERIFY2(fields.at(1).toInt() > 400, qPrintable(lines.at(i))); // a DC link's volts
        }

        // A source read from another set: what was written there, named with its set.
        const Run written = cli(connection + QStringList{QStringLiteral("write"),
                                                         QStringLiteral("op.11"),
                                                         QStringLiteral("2500"),
                                                         QStringLiteral("--sets"),
                                                         QStringLiteral("2")}, dir.path());
        QVERIFY2(written.exitCode == 0, qPrintable(explain(written)));
        const QString perSet = dir.filePath(QStringLiteral("set2.csv"));
        const Run set2 = cli(connection + QStringList{
            QStringLiteral("scope"), QStringLiteral("--channels"), QStringLiteral("op.11@2,op.11"),
            QStringLiteral("--duration"), QStringLiteral("50ms"), QStringLiteral("--csv"), perSet},
                             dir.path());
        QVERIFY2(set2.exitCode == 0, qPrintable(explain(set2)));
        const QStringList setLines = csvLines(perSet);
        QCOMPARE(setLines.first(), QStringLiteral("Time [ms],op.11 Maximum speed forward (set 2) "
                                                  "[1/min],op.11 Maximum speed forward [1/min]"));
        QVERIFY(setLines.size() > 1);
        QCOMPARE(setLines.at(1).section(QLatin1Char(','), 1), QStringLiteral("2500,3000"));

        // Over HSP5 as the specification has it there is no service 21: said so, no file.
        const Run hsp5 = sim({QStringLiteral("scope"), QStringLiteral("--offline"),
                              QStringLiteral("--csv"), dir.filePath(QStringLiteral("no.csv"))});
        QCOMPARE(hsp5.exitCode, 1);
        QVERIFY2(hsp5.err.contains(QStringLiteral("service 21")), qPrintable(explain(hsp5)));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("no.csv"))));
    }

    void anUnwritableFileIsNamed()
    {
        const QString csv = QStringLiteral("/nonexistent-folder/trace.csv");
        const Run run = sim({QStringLiteral("scope"), QStringLiteral("--channels"),
                             QStringLiteral("ru.3"), QStringLiteral("--duration"),
                             QStringLiteral("100ms"), QStringLiteral("--csv"), csv});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(csv), qPrintable(explain(run)));
    }

    void ctrlCStopsAndWritesWhatWasRecorded()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("stopped.csv"));
        QProcess process;
        process.start(kCli, {QStringLiteral("--connect"), QStringLiteral("sim"),
                             QStringLiteral("scope"), QStringLiteral("--channels"),
                             QStringLiteral("ru.3"), QStringLiteral("--duration"),
                             QStringLiteral("10min"), QStringLiteral("--csv"), csv});
        QVERIFY(process.waitForStarted());
        // The command says when it starts recording (--quiet is off for it).
        process.setReadChannel(QProcess::StandardError);
        QVERIFY(QTest::qWaitFor([&] {
            process.waitForReadyRead(100);
            return process.peek(1 << 16).contains("Ctrl+C");
        }, 20000));
        QTest::qWait(300);
        ::kill(pid_t(process.processId()), SIGINT);
        QVERIFY(process.waitForFinished(20000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 0);
        QVERIFY(csvLines(csv).size() > 2);
        QVERIFY(QString::fromUtf8(process.readAllStandardOutput()).contains(QStringLiteral("achieved")));
    }

    // The channels and the rate limit of a preset saved in the window.
    void recordsWithAPreset()
    {
        QTemporaryDir dir;
        const QString preset = writePreset(dir, presetJson(QStringLiteral("ru.18"), 40));
        const QString csv = dir.filePath(QStringLiteral("preset.csv"));
        const Run run = sim({QStringLiteral("scope"), QStringLiteral("--preset"), preset,
                             QStringLiteral("--duration"), QStringLiteral("1s"),
                             QStringLiteral("--csv"), csv});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList lines = csvLines(csv);
        QCOMPARE(lines.first(), QStringLiteral("Time [ms],ru.18 DC link voltage [V]"));
        QVERIFY2(lines.size() - 1 <= 42, qPrintable(QString::number(lines.size())));
        QVERIFY(lines.size() - 1 >= 10);

        // --channels and --rate given win over the preset's.
        const QString overridden = dir.filePath(QStringLiteral("overridden.csv"));
        const Run both = sim({QStringLiteral("scope"), QStringLiteral("--preset"), preset,
                              QStringLiteral("--channels"), QStringLiteral("ru.9,op.11"),
                              QStringLiteral("--rate"), QStringLiteral("400"),
                              QStringLiteral("--duration"), QStringLiteral("500ms"),
                              QStringLiteral("--csv"), overridden});
        QVERIFY2(both.exitCode == 0, qPrintable(explain(both)));
        const QStringList bothLines = csvLines(overridden);
        QCOMPARE(bothLines.first(), QStringLiteral("Time [ms],ru.09 Output voltage [V],"
                                                   "op.11 Maximum speed forward [1/min]"));
        QVERIFY2(bothLines.size() - 1 > 42, qPrintable(QString::number(bothLines.size())));
    }

    // A bad preset is refused before the drive is reached: the port below has no drive.
    void aBadPresetIsRefusedBeforeTheDriveIsReached_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("not a parameter") << presetJson(QStringLiteral("speed"), 0)
                                         << QStringLiteral("channel 1's source: 'speed' is not a "
                                                           "parameter id");
        QTest::newRow("not JSON") << QByteArray("{\"channels\": [") << QStringLiteral("not JSON");
        QTest::newRow("newer") << presetJson(QStringLiteral("ru.18"), 0)
                                      .replace("\"version\": 1", "\"version\": 7")
                               << QStringLiteral("newer format");
    }

    void aBadPresetIsRefusedBeforeTheDriveIsReached()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString preset = writePreset(dir, json);
        const QString csv = dir.filePath(QStringLiteral("never.csv"));
        const Run run = cli({QStringLiteral("--connect"), QStringLiteral("tcp:127.0.0.1:9"),
                             QStringLiteral("--timeout"), QStringLiteral("200"),
                             QStringLiteral("scope"), QStringLiteral("--preset"), preset,
                             QStringLiteral("--csv"), csv});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("preset file '%1'").arg(preset)),
                 qPrintable(explain(run)));
        QVERIFY2(run.err.contains(message), qPrintable(explain(run)));
        QVERIFY(!QFile::exists(csv));

        // A source this drive has no group for: the drive's to say, exit 2, no file.
        const QString unknown = writePreset(dir, presetJson(QStringLiteral("zz.3"), 0));
        const Run drive = sim({QStringLiteral("scope"), QStringLiteral("--preset"), unknown,
                               QStringLiteral("--csv"), csv});
        QCOMPARE(drive.exitCode, 2);
        QVERIFY2(drive.err.contains(QStringLiteral("zz")), qPrintable(explain(drive)));
        QVERIFY(!QFile::exists(csv));
    }
};

QTEST_GUILESS_MAIN(TestCliScope)
#include "tst_cliscope.moc"
