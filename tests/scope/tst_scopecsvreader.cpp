// A scope CSV export read back: every column with its title, unit, times and values as the
// export wrote them; quoted headers, empty fields, LF line ends; every fault named.
#include "ScopeTestRecording.h"
#include "scope/ScopeCsv.h"
#include "scope/ScopeCsvReader.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace DriveDesk;
using namespace DriveDesk::ScopeTest;

namespace {

bool write(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

} // namespace

class TestScopeCsvReader : public QObject
{
    Q_OBJECT
private slots:
    void readsBackWhatTheExportWrote()
    {
        ScopeRecording recording;
        recording.channels[0] = scaledChannel(0x0203, QStringLiteral("ru.03"),
                                              QStringLiteral("Actual frequency"), 100, kHz);
        recording.channels[2] = scaledChannel(0x0200, QStringLiteral("ru.00"),
                                              QStringLiteral("Status \"word\", bits"), 1, 0);
        recording.channels[3].enabled = false; // written when asked for: raw, "Channel 4"
        for (int i = 0; i < 500; ++i)
            append(recording, 7000 + i * 2 + (i % 3 == 0 ? 1 : 0), -1234 + 37 * i, 0, qint16(i),
                   qint16(-i));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("trace.csv"));
        ScopeCsvOptions options;
        options.channels = { 0, 2, 3 };
        QString error;
        QVERIFY2(saveScopeCsv(path, recording, options, &error), qPrintable(error));

        QList<ScopeSeries> columns;
        QVERIFY2(readScopeCsv(path, columns, &error), qPrintable(error));
        QCOMPARE(columns.size(), 3);
        QCOMPARE(columns[0].title, QStringLiteral("ru.03 Actual frequency"));
        QCOMPARE(columns[0].unit, QStringLiteral("Hz"));
        QCOMPARE(columns[1].title, QStringLiteral("ru.00 Status \"word\", bits"));
        QCOMPARE(columns[1].unit, QString());
        QCOMPARE(columns[2].title, QStringLiteral("Channel 4"));
        for (const ScopeSeries &column : std::as_const(columns))
            QCOMPARE(column.count(), qsizetype(500));
        const int channels[] = { 0, 2, 3 };
        for (int c = 0; c < 3; ++c) {
            for (qsizetype i = 0; i < 500; ++i) {
                QCOMPARE(columns[c].timeMs[std::size_t(i)],
                         double(recording.buffer.samples().time(i) - recording.firstTime()));
                QVERIFY(std::abs(columns[c].values[std::size_t(i)]
                                 - recording.displayValue(i, channels[c]))
                        < 1e-9);
            }
        }
    }

    // The measurements after the samples are no samples.
    void theMeasurementsSectionIsNotRead()
    {
        ScopeRecording recording;
        recording.channels[0] = scaledChannel(0x0203, QStringLiteral("ru.03"),
                                              QStringLiteral("Actual frequency"), 10, kHz);
        for (int i = 0; i < 50; ++i)
            append(recording, i, 10 * i);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("measured.csv"));
        ScopeCsvOptions options;
        options.channels = { 0 };
        options.measureBetweenMs = std::pair(10.0, 20.0);
        QString error;
        QVERIFY2(saveScopeCsv(path, recording, options, &error), qPrintable(error));
        QList<ScopeSeries> columns;
        QVERIFY2(readScopeCsv(path, columns, &error), qPrintable(error));
        QCOMPARE(columns.size(), 1);
        QCOMPARE(columns[0].count(), qsizetype(50));
        QCOMPARE(columns[0].values.back(), 49.0);
    }

    // Written by another tool: LF line ends, a byte-order mark, a value left empty.
    void emptyFieldsLeaveTheSampleOut()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("other.csv"));
        QVERIFY(write(path, "\xEF\xBB\xBFTime [ms],a [V],b\n0,1.5,2\n1,,3\n2,-0.25,4\n\n"));
        QList<ScopeSeries> columns;
        QString error;
        QVERIFY2(readScopeCsv(path, columns, &error), qPrintable(error));
        QCOMPARE(columns.size(), 2);
        QCOMPARE(columns[0].unit, QStringLiteral("V"));
        QCOMPARE(columns[0].timeMs, (std::vector<double> { 0, 2 }));
        QCOMPARE(columns[0].values, (std::vector<double> { 1.5, -0.25 }));
        QCOMPARE(columns[1].timeMs, (std::vector<double> { 0, 1, 2 }));
    }

    void faultsAreNamed_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("error");
        QTest::newRow("empty") << QByteArray()
                               << QStringLiteral("is not a scope CSV export: its first column is "
                                                 "not \"Time [ms]\"");
        QTest::newRow("a parameter CSV") << QByteArray("id,name,unit\r\nru.03,f,Hz\r\n")
                                         << QStringLiteral("is not a scope CSV export");
        QTest::newRow("unterminated quote") << QByteArray("Time [ms],\"a\r\n0,1\r\n")
                                            << QStringLiteral("is not a scope CSV export");
        QTest::newRow("a field short") << QByteArray("Time [ms],a,b\r\n0,1,2\r\n1,2\r\n")
                                       << QStringLiteral(", line 3 has 2 fields, the header 3");
        QTest::newRow("a field too many") << QByteArray("Time [ms],a\r\n0,1,2\r\n")
                                          << QStringLiteral(", line 2 has 3 fields, the header 2");
        QTest::newRow("a word") << QByteArray("Time [ms],a [Hz]\r\n0,1\r\n1,fast\r\n")
                                << QStringLiteral(
                                       ", line 3: \"fast\" in column \"a [Hz]\" is not a "
                                       "number");
        QTest::newRow("no time") << QByteArray("Time [ms],a\r\n,1\r\n")
                                 << QStringLiteral(
                                        ", line 2: \"\" in column \"Time [ms]\" is not a "
                                        "number");
        QTest::newRow("time goes back") << QByteArray("Time [ms],a\r\n5,1\r\n4,1\r\n")
                                        << QStringLiteral(", line 3: the time 4 ms is earlier than "
                                                          "the line's before");
    }

    void faultsAreNamed()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, error);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.csv"));
        QVERIFY(write(path, bytes));
        QList<ScopeSeries> columns { ScopeSeries() };
        QString message;
        QVERIFY(!readScopeCsv(path, columns, &message));
        QVERIFY2(message.startsWith(QStringLiteral("'%1'").arg(path)), qPrintable(message));
        QVERIFY2(message.contains(error), qPrintable(message));
        QCOMPARE(columns.size(), 1); // untouched
    }

    void aMissingFileIsNamed()
    {
        QList<ScopeSeries> columns;
        QString error;
        QVERIFY(!readScopeCsv(QStringLiteral("/nonexistent/trace.csv"), columns, &error));
        QCOMPARE(error,
                 QStringLiteral("cannot read '/nonexistent/trace.csv': No such file or directory"));
    }
};

QTEST_GUILESS_MAIN(TestScopeCsvReader)
#include "tst_scopecsvreader.moc"
