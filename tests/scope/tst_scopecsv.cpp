#include "scope/ScopeCsv.h"
#include "scope/ScopeMath.h"
#include "scope/ScopeRecording.h"

#include <QBuffer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <QMap>

#include <cmath>
#include <limits>

using namespace DriveDesk;

namespace {

constexpr quint16 kHz = 18;
constexpr quint16 kPercent = 37;

quint16 flags(quint16 unit, int representation, int mode = 0)
{
    return quint16(unit | (mode << 6) | (representation << 8));
}

ScopeChannel channel(quint16 address, const QString &id, const QString &name,
                     DisplayScalingData scaling)
{
    ScopeChannel described;
    described.source = address;
    described.id = id;
    described.name = name;
    scaling.address = address;
    described.scaling = DisplayScaling(scaling);
    return described;
}

ScopeSample sample(qint64 time, qint32 wide0, qint32 wide1, qint16 narrow0, qint16 narrow1)
{
    ScopeSample made;
    made.time = time;
    made.wide = { wide0, wide1 };
    made.narrow = { narrow0, narrow1 };
    return made;
}

// Four channels as they come: a scaled one with a unit (divisor 10, one decimal), an unknown
// source (raw), a hexadecimal status word whose name needs quoting, and a channel that is off
// with variable decimals.
void describe(ScopeRecording &recording)
{
    recording.channels[0]
        = channel(0x0203, QStringLiteral("ru.03"), QStringLiteral("Actual frequency"),
                  { 0, 10, 1, 0, flags(kHz, 1) });
    recording.channels[2]
        = channel(0x0200, QStringLiteral("ru.00"), QStringLiteral("Status \"word\", bits"),
                  { 0, 1, 1, 0, flags(0, 6) });
    recording.channels[3] = channel(0x0207, QStringLiteral("ru.07"), QStringLiteral("Load"),
                                    { 0, 1000, 1, 0, flags(kPercent, 5) });
    recording.channels[3].enabled = false;
}

void fill(ScopeRecording &recording)
{
    const qint32 max = std::numeric_limits<qint32>::max();
    const qint32 min = std::numeric_limits<qint32>::min();
    for (const ScopeSample &s :
         { sample(1000, 125, -5, 255, -32768), sample(1001, -125, max, -1, 12500),
           sample(1003, -4, min, 0, 12000), sample(1003, 0, 0, 32767, -1),
           sample(1010, -1, 7, -32768, 0) })
        QVERIFY(recording.buffer.append(s));
}

const QByteArray kHeader = "Time [ms],ru.03 Actual frequency [Hz],Channel 2,"
                           "\"ru.00 Status \"\"word\"\", bits\",ru.07 Load [%]\r\n";

QByteArray csvOf(const ScopeRecording &recording, const ScopeCsvOptions &options = {})
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QString error;
    if (!writeScopeCsv(buffer, recording, options, &error))
        qWarning("%s", qPrintable(error));
    return buffer.data();
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("(missing)");
}

} // namespace

// A recording as CSV: exact bytes, ranges, chosen channels, whole-or-nothing files, cancel.
class TestScopeCsv : public QObject
{
    Q_OBJECT

private slots:
    void wholeRecording()
    {
        ScopeRecording recording;
        describe(recording);
        fill(recording);
        QCOMPARE(csvOf(recording),
                 kHeader
                     + "0,12.5,-5,255,-32.768\r\n"
                       "1,-12.5,2147483647,-1,12.5\r\n"
                       "3,-0.4,-2147483648,0,12\r\n"
                       "3,0.0,0,32767,-0.001\r\n"
                       "10,-0.1,7,-32768,0\r\n");
    }

    void rangeIsInclusiveAndTimesStayRelativeToTheRecording()
    {
        ScopeRecording recording;
        describe(recording);
        fill(recording);
        ScopeCsvOptions options;
        options.fromMs = 1001;
        options.toMs = 1003;
        QCOMPARE(csvOf(recording, options),
                 kHeader
                     + "1,-12.5,2147483647,-1,12.5\r\n"
                       "3,-0.4,-2147483648,0,12\r\n"
                       "3,0.0,0,32767,-0.001\r\n");
        options.fromMs = 1010;
        options.toMs = 5000;
        QCOMPARE(csvOf(recording, options), kHeader + "10,-0.1,7,-32768,0\r\n");
    }

