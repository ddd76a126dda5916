// `drivedesk-cli journal`: the entries in each format, filtered, with no drive; the options
// --journal and --no-journal as every command takes them; exit 2 naming the bad option or value.
#include "JournalTestSupport.h"
#include "cli/CommandLine.h"

#include "../cli/CliTestSupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::CliTest;
using namespace DriveDesk::JournalTest;

namespace {

std::optional<CliRequest> parse(const QStringList &arguments, QString *error)
{
    QString help;
    return parseCommandLine(QStringList { QStringLiteral("drivedesk-cli") } + arguments, error,
                            &help);
}

} // namespace

class tst_CliJournal : public QObject
{
    Q_OBJECT

private:
    QStringList journal(const QStringList &options = {}) const
    {
        return QStringList { QStringLiteral("journal"), QStringLiteral("--journal"), m_path }
        + options;
    }

    QTemporaryDir m_dir;
    QString m_path;

private slots:
    void initTestCase()
    {
        m_path = m_dir.filePath(QStringLiteral("journal.sqlite"));
        Journal journal(m_path);
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        const std::optional<qint64> job = journal.beginJob(QStringLiteral("edit"));
        QVERIFY(job);
        JournalEntry first
            = entryAt(0, busDrive(QStringLiteral("1111"), 3), QStringLiteral("anna"));
        first.jobId = *job;
        const std::optional<qint64> written = journal.begin(first);
        QVERIFY(written);
        QVERIFY(journal.complete(*written, first.written, JournalOutcome::Written));
        JournalEntry second = entryAt(90, busDrive(QStringLiteral("2222"), 5),
                                      QStringLiteral("ben"), QStringLiteral("ru.03"), 0x0203);
        second.parameterName = QStringLiteral("Set value, \"display\"");
        second.set.reset();
        const std::optional<qint64> refused = journal.begin(second);
        QVERIFY(refused);
        QVERIFY(journal.complete(*refused, second.before, JournalOutcome::Refused,
                                 QStringLiteral("value outside the limits")));
        JournalEntry third
            = entryAt(24 * 60, busDrive(QStringLiteral("1111"), 3), QStringLiteral("anna"));
        QVERIFY(journal.begin(third)); // never answered
    }

