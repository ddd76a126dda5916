// The journal command's filters as a user types them: dates and times in local time (or with an
// offset), drives by serial number, link or LINK@ADDRESS, parameters by id or address; and the
// clear error, naming the text, for anything else.
#include "journal/JournalFilter.h"

#include <QTest>

using namespace DriveDesk;

class tst_JournalFilter : public QObject
{
    Q_OBJECT

private slots:
    void timesNameASpan_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QDateTime>("start");
        QTest::addColumn<QDateTime>("end");
        const auto local = [](int day, int hour, int minute, int second = 0) {
            return QDateTime(QDate(2026, 11, day), QTime(hour, minute, second), Qt::LocalTime)
                .toUTC();
        };
        QTest::newRow("a day") << QStringLiteral("2026-11-24") << local(24, 0, 0)
                               << local(25, 0, 0);
        QTest::newRow("a minute") << QStringLiteral("2026-11-24T10:42") << local(24, 10, 42)
                                  << local(24, 10, 43);
        QTest::newRow("with a space")
            << QStringLiteral(" 2026-11-24 10:42 ") << local(24, 10, 42) << local(24, 10, 43);
        QTest::newRow("a second") << QStringLiteral("2026-11-24T10:42:30") << local(24, 10, 42, 30)
                                  << local(24, 10, 42, 31);
        QTest::newRow("UTC") << QStringLiteral("2026-11-24T10:42Z")
                             << QDateTime(QDate(2026, 11, 24), QTime(10, 42), Qt::UTC)
                             << QDateTime(QDate(2026, 11, 24), QTime(10, 43), Qt::UTC);
        QTest::newRow("an offset") << QStringLiteral("2026-11-24T10:42:00+01:00")
                                   << QDateTime(QDate(2026, 11, 24), QTime(9, 42), Qt::UTC)
                                   << QDateTime(QDate(2026, 11, 24), QTime(9, 42, 1), Qt::UTC);
        QTest::newRow("a negative offset")
            << QStringLiteral("2026-11-24T10:42-0530")
            << QDateTime(QDate(2026, 11, 24), QTime(16, 12), Qt::UTC)
            << QDateTime(QDate(2026, 11, 24), QTime(16, 13), Qt::UTC);
    }

    void timesNameASpan()
    {
        QFETCH(QString, text);
        QFETCH(QDateTime, start);
        QFETCH(QDateTime, end);
        QString error;
        QCOMPARE(JournalFilter::parseTime(text, false, &error), std::optional<QDateTime>(start));
        QCOMPARE(JournalFilter::parseTime(text, true, &error), std::optional<QDateTime>(end));
        QCOMPARE(JournalFilter::parseTime(text, true, &error)->timeSpec(), Qt::UTC);
    }

    void badTimesAreNamed_data()
    {
        QTest::addColumn<QString>("text");
        for (const char *text :
             { "", "yesterday", "2026-13-01", "2026-02-30", "24.11.2026", "2026-11-24T25:00",
               "2026-11-24T10", "2026-11-24Z", "10:42", "2026-11-24T10:42+1" })
            QTest::newRow(text) << QString::fromLatin1(text);
    }

    void badTimesAreNamed()
    {
        QFETCH(QString, text);
        QString error;
        QCOMPARE(JournalFilter::parseTime(text, false, &error), std::nullopt);
        QVERIFY2(error.contains(QStringLiteral("'%1'").arg(text)), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("2026-11-24T10:42")), qPrintable(error));
    }

    void drives()
    {
        JournalFilter filter;
        QString error;
        QVERIFY(filter.setDrive(QStringLiteral("1234567"), &error));
        QCOMPARE(filter.serialNumber(), QStringLiteral("1234567"));
        QCOMPARE(filter.link(), QString());
        QCOMPARE(filter.driveAddress(), std::nullopt);
        QVERIFY(filter.setDrive(QStringLiteral("tcp:10.0.0.5:5020@17"), &error));
        QCOMPARE(filter.serialNumber(), QString());
        QCOMPARE(filter.link(), QStringLiteral("tcp:10.0.0.5:5020"));
        QCOMPARE(filter.driveAddress(), std::optional<int>(17));
        QVERIFY(filter.setDrive(QStringLiteral("serial:/dev/ttyUSB0"), &error));
        QCOMPARE(filter.link(), QStringLiteral("serial:/dev/ttyUSB0"));
        QCOMPARE(filter.driveAddress(), std::nullopt);
        QVERIFY(filter.setDrive(QStringLiteral("sim"), &error));
        QCOMPARE(filter.link(), QStringLiteral("sim"));
        QCOMPARE(filter.serialNumber(), QString());
        QCOMPARE(filter.driveAddress(), std::nullopt);
        for (const QString &bad :
             { QString(), QStringLiteral("sim@"), QStringLiteral("sim@300") }) {
            error.clear();
            QVERIFY(!filter.setDrive(bad, &error));
            QVERIFY2(error.contains(QStringLiteral("'%1'").arg(bad))
                         && error.contains(QStringLiteral("LINK@ADDRESS")),
                     qPrintable(error));
        }
    }

    void parameters()
    {
        JournalFilter filter;
        QString error;
        QVERIFY(filter.setParameter(QStringLiteral("op.28"), &error));
        QCOMPARE(filter.parameterIds(),
                 (QStringList { QStringLiteral("op.28"), QStringLiteral("op.028") }));
        QCOMPARE(filter.parameterAddress(), std::nullopt);
        QVERIFY(filter.setParameter(QStringLiteral("ru3"), &error));
        QCOMPARE(filter.parameterIds(),
                 (QStringList { QStringLiteral("ru.3"), QStringLiteral("ru.03"),
                                QStringLiteral("ru.003") }));
        QVERIFY(filter.setParameter(QStringLiteral("0x0A1C"), &error));
        QCOMPARE(filter.parameterAddress(), std::optional<quint16>(0x0A1C));
        QVERIFY(filter.parameterIds().isEmpty());
        for (const char *bad : { "", "op.", "op.256", "0x12345", "op.2.8" }) {
            error.clear();
            QVERIFY2(!filter.setParameter(QString::fromLatin1(bad), &error), bad);
            QVERIFY2(error.contains(QStringLiteral("'%1'").arg(QString::fromLatin1(bad))),
                     qPrintable(error));
        }
    }
};

QTEST_GUILESS_MAIN(tst_JournalFilter)
#include "tst_journalfilter.moc"
