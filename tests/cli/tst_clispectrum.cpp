#include "CliTestSupport.h"

#include "scope/ScopeCsv.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeRecording.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cmath>

using namespace DriveDesk;
using namespace DriveDesk::CliTest;

namespace {

// A recording whose drive clock starts at 12345 ms: channel 1 ru.03 in Hz (hundredths) is
// 12.5 Hz at 50 Hz plus 2 Hz at 80 Hz for the first 2 s, then 3 Hz at 130 Hz for 2 s more;
// channel 3 ru.09 in V holds 230 V; channels 2 and 4 are off. Steps of 1 ms, or of 1 and 2 ms
// in turn where `uneven`.
ScopeRecording recording(bool uneven)
{
    ScopeRecording made;
    made.source = QStringLiteral("test");
    ScopeChannel frequency;
    frequency.source = 0x0203;
    frequency.id = QStringLiteral("ru.03");
    frequency.name = QStringLiteral("Actual frequency");
    frequency.scaling = DisplayScaling(DisplayScalingData { 0x0203, 100, 1, 0, 18 | (2 << 8) });
    ScopeChannel voltage;
    voltage.source = 0x0209;
    voltage.id = QStringLiteral("ru.09");
    voltage.name = QStringLiteral("Output voltage");
    voltage.scaling = DisplayScaling(DisplayScalingData { 0x0209, 1, 1, 0, 21 });
    made.channels = { frequency, ScopeChannel(), voltage, ScopeChannel() };
    made.channels[1].enabled = false;
    made.channels[3].enabled = false;
    for (qint64 t = 0; t < 4000; t += uneven && t % 3 == 1 ? 2 : 1) {
        const double s = double(t) / 1000;
        const double hz = t < 2000
            ? 12.5 * std::sin(2 * M_PI * 50 * s) + 2 * std::sin(2 * M_PI * 80 * s)
            : 3 * std::sin(2 * M_PI * 130 * s);
        ScopeSample sample;
        sample.time = 12345 + t;
        sample.wide = { qint32(std::lround(hz * 100)), 0 };
        sample.narrow = { 230, 0 };
        made.buffer.append(sample);
    }
    return made;
}

QString writeRecordingFile(const QTemporaryDir &dir, const ScopeRecording &recording)
{
    const QString path = dir.filePath(QStringLiteral("shot.ddscope"));
    ScopeFileWriter writer;
    QString error;
    if (!writer.open(path, ScopeFileHeader::of(recording), &error)
        || !writer.append(recording.buffer.samples(), 0, recording.buffer.count(), &error)
        || !writer.close(&error))
        qWarning() << error;
    return path;
}

QJsonObject spectrumJson(const QStringList &arguments, Run *run)
{
    *run = cli(QStringList { QStringLiteral("spectrum") } + arguments
               + QStringList { QStringLiteral("--format"), QStringLiteral("json") });
    return QJsonDocument::fromJson(run->out.toUtf8()).object();
}

// The peak `index` near `hz` (within one bin) with `amplitude` (within `tolerance`).
bool hasPeak(const QJsonObject &spectrum, int index, double hz, double amplitude,
             double tolerance = 0.02)
{
    const QJsonObject peak = spectrum.value(QStringLiteral("peaks")).toArray().at(index).toObject();
    return std::abs(peak.value(QStringLiteral("frequencyHz")).toDouble() - hz)
        < spectrum.value(QStringLiteral("binHz")).toDouble()
        && std::abs(peak.value(QStringLiteral("amplitude")).toDouble() - amplitude)
        < tolerance * amplitude;
}

} // namespace