    // The cursors' measurements after the samples: a ramp of 1 Hz a ms from 0 Hz at t = 1000,
    // cursors at 1008 and 1002 (either order), so the samples from 2 to 8 Hz count.
    void measurementsFollowTheSamples()
    {
        ScopeRecording recording;
        recording.channels[0] = channel(0x0203, QStringLiteral("ru.03"),
                                        QStringLiteral("Actual frequency"),
                                        { 0, 10, 1, 0, flags(kHz, 1) });
        for (qint64 t = 1000; t <= 1010; ++t)
            QVERIFY(recording.buffer.append(sample(t, qint32(10 * (t - 1000)), 0, 0, 0)));
        // A math channel goes along as a column of its own: the ramp's slope, 1000 Hz/s.
        const ScopeMathResult slope = computeScopeMath(ScopeMathDefinition(), recording);
        QVERIFY(slope.ok());
        ScopeCsvOptions options;
        options.channels = { 0, 1 };
        options.math = { &slope.series };
        options.fromMs = 1009;
        options.measureBetweenMs = std::pair(1008.0, 1002.0);
        const QList<QByteArray> lines = csvOf(recording, options).split('\n');
        // The samples asked for, an empty line, then the section: header and twelve rows.
        QCOMPARE(lines.at(0),
                 QByteArray("Time [ms],ru.03 Actual frequency [Hz],Channel 2,"
                            "d/dt ru.03 Actual frequency [Hz/s]\r"));
        QCOMPARE(lines.at(1), QByteArray("9,9.0,0,1000\r"));
        QCOMPARE(lines.at(3), QByteArray("\r"));
        QCOMPARE(lines.at(4), QByteArray("Measurement,ru.03 Actual frequency [Hz],Channel 2,"
                                         "d/dt ru.03 Actual frequency [Hz/s]\r"));
        QCOMPARE(lines.size(), 4 + 1 + 12 + 1);
        QMap<QByteArray, double> first;
        QMap<QByteArray, QByteArray> second;
        QMap<QByteArray, QByteArray> math;
        for (qsizetype i = 5; i < lines.size() - 1; ++i) {
            const QList<QByteArray> fields = lines.at(i).chopped(1).split(',');
            QCOMPARE(fields.size(), 4);
            math[fields.at(0)] = fields.at(3);
            bool ok = fields.at(1).isEmpty();
            first[fields.at(0)] = ok ? qQNaN() : fields.at(1).toDouble(&ok);
            QVERIFY2(ok, lines.at(i).constData());
            second[fields.at(0)] = fields.at(2);
        }
        const auto near = [](double a, double b) { return std::abs(a - b) < 1e-9; };
        QCOMPARE(first.value("From [ms]"), 2.0); // the file's time, from the first sample
        QCOMPARE(first.value("To [ms]"), 8.0);
        QCOMPARE(first.value("Samples"), 7.0);
        QCOMPARE(first.value("Minimum"), 2.0);
        QCOMPARE(first.value("Maximum"), 8.0);
        QCOMPARE(first.value("Peak to peak"), 6.0);
        QVERIFY(near(first.value("Mean"), 5.0));
        QVERIFY(near(first.value("RMS"), std::sqrt((2.0 * 2 + 2.0 * 8 + 8.0 * 8) / 3)));
        QVERIFY(near(first.value("Rise time [ms]"), 4.8)); // from 2.6 Hz to 7.4 Hz
        QVERIFY(near(first.value("Rise rate [unit/s]"), 1000.0));
        QVERIFY(qIsNaN(first.value("Fall time [ms]")));
        QVERIFY(qIsNaN(first.value("Fall rate [unit/s]")));
        // Channel 2 is flat (0): its levels meet, so no rise.
        QCOMPARE(second.value("Samples"), QByteArray("7"));
        QCOMPARE(second.value("Peak to peak"), QByteArray("0"));
        QCOMPARE(second.value("Rise time [ms]"), QByteArray());
        QCOMPARE(math.value("Samples"), QByteArray("7"));
        QCOMPARE(math.value("Mean"), QByteArray("1000"));
        QCOMPARE(math.value("Peak to peak"), QByteArray("0"));
    }

    void emptyRangeGivesTheHeaderOnly()
    {
        ScopeRecording recording;
        describe(recording);
        fill(recording);
        ScopeCsvOptions options;
        options.fromMs = 1004;
        options.toMs = 1009;
        QCOMPARE(csvOf(recording, options), kHeader);
        options.fromMs = 1003;
        options.toMs = 1001;
        QCOMPARE(csvOf(recording, options), kHeader);
        QCOMPARE(csvOf(ScopeRecording()), "Time [ms],Channel 1,Channel 2,Channel 3,Channel 4\r\n");
    }

    void chosenChannelsInTheOrderAsked()
    {
        ScopeRecording recording;
        describe(recording);
        fill(recording);
        ScopeCsvOptions options;
        options.channels = { 3, 0 };
        options.toMs = 1001;
        QCOMPARE(csvOf(recording, options),
                 "Time [ms],ru.07 Load [%],ru.03 Actual frequency [Hz]\r\n"
                 "0,-32.768,12.5\r\n"
                 "1,12.5,-12.5\r\n");
        options.channels = {};
        QCOMPARE(csvOf(recording, options), "Time [ms]\r\n0\r\n1\r\n");
    }

