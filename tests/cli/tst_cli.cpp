#include "CliTestSupport.h"

#include "parameters/DriveDescription.h"
#include "parameters/ParameterDocument.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::CliTest;


// drivedesk-cli as a user runs it, against the simulated drive.
class TestCli : public QObject
{
    Q_OBJECT
private slots:
    // Each command has its own --help: that command's lines, not the whole text; without a
    // command (or with one it does not know) the whole text.
    void eachCommandHasItsOwnHelp()
    {
        const Run scope = sim({QStringLiteral("scope"), QStringLiteral("--help")});
        QCOMPARE(scope.exitCode, 0);
        QVERIFY2(scope.out.contains(QStringLiteral("scope --csv FILE"))
                     && scope.out.contains(QStringLiteral("scope --offline --csv FILE")),
                 qPrintable(scope.out));
        QVERIFY2(!scope.out.contains(QStringLiteral("upload FILE")), qPrintable(scope.out));

        const Run plant = cli({QStringLiteral("plant"), QStringLiteral("--help")});
        QCOMPARE(plant.exitCode, 0);
        QVERIFY2(plant.out.contains(QStringLiteral("plant verify PLANT DIR")), qPrintable(plant.out));
        QVERIFY2(!plant.out.contains(QStringLiteral("scope --csv")), qPrintable(plant.out));

        const Run all = cli({QStringLiteral("--help")});
        QCOMPARE(all.exitCode, 0);
        QVERIFY(all.out.contains(QStringLiteral("upload FILE"))
                && all.out.contains(QStringLiteral("scope --csv FILE")));
    }