    void table()
    {
        const Run run = cli(journal());
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList lines = run.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4);
        QVERIFY2(lines[0].contains(QStringLiteral("Parameter"))
                     && lines[0].contains(QStringLiteral("Outcome")),
                 qPrintable(lines[0]));
        QVERIFY(lines[1].contains(QStringLiteral("2026-11-24 10:00:00")));
        QVERIFY(lines[1].contains(QStringLiteral("anna@line3-laptop")));
        QVERIFY(lines[1].contains(QStringLiteral("5.00 s"))
                && lines[1].contains(QStringLiteral("7.50 s")));
        QVERIFY(lines[2].contains(QStringLiteral("refused: value outside the limits")));
        QVERIFY(lines[2].contains(QStringLiteral("active")));
        QVERIFY(lines[3].contains(QStringLiteral("unknown")));
        // Aligned: each column starts where its heading does.
        const qsizetype outcome = lines[0].indexOf(QStringLiteral("Outcome"));
        QCOMPARE(lines[1].indexOf(QStringLiteral("written")), outcome);
        QCOMPARE(lines[2].indexOf(QStringLiteral("refused")), outcome);
        QCOMPARE(lines[3].indexOf(QStringLiteral("unknown")), outcome);
        const qsizetype parameter = lines[0].indexOf(QStringLiteral("Parameter"));
        QCOMPARE(lines[2].indexOf(QStringLiteral("ru.03")), parameter);
    }

    void json()
    {
        const Run run = cli(journal({ QStringLiteral("--format"), QStringLiteral("json") }));
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QJsonParseError error;
        const QJsonArray entries = QJsonDocument::fromJson(run.out.toUtf8(), &error).array();
        QCOMPARE(error.error, QJsonParseError::NoError);
        QCOMPARE(entries.size(), 3);
        const QJsonObject first = entries[0].toObject();
        QCOMPARE(first[QStringLiteral("outcome")].toString(), QStringLiteral("written"));
        QCOMPARE(first[QStringLiteral("user")].toString(), QStringLiteral("anna"));
        QCOMPARE(first[QStringLiteral("set")].toInt(), 2);
        QCOMPARE(first[QStringLiteral("job")][QStringLiteral("description")].toString(),
                 QStringLiteral("edit"));
        QCOMPARE(first[QStringLiteral("drive")][QStringLiteral("serialNumber")].toString(),
                 QStringLiteral("1111"));
        QCOMPARE(first[QStringLiteral("drive")][QStringLiteral("address")].toInt(), 3);
        QCOMPARE(first[QStringLiteral("parameter")][QStringLiteral("address")].toInt(), 0x0A1C);
        QCOMPARE(first[QStringLiteral("before")][QStringLiteral("raw")].toInt(), 500);
        QCOMPARE(first[QStringLiteral("readBack")][QStringLiteral("text")].toString(),
                 QStringLiteral("7.50 s"));
        const QDateTime time
            = QDateTime::fromString(first[QStringLiteral("time")].toString(), Qt::ISODateWithMs);
        QCOMPARE(time, QDateTime(QDate(2026, 11, 24), QTime(10, 0), Qt::LocalTime));
        QVERIFY(first[QStringLiteral("time")].toString().endsWith(QLatin1Char('Z')));
        const QJsonObject second = entries[1].toObject();
        QCOMPARE(second[QStringLiteral("outcome")].toString(), QStringLiteral("refused"));
        QCOMPARE(second[QStringLiteral("reason")].toString(),
                 QStringLiteral("value outside the limits"));
        QVERIFY(second[QStringLiteral("set")].isNull());
        QVERIFY(entries[2].toObject()[QStringLiteral("readBack")].isNull());
        QVERIFY(entries[2].toObject()[QStringLiteral("completed")].isNull());
    }

    void csv()
    {
        const Run run = cli(journal({ QStringLiteral("--format"), QStringLiteral("csv") }));
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList lines = run.out.split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4);
        QVERIFY(
            lines[0].startsWith(QStringLiteral("id,time,completed,user,host,program,job id,job,")));
        QVERIFY2(lines[2].contains(QStringLiteral(",\"Set value, \"\"display\"\"\",")),
                 qPrintable(lines[2]));
        QVERIFY(lines[2].contains(QStringLiteral(",refused,value outside the limits")));
        QVERIFY(lines[1].contains(QStringLiteral(",0x0a1c,")));
        // Local time with its offset.
        const QString time = lines[1].section(QLatin1Char(','), 1, 1);
        QCOMPARE(QDateTime::fromString(time, Qt::ISODateWithMs),
                 QDateTime(QDate(2026, 11, 24), QTime(10, 0), Qt::LocalTime));
    }

    void filters_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<int>("count");
        QTest::newRow("serial number")
            << QStringList { QStringLiteral("--drive"), QStringLiteral("1111") } << 2;
        QTest::newRow("link and address")
            << QStringList { QStringLiteral("--drive"), QStringLiteral("serial:/dev/ttyUSB0@5") }
            << 1;
        QTest::newRow("parameter")
            << QStringList { QStringLiteral("--parameter"), QStringLiteral("ru.3") } << 1;
        QTest::newRow("since") << QStringList { QStringLiteral("--since"),
                                                QStringLiteral("2026-11-24T11:00") }
                               << 2;
        QTest::newRow("until") << QStringList { QStringLiteral("--until"),
                                                QStringLiteral("2026-11-24") }
                               << 2;
        QTest::newRow("user") << QStringList { QStringLiteral("--user"), QStringLiteral("ben") }
                              << 1;
        QTest::newRow("nothing") << QStringList { QStringLiteral("--user"), QStringLiteral("carl") }
                                 << 0;
    }

    void filters()
    {
        QFETCH(QStringList, options);
        QFETCH(int, count);
        const Run run = cli(
            journal(options + QStringList { QStringLiteral("--format"), QStringLiteral("json") }));
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(QJsonDocument::fromJson(run.out.toUtf8()).array().size(), count);
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("named");
        const QString path = QStringLiteral("journal.sqlite");
        const auto args = [&](std::initializer_list<const char *> words) {
            QStringList list { QStringLiteral("journal"), QStringLiteral("--journal"), path };
            for (const char *word : words)
                list << QString::fromLatin1(word);
            return list;
        };
        QTest::newRow("since") << args({ "--since", "yesterday" })
                               << QStringLiteral("--since: 'yesterday'");
        QTest::newRow("until") << args({ "--until", "2026-11-31" })
                               << QStringLiteral("--until: '2026-11-31'");
        QTest::newRow("until before since")
            << args({ "--since", "2026-11-24", "--until", "2026-11-23" })
            << QStringLiteral("--until 2026-11-23");
        QTest::newRow("drive") << args({ "--drive", "sim@" }) << QStringLiteral("--drive: 'sim@'");
        QTest::newRow("parameter")
            << args({ "--parameter", "op.999" }) << QStringLiteral("--parameter: 'op.999'");
        QTest::newRow("format") << args({ "--format", "xml" }) << QStringLiteral("'xml'");
        QTest::newRow("connect") << args({ "--connect", "sim" }) << QStringLiteral("--connect");
        QTest::newRow("an argument")
            << args({ "extra" }) << QStringLiteral("journal takes no arguments");
        QTest::newRow("no journal") << args({ "--no-journal" }) << QStringLiteral("--no-journal");
        QTest::newRow("a drive's option") << args({ "--sets", "all" }) << QStringLiteral("--sets");
        QTest::newRow("a filter elsewhere")
            << QStringList { QStringLiteral("--connect"), QStringLiteral("sim"),
                             QStringLiteral("read"),      QStringLiteral("ru.3"),
                             QStringLiteral("--user"),    QStringLiteral("anna") }
            << QStringLiteral("--user belongs to journal");
        QTest::newRow("both") << QStringList {
            QStringLiteral("--connect"),    QStringLiteral("sim"),
            QStringLiteral("--journal"),    path,
            QStringLiteral("--no-journal"), QStringLiteral("info")
        } << QStringLiteral("--journal and --no-journal");
    }

    void badInput()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, named);
        const Run run = cli(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(named), qPrintable(explain(run)));
        QVERIFY(run.out.isEmpty());
    }

    void aJournalThatCannotBeRead()
    {
        Run run = cli({ QStringLiteral("journal"), QStringLiteral("--journal"),
                        m_dir.filePath(QStringLiteral("missing.sqlite")) });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(m_dir.filePath(QStringLiteral("missing.sqlite"))),
                 qPrintable(explain(run)));
        const QString damaged = m_dir.filePath(QStringLiteral("damaged.sqlite"));
        QFile file(damaged);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(4096, 'x'));
        file.close();
        run = cli({ QStringLiteral("journal"), QStringLiteral("--journal"), damaged });
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(damaged)
                     && run.err.contains(QStringLiteral("no DriveDesk journal")),
                 qPrintable(explain(run)));
    }

    // The default journal, $XDG_DATA_HOME/DriveDesk/journal.sqlite: none yet is an empty one.
    void theDefaultJournal()
    {
        QTemporaryDir home;
        QProcess process;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("XDG_DATA_HOME"), home.path());
        process.setProcessEnvironment(environment);
        process.start(
            kCli,
            { QStringLiteral("journal"), QStringLiteral("--format"), QStringLiteral("json") });
        QVERIFY(process.waitForFinished(60000));
        QCOMPARE(process.exitCode(), 0);
        QCOMPARE(QJsonDocument::fromJson(process.readAllStandardOutput()).array().size(), 0);
        QVERIFY(process.readAllStandardError().contains(
            home.filePath(QStringLiteral("DriveDesk/journal.sqlite")).toUtf8()));

        QVERIFY(QDir().mkpath(home.filePath(QStringLiteral("DriveDesk"))));
        QVERIFY(QFile::copy(m_path, home.filePath(QStringLiteral("DriveDesk/journal.sqlite"))));
        process.start(
            kCli,
            { QStringLiteral("journal"), QStringLiteral("--format"), QStringLiteral("json") });
        QVERIFY(process.waitForFinished(60000));
        QCOMPARE(process.exitCode(), 0);
        QCOMPARE(QJsonDocument::fromJson(process.readAllStandardOutput()).array().size(), 3);
    }

    // --journal and --no-journal are kept for the commands that write.
    void theOptionsAreKept()
    {
        QString error;
        std::optional<CliRequest> request
            = parse({ QStringLiteral("--connect"), QStringLiteral("sim"),
                      QStringLiteral("--journal"), QStringLiteral("/tmp/j.sqlite"),
                      QStringLiteral("write"), QStringLiteral("uF.07"), QStringLiteral("70.0") },
                    &error);
        QVERIFY2(request, qPrintable(error));
        QCOMPARE(request->journalPath, QStringLiteral("/tmp/j.sqlite"));
        QVERIFY(request->journalWrites);
        request = parse({ QStringLiteral("--connect"), QStringLiteral("sim"),
                          QStringLiteral("--no-journal"), QStringLiteral("download"),
                          QStringLiteral("f5.json") },
                        &error);
        QVERIFY2(request, qPrintable(error));
        QVERIFY(!request->journalWrites);
        QVERIFY(request->journalPath.isEmpty());
        request = parse({ QStringLiteral("--no-journal"), QStringLiteral("plant"),
                          QStringLiteral("download"), QStringLiteral("line3.json"),
                          QStringLiteral("backups") },
                        &error);
        QVERIFY2(request && request->plant, qPrintable(error));
        QVERIFY(!request->journalWrites);
        request
            = parse({ QStringLiteral("journal"), QStringLiteral("--drive"), QStringLiteral("sim@1"),
                      QStringLiteral("--format"), QStringLiteral("csv") },
                    &error);
        QVERIFY2(request, qPrintable(error));
        QCOMPARE(request->command, CliRequest::Command::Journal);
        QCOMPARE(request->format, CliRequest::Format::Csv);
        QCOMPARE(request->journalFilter.link(), QStringLiteral("sim"));
        QCOMPARE(request->journalFilter.driveAddress(), std::optional<int>(1));
    }

    void theCommandsHelp()
    {
        const Run run = cli({ QStringLiteral("journal"), QStringLiteral("--help") });
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("--since TIME")), qPrintable(explain(run)));
    }
};

QTEST_GUILESS_MAIN(tst_CliJournal)
#include "tst_clijournal.moc"