    void valuesWithoutAScaledNumber()
    {
        ScopeRecording recording;
        // divisor 0: the raw value, as the chart shows it; mode 1 at raw + offset = 0: empty
        recording.channels[0] = channel(0x0203, QStringLiteral("ru.03"), QStringLiteral("F"),
                                        { 0, 0, 1, 0, flags(kHz, 2) });
        recording.channels[1] = channel(0x0204, QStringLiteral("ru.04"), QStringLiteral("T"),
                                        { 0, 1, 1000, 0, flags(0, 0, 1) });
        QVERIFY(recording.buffer.append(sample(0, 1234, 0, 0, 0)));
        QVERIFY(recording.buffer.append(sample(1, -7, 8, 0, 0)));
        ScopeCsvOptions options;
        options.channels = { 0, 1 };
        QCOMPARE(csvOf(recording, options),
                 "Time [ms],ru.03 F [Hz],ru.04 T\r\n"
                 "0,1234,\r\n"
                 "1,-7,125\r\n");
    }

    void badChannelAndWriteErrors()
    {
        ScopeRecording recording;
        fill(recording);
        ScopeCsvOptions options;
        options.channels = { 0, 4 };
        QBuffer buffer;
        buffer.open(QIODevice::WriteOnly);
        QString error;
        QVERIFY(!writeScopeCsv(buffer, recording, options, &error));
        QCOMPARE(error, QStringLiteral("there is no channel 5"));
        QCOMPARE(buffer.data(), QByteArray());

        QBuffer readOnly;
        readOnly.open(QIODevice::ReadOnly);
        QTest::ignoreMessage(QtWarningMsg, "QIODevice::write (QBuffer): ReadOnly device");
        QVERIFY(!writeScopeCsv(readOnly, recording, {}, &error));
        QVERIFY2(error.startsWith(QStringLiteral("cannot write the CSV: ")), qPrintable(error));
    }

    void progressEveryBlockOfRows()
    {
        ScopeRecording recording;
        const qsizetype count = 3 * kScopeCsvProgressRows + 100;
        for (qsizetype i = 0; i < count; ++i)
            QVERIFY(recording.buffer.append(sample(i, qint32(i), 0, 0, 0)));
        QList<std::pair<qsizetype, qsizetype>> calls;
        ScopeCsvOptions options;
        options.progress = [&calls](qsizetype done, qsizetype total) {
            calls.append({ done, total });
            return true;
        };
        const QByteArray csv = csvOf(recording, options);
        QCOMPARE(calls,
                 (QList<std::pair<qsizetype, qsizetype>> { { kScopeCsvProgressRows, count },
                                                           { 2 * kScopeCsvProgressRows, count },
                                                           { 3 * kScopeCsvProgressRows, count },
                                                           { count, count } }));
        QCOMPARE(csv.count('\n'), count + 1);
        const QByteArray last = QByteArray::number(count - 1);
        QVERIFY(csv.endsWith("\r\n" + last + "," + last + ",0,0,0\r\n"));
    }

    void savedWholeAndCancelledLeavesNothing()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        ScopeRecording recording;
        describe(recording);
        fill(recording);
        const QString path = dir.filePath(QStringLiteral("shot.csv"));
        QString error;
        QVERIFY2(saveScopeCsv(path, recording, {}, &error), qPrintable(error));
        QCOMPARE(readFile(path), csvOf(recording));

        for (qsizetype i = 0; i < 2 * kScopeCsvProgressRows; ++i)
            QVERIFY(recording.buffer.append(sample(2000 + i, 1, 2, 3, 4)));
        ScopeCsvOptions options;
        options.progress = [](qsizetype, qsizetype) { return false; };
        // an existing file stays as it was, a new one is not made
        QVERIFY(!saveScopeCsv(path, recording, options, &error));
        QCOMPARE(error, QStringLiteral("the export was cancelled"));
        QCOMPARE(readFile(path),
                 kHeader
                     + "0,12.5,-5,255,-32.768\r\n"
                       "1,-12.5,2147483647,-1,12.5\r\n"
                       "3,-0.4,-2147483648,0,12\r\n"
                       "3,0.0,0,32767,-0.001\r\n"
                       "10,-0.1,7,-32768,0\r\n");
        const QString fresh = dir.filePath(QStringLiteral("fresh.csv"));
        QVERIFY(!saveScopeCsv(fresh, recording, options, &error));
        QVERIFY(!QFile::exists(fresh));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files),
                 QStringList { QStringLiteral("shot.csv") });
    }

    void unwritableFolderIsNamed()
    {
        ScopeRecording recording;
        fill(recording);
        const QString path = QStringLiteral("/nonexistent-folder/shot.csv");
        QString error;
        QVERIFY(!saveScopeCsv(path, recording, {}, &error));
        QVERIFY2(error.startsWith(QStringLiteral("cannot write '%1': ").arg(path)),
                 qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestScopeCsv)
#include "tst_scopecsv.moc"