    void scanWritesTheParameterFile()
    {
        const Run run = sim({QStringLiteral("scan"), QStringLiteral("--format"), QStringLiteral("json"),
                             QStringLiteral("--values")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QJsonObject root = QJsonDocument::fromJson(run.out.toUtf8()).object();
        QCOMPARE(root.value(QStringLiteral("format")).toString(), QStringLiteral("drivedesk-parameters"));
        QCOMPARE(root.value(QStringLiteral("version")).toInt(), 1);

        QString error;
        const auto drive = ParameterDocument::fromJson(run.out.toUtf8(), &error);
        QVERIFY2(drive, qPrintable(error));
        QVERIFY(drive->groups.size() >= 12);
        QVERIFY(drive->parameterCount() >= 200);
        QVERIFY(drive->incompleteReason.isEmpty());

        const ParameterDescription *state = drive->find(0x0200);
        QVERIFY(state);
        QVERIFY(!state->plaintexts.isEmpty());
        const ParameterDescription *acceleration = drive->find(0x031C); // op.28
        QVERIFY(acceleration);
        QVERIFY(acceleration->isSetProgrammable());
        for (const auto &value : acceleration->values)
            QVERIFY(value.has_value());

        const QJsonArray groups = root.value(QStringLiteral("groups")).toArray();
        QCOMPARE(groups.first().toObject().value(QStringLiteral("id")).toString(), drive->groups.first().id);
    }

    // Two files, no drive: each differing value and set in display form, and the exit status
    // a script tests.
    void diffListsWhatDiffersBetweenTwoFiles()
    {
        const Run scan = sim({QStringLiteral("scan"), QStringLiteral("--format"),
                              QStringLiteral("json"), QStringLiteral("--values")});
        QVERIFY2(scan.exitCode == 0, qPrintable(explain(scan)));
        auto drive = ParameterDocument::fromJson(scan.out.toUtf8());
        QVERIFY(drive);
        QTemporaryDir dir;
        const QString a = dir.filePath(QStringLiteral("a.json"));
        const QString b = dir.filePath(QStringLiteral("b.json"));
        const QString broken = dir.filePath(QStringLiteral("broken.json"));
        QVERIFY(ParameterDocument::save(a, *drive));
        // b: op.11 set 2 changed, Sy.11 missing.
        for (GroupDescription &group : drive->groups) {
            for (ParameterDescription &parameter : group.parameters) {
                if (parameter.address == 0x030B)
                    parameter.values[2] = 2600;
            }
            group.parameters.removeIf(
                [](const ParameterDescription &p) { return p.address == 0x000B; });
        }
        QVERIFY(ParameterDocument::save(b, *drive));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\n  \"format\": ");
        file.close();

        const Run same = cli({QStringLiteral("diff"), a, a});
        QVERIFY2(same.exitCode == 0, qPrintable(explain(same)));
        QVERIFY2(same.out.startsWith(QStringLiteral("0 difference")), qPrintable(same.out));

        const Run differ = cli({QStringLiteral("diff"), a, b});
        QVERIFY2(differ.exitCode == 1, qPrintable(explain(differ)));
        const QStringList lines = differ.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4); // heading, two differences, the count
        QVERIFY2(lines[1].contains(QRegularExpression(QStringLiteral("^Sy\\.11 .* only in A +250000 +-$"))),
                 qPrintable(lines[1]));
        QVERIFY2(lines[2].contains(QRegularExpression(
                     QStringLiteral("^op\\.11 +Maximum speed forward +2 +3000 1/min +2600 1/min$"))),
                 qPrintable(lines[2]));

        const Run json = cli({QStringLiteral("diff"), a, b, QStringLiteral("--format"),
                              QStringLiteral("json")});
        QCOMPARE(json.exitCode, 1);
        const QJsonArray differences = QJsonDocument::fromJson(json.out.toUtf8())
                                           .object()
                                           .value(QStringLiteral("differences"))
                                           .toArray();
        QCOMPARE(differences.size(), 2);
        const QJsonObject op11 = differences[1].toObject();
        QCOMPARE(op11.value(QStringLiteral("id")).toString(), QStringLiteral("op.11"));
        QCOMPARE(op11.value(QStringLiteral("set")).toInt(), 2);
        QCOMPARE(op11.value(QStringLiteral("b")).toString(), QStringLiteral("2600 1/min"));

        const Run bad = cli({QStringLiteral("diff"), a, broken});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains(broken) && bad.err.contains(QStringLiteral("line")),
                 qPrintable(bad.err));
        QVERIFY(bad.out.isEmpty());
        QCOMPARE(cli({QStringLiteral("diff"), a}).exitCode, 2);
        QCOMPARE(cli({QStringLiteral("diff"), a, QStringLiteral("drive")}).exitCode, 2);
    }

    // For a spreadsheet: a heading, one row per parameter, values per set in display form,
    // fields with a comma quoted.
    void scanWritesCsvForSpreadsheets()
    {
        const Run run = sim({QStringLiteral("scan"), QStringLiteral("--format"),
                             QStringLiteral("csv"), QStringLiteral("--values")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList lines = run.out.split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 206);
        QCOMPARE(lines[0], QStringLiteral("id,name,unit,set 0,set 1,set 2,set 3,set 4,set 5,set 6,set 7"));
        const auto row = [&lines](const QString &id) {
            for (const QString &line : lines) {
                if (line.startsWith(id + QLatin1Char(',')))
                    return line;
            }
            return QString();
        };
        QCOMPARE(row(QStringLiteral("op.28")),
                 QStringLiteral("op.28,Acceleration time,s,5.00,5.00,5.00,5.00,5.00,5.00,5.00,5.00"));
        QCOMPARE(row(QStringLiteral("op.05")),
                 QStringLiteral("op.05,Demo cycle period,s,20.0,,,,,,,"));
        QCOMPARE(row(QStringLiteral("ru.00")).section(QLatin1Char(','), 0, 2),
                 QStringLiteral("ru.00,Inverter state,"));
        QCOMPARE(cli({QStringLiteral("diff"), QStringLiteral("a"), QStringLiteral("b"),
                      QStringLiteral("--format"), QStringLiteral("csv")})
                     .exitCode,
                 2);
    }

    void scanTableShowsGroupsAndUnits()
    {
        const Run run = sim({QStringLiteral("scan")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("^ru  \\S"), QRegularExpression::MultilineOption)),
                 qPrintable(run.out.left(400)));
        QVERIFY(run.out.contains(QStringLiteral("op.28")));
        QVERIFY(run.out.contains(QRegularExpression(QStringLiteral("\\d+ groups, \\d+ parameters"))));
    }

    void theSecondScanTakesTheMetadataFromTheCache()
    {
        QTemporaryDir home;
        const QStringList scan{QStringLiteral("--connect"), QStringLiteral("sim"),
                               QStringLiteral("scan"), QStringLiteral("--format"),
                               QStringLiteral("json")};
        const QString fromCache = QStringLiteral("metadata from the cache");
        const Run cold = cli(scan, home.path());
        QVERIFY2(cold.exitCode == 0, qPrintable(explain(cold)));
        QVERIFY(!cold.err.contains(fromCache));
        const QDir cache(home.filePath(QStringLiteral("DriveDesk/metadata")));
        QCOMPARE(cache.entryList(QDir::Files).size(), 1);

        const Run warm = cli(scan, home.path());
        QVERIFY2(warm.exitCode == 0, qPrintable(explain(warm)));
        QVERIFY2(warm.err.contains(fromCache), qPrintable(explain(warm)));
        QCOMPARE(warm.out, cold.out);

        const Run forced = cli(scan + QStringList{QStringLiteral("--no-cache")}, home.path());
        QVERIFY2(forced.exitCode == 0, qPrintable(explain(forced)));
        QVERIFY(!forced.err.contains(fromCache));
        QCOMPARE(forced.out, cold.out);

        // A cache file that is not one is reported, not trusted, and replaced.
        const QString file = cache.filePath(cache.entryList(QDir::Files).constFirst());
        QFile broken(file);
        QVERIFY(broken.open(QIODevice::WriteOnly | QIODevice::Truncate));
        broken.write("{\"format\": \"something else\"}");
        broken.close();
        const Run repaired = cli(scan, home.path());
        QVERIFY2(repaired.exitCode == 0, qPrintable(explain(repaired)));
        QVERIFY2(repaired.err.contains(file) && repaired.err.contains(QStringLiteral("ignored")),
                 qPrintable(explain(repaired)));
        QCOMPARE(repaired.out, cold.out);
        QVERIFY(cli(scan, home.path()).err.contains(fromCache));
    }

    void infoNamesGroupsAndCounts()
    {
        const Run run = sim({QStringLiteral("info")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY(run.out.contains(QStringLiteral("simulated"), Qt::CaseInsensitive));
        QVERIFY(run.out.contains(QRegularExpression(QStringLiteral("^ru\\s+0200h\\s+\\d+"),
                                                    QRegularExpression::MultilineOption)));
    }

    void everySpellingOfAnIdReadsTheSameParameter()
    {
        QStringList lines;
        for (const QString &id : {QStringLiteral("op.28"), QStringLiteral("op.028"), QStringLiteral("OP.28"),
                                  QStringLiteral("0x031C"), QStringLiteral("031Ch")}) {
            const Run run = sim({QStringLiteral("read"), id});
            QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
            lines << run.out.trimmed();
        }
        lines.removeDuplicates();
        QCOMPARE(lines.size(), 1);
        QVERIFY2(lines.first().contains(QStringLiteral("5.00 s")), qPrintable(lines.first()));
    }

    void readOfAPlaintextParameterShowsItsText()
    {
        const Run run = sim({QStringLiteral("read"), QStringLiteral("uF.10")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("= on")), qPrintable(run.out));
    }

    void valueOutsideTheLimitsIsRefusedBeforeSending()
    {
        const Run run = sim({QStringLiteral("write"), QStringLiteral("op.28"), QStringLiteral("999")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("outside the limits")), qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("300.00 s")), qPrintable(run.err));
    }

    void aValueThatCannotBeHeldExactlyIsRefusedAsInTheWindow()
    {
        // uF.07 holds tenths of a percent: 75.03 would be written as 75.0.
        const Run run = sim({QStringLiteral("write"), QStringLiteral("uF.07"), QStringLiteral("75.03")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("cannot be set exactly")), qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("75.0 %")), qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("nothing was written")), qPrintable(run.err));
        QVERIFY(run.out.isEmpty());

        const Run exact = sim({QStringLiteral("write"), QStringLiteral("uF.07"), QStringLiteral("75.0")});
        QVERIFY2(exact.exitCode == 0, qPrintable(explain(exact)));
        const Run raw = sim({QStringLiteral("write"), QStringLiteral("uF.07"), QStringLiteral("0x2EE"),
                             QStringLiteral("--raw")});
        QVERIFY2(raw.exitCode == 0, qPrintable(explain(raw)));
        QVERIFY2(raw.out.contains(QStringLiteral("75.0 %")), qPrintable(raw.out));
    }

    void writeReadsTheValueBack()
    {
        const Run run = sim({QStringLiteral("write"), QStringLiteral("op.28"), QStringLiteral("12.5"),
                             QStringLiteral("--sets"), QStringLiteral("0,2-3")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("12.50 s")), qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("written (sets 0, 2, 3)")), qPrintable(run.out));
    }

    void negativeValuesAndPlaintextsAreValues()
    {
        Run run = sim({QStringLiteral("write"), QStringLiteral("op.20"), QStringLiteral("-250")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("-250 1/min")), qPrintable(run.out));
        run = sim({QStringLiteral("write"), QStringLiteral("uF.10"), QStringLiteral("off")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("= off")), qPrintable(run.out));
        run = sim({QStringLiteral("write"), QStringLiteral("uF.10"), QStringLiteral("sometimes")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("off")), qPrintable(run.err));
    }

    void theDrivesRefusalIsPrintedInWords()
    {
        // cn.00 is written at the Drive mode level; the drive starts at Application.
        const Run run = sim({QStringLiteral("write"), QStringLiteral("cn.00"), QStringLiteral("--raw"),
                             QStringLiteral("1")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("address or password invalid")), qPrintable(run.err));

        // In German the whole message is German: the catalogue, not the drive, says it.
        const Run german = sim({QStringLiteral("--language"), QStringLiteral("de"), QStringLiteral("write"),
                                QStringLiteral("cn.00"), QStringLiteral("--raw"), QStringLiteral("1")});
        QCOMPARE(german.exitCode, 1);
        QVERIFY2(german.err.contains(QStringLiteral("Umrichter lehnt ab: Adresse oder Passwort ungültig")),
                 qPrintable(german.err));
        QVERIFY2(!german.err.contains(QStringLiteral("refused")), qPrintable(german.err));
    }

    void germanReportsReadAsGerman()
    {
        const Run info = sim({QStringLiteral("--language"), QStringLiteral("de"), QStringLiteral("info")});
        QVERIFY2(info.exitCode == 0, qPrintable(explain(info)));
        QVERIFY2(info.out.contains(QStringLiteral("Verbindung: ")), qPrintable(info.out));
        QVERIFY2(info.out.contains(QRegularExpression(QStringLiteral("^Gruppe\\s+Adresse\\s+Parameter\\s+Name$"),
                                                      QRegularExpression::MultilineOption)),
                 qPrintable(info.out));
        QVERIFY2(info.out.contains(QRegularExpression(QStringLiteral("\\d+ Gruppen, \\d+ Parameter\\n$"))),
                 qPrintable(info.out));

        const Run write = sim({QStringLiteral("--language"), QStringLiteral("de"), QStringLiteral("write"),
                               QStringLiteral("op.28"), QStringLiteral("12.5"), QStringLiteral("--sets"),
                               QStringLiteral("2")});
        QVERIFY2(write.exitCode == 0, qPrintable(explain(write)));
        QVERIFY2(write.out.contains(QStringLiteral("(Satz 2)")), qPrintable(write.out));
    }

    void aPasswordOpensItsLevelBeforeTheCommand()
    {
        // 500 opens Drive mode, where cn.00 may be written (docs/simulated-drive.md).
        Run run = sim({QStringLiteral("--password"), QStringLiteral("500"), QStringLiteral("write"),
                       QStringLiteral("cn.00"), QStringLiteral("--raw"), QStringLiteral("1")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cn.00")), qPrintable(run.out));

        run = sim({QStringLiteral("--password"), QStringLiteral("123"), QStringLiteral("write"),
                   QStringLiteral("cn.00"), QStringLiteral("--raw"), QStringLiteral("1")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("password not accepted: drive refused: password invalid")),
                 qPrintable(run.err));
        QVERIFY2(run.out.isEmpty(), qPrintable(run.out));

        run = sim({QStringLiteral("--password"), QStringLiteral("12345"), QStringLiteral("info")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--password 12345")), qPrintable(run.err));
    }

    void readOnlyIsRefusedBeforeAnythingIsSent()
    {
        const Run run = sim({QStringLiteral("write"), QStringLiteral("ru.03"), QStringLiteral("--raw"),
                             QStringLiteral("0")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("ru.03 is read-only")), qPrintable(run.err));
    }

    void germanTextsComeFromTheDrive()
    {
        const Run run = sim({QStringLiteral("--language"), QStringLiteral("de"), QStringLiteral("read"),
                             QStringLiteral("op.28")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("Beschleunigungszeit")), qPrintable(run.out));
    }

    void din66019iiWorksLikeHsp5()
    {
        const Run run = sim({QStringLiteral("--protocol"), QStringLiteral("din66019ii"), QStringLiteral("read"),
                             QStringLiteral("op.28"), QStringLiteral("--set"), QStringLiteral("1")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("5.00 s")), qPrintable(run.out));
    }

    void legacyDin66019ReadsRawValues()
    {
        const Run run = sim({QStringLiteral("--protocol"), QStringLiteral("din66019"), QStringLiteral("read"),
                             QStringLiteral("0x031C")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("500")), qPrintable(run.out));
        const Run scan = sim({QStringLiteral("--protocol"), QStringLiteral("din66019"), QStringLiteral("scan")});
        QCOMPARE(scan.exitCode, 2);
        QVERIFY2(scan.err.contains(QStringLiteral("din66019ii")), qPrintable(scan.err));
    }

    void legacyDin66019WritesThroughTheEditPathAndReadsBack()
    {
        const Run run = sim({QStringLiteral("--protocol"), QStringLiteral("din66019"), QStringLiteral("write"),
                             QStringLiteral("0x031C"), QStringLiteral("600")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        // The window's words: read back from the active set, raw for want of metadata.
        QVERIFY2(run.out.contains(QStringLiteral("031Ch = 600 written (active set)")), qPrintable(run.out));
    }

    void badArgumentsAreNamed_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("no connect") << QStringList{QStringLiteral("info")} << QStringLiteral("--connect");
        QTest::newRow("bad target") << QStringList{QStringLiteral("--connect"), QStringLiteral("usb:1"), QStringLiteral("info")}
                                    << QStringLiteral("usb:1");
        QTest::newRow("bad address") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"),
                                                    QStringLiteral("--address"), QStringLiteral("240"), QStringLiteral("info")}
                                     << QStringLiteral("--address 240");
        QTest::newRow("bad command") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("erase")}
                                     << QStringLiteral("erase");
        QTest::newRow("bad sets") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("write"),
                                                 QStringLiteral("op.28"), QStringLiteral("1"), QStringLiteral("--sets"),
                                                 QStringLiteral("2-9")}
                                  << QStringLiteral("2-9");
        QTest::newRow("unknown parameter") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"),
                                                          QStringLiteral("read"), QStringLiteral("xy.3")}
                                           << QStringLiteral("xy");
        QTest::newRow("not a number") << QStringList{QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("write"),
                                                     QStringLiteral("op.28"), QStringLiteral("fast")}
                                      << QStringLiteral("fast");
    }

    void badArgumentsAreNamed()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const Run run = cli(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(message), qPrintable(run.err));
    }

    void deadLinkIsReported()
    {
        const Run run = cli({QStringLiteral("--connect"), QStringLiteral("tcp:127.0.0.1:1"), QStringLiteral("info")});
        QCOMPARE(run.exitCode, 3);
        QVERIFY2(run.err.contains(QStringLiteral("cannot connect")), qPrintable(run.err));
    }

    void writesPersistOnASimulatorServer()
    {
        SimulatorProcess server({QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                                 QStringLiteral("--address"), QStringLiteral("7")});
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString target = server.target();
        const QStringList common{QStringLiteral("--connect"), target, QStringLiteral("--protocol"),
                                 QStringLiteral("din66019ii"), QStringLiteral("--address"), QStringLiteral("7"),
                                 QStringLiteral("--quiet")};
        Run run = cli(common + QStringList{QStringLiteral("write"), QStringLiteral("op.30"), QStringLiteral("7.25"),
                                           QStringLiteral("--sets"), QStringLiteral("1")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        run = cli(common + QStringList{QStringLiteral("read"), QStringLiteral("op.30"), QStringLiteral("--set"),
                                       QStringLiteral("1")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("7.25 s")), qPrintable(run.out));
        run = cli(common + QStringList{QStringLiteral("read"), QStringLiteral("op.30"), QStringLiteral("--set"),
                                       QStringLiteral("0")});
        QVERIFY2(run.out.contains(QStringLiteral("5.00 s")), qPrintable(run.out));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