// drivedesk-cli spectrum on files the project's own writers made: a recording file and a CSV
// export, their channels chosen by id, title or number, a window, and every bad input refused
// with exit 2 and its reason.
class TestCliSpectrum : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_recordingFile = writeRecordingFile(m_dir, recording(false));
        m_csv = m_dir.filePath(QStringLiteral("trace.csv"));
        ScopeCsvOptions options;
        options.channels = { 0, 2 };
        QString error;
        QVERIFY2(saveScopeCsv(m_csv, recording(false), options, &error), qPrintable(error));
    }

    void recordingFileAsJson()
    {
        Run run;
        const QJsonObject spectrum = spectrumJson(
            { m_recordingFile, QStringLiteral("--to"), QStringLiteral("1999") }, &run);
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(spectrum.value(QStringLiteral("channel")).toString(),
                 QStringLiteral("ru.03 Actual frequency"));
        QCOMPARE(spectrum.value(QStringLiteral("unit")).toString(), QStringLiteral("Hz"));
        QCOMPARE(spectrum.value(QStringLiteral("fromMs")).toDouble(), 0.0);
        QCOMPARE(spectrum.value(QStringLiteral("toMs")).toDouble(), 1999.0);
        QCOMPARE(spectrum.value(QStringLiteral("samples")).toInt(), 2000);
        QCOMPARE(spectrum.value(QStringLiteral("sampleRateHz")).toDouble(), 1000.0);
        QCOMPARE(spectrum.value(QStringLiteral("resampled")).toBool(), false);
        QCOMPARE(spectrum.value(QStringLiteral("peaks")).toArray().size(), 5);
        QVERIFY2(hasPeak(spectrum, 0, 50, 12.5) && hasPeak(spectrum, 1, 80, 2),
                 qPrintable(run.out));
    }

    // --from and --to count from the recording's first sample (12345 ms on the drive's clock).
    void theWindowPicksItsPart()
    {
        Run run;
        const QJsonObject spectrum
            = spectrumJson({ m_recordingFile, QStringLiteral("--from"), QStringLiteral("2000"),
                             QStringLiteral("--to"), QStringLiteral("3999"),
                             QStringLiteral("--peaks"), QStringLiteral("1") },
                           &run);
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(spectrum.value(QStringLiteral("fromMs")).toDouble(), 2000.0);
        QCOMPARE(spectrum.value(QStringLiteral("peaks")).toArray().size(), 1);
        QVERIFY2(hasPeak(spectrum, 0, 130, 3), qPrintable(run.out));
    }

    void csvExportAsTable()
    {
        const Run run
            = cli({ QStringLiteral("spectrum"), m_csv, QStringLiteral("--channel"),
                    QStringLiteral("ru.3"), QStringLiteral("--to"), QStringLiteral("1999"),
                    QStringLiteral("--peaks"), QStringLiteral("2") });
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList lines = run.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.value(0),
                 QStringLiteral("ru.03 Actual frequency [Hz] in '%1', 0 to 1999 ms").arg(m_csv));
        QCOMPARE(lines.value(1), QStringLiteral("2000 samples at 1000 Hz, 0.5 Hz a bin"));
        QCOMPARE(lines.value(2).simplified(), QStringLiteral("frequency [Hz] amplitude [Hz]"));
        QCOMPARE(lines.size(), 5);
        const QStringList first = lines.value(3).simplified().split(QLatin1Char(' '));
        QCOMPARE(first.value(0), QStringLiteral("50.00"));
        QVERIFY2(std::abs(first.value(1).toDouble() - 12.5) < 0.25, qPrintable(run.out));
        QCOMPARE(lines.value(4).simplified().split(QLatin1Char(' ')).value(0),
                 QStringLiteral("80.00"));
    }

    // The same channel by its title or number; the recording file's numbers are the drive's
    // channels, the CSV's its columns.
    void channelsByTitleOrNumber()
    {
        Run run;
        QJsonObject spectrum = spectrumJson(
            { m_recordingFile, QStringLiteral("--channel"), QStringLiteral("3") }, &run);
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(spectrum.value(QStringLiteral("channel")).toString(),
                 QStringLiteral("ru.09 Output voltage"));
        QCOMPARE(spectrum.value(QStringLiteral("peaks")).toArray().size(), 0); // 230 V, flat
        spectrum = spectrumJson({ m_csv, QStringLiteral("--channel"), QStringLiteral("2") }, &run);
        QCOMPARE(spectrum.value(QStringLiteral("channel")).toString(),
                 QStringLiteral("ru.09 Output voltage"));
        spectrum = spectrumJson(
            { m_csv, QStringLiteral("--channel"), QStringLiteral("RU.03 actual frequency") }, &run);
        QCOMPARE(spectrum.value(QStringLiteral("unit")).toString(), QStringLiteral("Hz"));
    }

    void unevenSamplesAreResampled()
    {
        QTemporaryDir dir;
        Run run;
        const QJsonObject spectrum
            = spectrumJson({ writeRecordingFile(dir, recording(true)), QStringLiteral("--to"),
                             QStringLiteral("1999") },
                           &run);
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(spectrum.value(QStringLiteral("resampled")).toBool(), true);
        // Straight lines between samples 1 and 2 ms apart damp 50 Hz by a few percent.
        QVERIFY2(hasPeak(spectrum, 0, 50, 12.5, 0.04), qPrintable(run.out));
    }

    void badInputIsRefused_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        const QString missing = m_dir.filePath(QStringLiteral("missing.csv"));
        QTest::newRow("missing file")
            << QStringList { missing }
            << QStringLiteral("cannot read '%1': No such file or directory").arg(missing);
        QTest::newRow("not a recording")
            << QStringList { QStringLiteral(DRIVEDESK_TEST_DATA "/../CMakeLists.txt") }
            << QStringLiteral("is not a scope CSV export");
        QTest::newRow("no such channel")
            << QStringList { m_recordingFile, QStringLiteral("--channel"), QStringLiteral("ru.18") }
            << QStringLiteral("has no channel 'ru.18'; it holds ru.03 Actual frequency (1), ru.09 "
                              "Output voltage (3)");
        QTest::newRow("a channel that is off")
            << QStringList { m_recordingFile, QStringLiteral("--channel"), QStringLiteral("2") }
            << QStringLiteral("has no channel '2'");
        QTest::newRow("from after the end")
            << QStringList { m_csv, QStringLiteral("--from"), QStringLiteral("4000") }
            << QStringLiteral("--from 4000 ms is outside the recording in '%1' (0 to 3999 ms)")
                   .arg(m_csv);
        QTest::newRow("to after the end")
            << QStringList { m_recordingFile, QStringLiteral("--to"), QStringLiteral("5000") }
            << QStringLiteral("--to 5000 ms is outside the recording");
        QTest::newRow("too few samples")
            << QStringList { m_recordingFile, QStringLiteral("--from"), QStringLiteral("100"),
                             QStringLiteral("--to"), QStringLiteral("110") }
            << QStringLiteral("ru.03 Actual frequency: too few samples for a spectrum: 11 in the "
                              "window, at least 16 needed");
        QTest::newRow("from after to")
            << QStringList { m_csv, QStringLiteral("--from"), QStringLiteral("300"),
                             QStringLiteral("--to"), QStringLiteral("200") }
            << QStringLiteral("--from must come before --to");
        QTest::newRow("a negative time")
            << QStringList { m_csv, QStringLiteral("--from"), QStringLiteral("-5") }
            << QStringLiteral("--from takes ms from the recording's start");
        QTest::newRow("no peaks") << QStringList { m_csv, QStringLiteral("--peaks"),
                                                   QStringLiteral("0") }
                                  << QStringLiteral("--peaks");
        QTest::newRow("no file") << QStringList {}
                                 << QStringLiteral("spectrum takes a scope CSV export");
        QTest::newRow("a drive") << QStringList { QStringLiteral("--connect"),
                                                  QStringLiteral("sim"), m_csv }
                                 << QStringLiteral("spectrum reads a file: --connect");
        QTest::newRow("csv") << QStringList { m_csv, QStringLiteral("--format"),
                                              QStringLiteral("csv") }
                             << QStringLiteral("spectrum writes json or table");
    }

    void badInputIsRefused()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const Run run = cli(QStringList { QStringLiteral("spectrum") } + arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(message), qPrintable(explain(run)));
        QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
    }

    // The spectrum's options belong to it alone.
    void otherCommandsRefuseTheOptions()
    {
        const Run run
            = sim({ QStringLiteral("info"), QStringLiteral("--channel"), QStringLiteral("ru.3") });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--channel belongs to spectrum")),
                 qPrintable(run.err));
    }

private:
    QTemporaryDir m_dir;
    QString m_recordingFile;
    QString m_csv;
};

QTEST_GUILESS_MAIN(TestCliSpectrum)
#include "tst_clispectrum.moc"
