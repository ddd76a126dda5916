#include "CliTestSupport.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTemporaryDir>

#include <csignal>

using namespace DriveDesk::CliTest;

namespace {

QString planText(const QString &bus, const QString &busAddresses, const QString &hoist,
                 const QString &dead = {})
{
    QString text = QStringLiteral(
                       "{\n"
                       "    \"format\": \"drivedesk-plant\",\n"
                       "    \"version\": 1,\n"
                       "    \"name\": \"Line 3\",\n"
                       "    \"links\": [\n"
                       "        {\n"
                       "            \"name\": \"cabinet\",\n"
                       "            \"connect\": \"%1\",\n"
                       "            \"protocol\": \"din66019ii\"%2\n"
                       "        },\n"
                       "        {\n"
                       "            \"name\": \"hoist\",\n"
                       "            \"connect\": \"%3\",\n"
                       "            \"protocol\": \"hsp5\"\n"
                       "        }")
                       .arg(bus,
                            busAddresses.isEmpty()
                                ? QString()
                                : QStringLiteral(",\n            \"addresses\": [%1]").arg(busAddresses),
                            hoist);
    if (!dead.isEmpty()) {
        text += QStringLiteral(",\n"
                               "        {\n"
                               "            \"name\": \"dead\",\n"
                               "            \"connect\": \"%1\",\n"
                               "            \"protocol\": \"hsp5\"\n"
                               "        }")
                    .arg(dead);
    }
    return text + QStringLiteral("\n    ]\n}\n");
}

bool writeText(const QString &path, const QString &text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && file.write(text.toUtf8()) == text.toUtf8().size();
}

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// The first value of a parameter in a parameter file; -1 when it is not there.
qint64 valueInFile(const QString &path, const QString &id)
{
    const QJsonArray groups = QJsonDocument::fromJson(readText(path).toUtf8())
                                  .object()
                                  .value(QStringLiteral("groups"))
                                  .toArray();
    for (const QJsonValue &group : groups) {
        for (const QJsonValue &parameter :
             group.toObject().value(QStringLiteral("parameters")).toArray()) {
            if (parameter.toObject().value(QStringLiteral("id")).toString() == id)
                return parameter.toObject().value(QStringLiteral("values")).toArray().at(0).toInteger(-1);
        }
    }
    return -1;
}

} // namespace

// drivedesk-cli plant: every drive of a machine at once, against a DIN66019II bus of three
// drives (drive 9 of another kind), an HSP5 drive and a gateway that is not there.
class TestCliPlant : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        m_bus = std::make_unique<SimulatorProcess>(
            QStringList{QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                        QStringLiteral("--address"), QStringLiteral("2,5,9"),
                        QStringLiteral("--other-kind"), QStringLiteral("9")});
        QVERIFY2(m_bus->started(), qPrintable(m_bus->error()));
        m_hoist = std::make_unique<SimulatorProcess>();
        QVERIFY2(m_hoist->started(), qPrintable(m_hoist->error()));
        // A port that was just free and is closed again: a gateway that is switched off.
        QTcpServer closed;
        QVERIFY(closed.listen(QHostAddress::LocalHost));
        m_dead = QStringLiteral("tcp:127.0.0.1:%1").arg(closed.serverPort());
        closed.close();
        QVERIFY(m_dir.isValid());
        m_backups = m_dir.filePath(QStringLiteral("backups"));
        m_plant = m_dir.filePath(QStringLiteral("line3.json"));
        m_live = m_dir.filePath(QStringLiteral("live.json"));
        QVERIFY(writeText(m_plant, planText(m_bus->target(), {}, m_hoist->target(), m_dead)));
        QVERIFY(writeText(m_live, planText(m_bus->target(), QStringLiteral("2, 5, 9"),
                                           m_hoist->target())));
    }

    void cleanupTestCase()
    {
        m_bus.reset();
        m_hoist.reset();
    }

    void findListsEveryDriveAndUpdatesThePlant()
    {
        // A short wait per address keeps the search of 240 addresses to a few seconds.
        const Run run = cli({QStringLiteral("plant"), QStringLiteral("find"), m_plant,
                             QStringLiteral("--update"), QStringLiteral("--timeout"),
                             QStringLiteral("20"), QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run))); // the dead gateway
        for (const QString &drive : {QStringLiteral("cabinet-2"), QStringLiteral("cabinet-5"),
                                     QStringLiteral("cabinet-9"), QStringLiteral("hoist")}) {
            QVERIFY2(run.out.contains(QRegularExpression(
                         QStringLiteral("^%1: inverter identifier .*software").arg(drive),
                         QRegularExpression::MultilineOption)),
                     qPrintable(drive + QLatin1Char('\n') + run.out));
        }
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("^dead: unreachable: "),
                                                     QRegularExpression::MultilineOption)),
                 qPrintable(run.out));
        QVERIFY2(!run.out.contains(QStringLiteral("cabinet-1:")), qPrintable(run.out));
        // The addresses found, and not a byte else changed.
        QCOMPARE(readText(m_plant),
                 planText(m_bus->target(), QStringLiteral("2, 5, 9"), m_hoist->target(), m_dead));
    }

    void backupSavesEveryDriveItCouldReadWhole()
    {
        // Drive 7 is not on the bus: it never answers, and fails alone.
        QVERIFY(writeText(m_plant, planText(m_bus->target(), QStringLiteral("2, 5, 7, 9"),
                                            m_hoist->target(), m_dead)));
        const Run run = cli({QStringLiteral("plant"), QStringLiteral("backup"), m_plant, m_backups});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
        const QStringList saved{QStringLiteral("cabinet-2"), QStringLiteral("cabinet-5"),
                                QStringLiteral("cabinet-9"), QStringLiteral("hoist")};
        for (const QString &drive : saved) {
            QVERIFY2(run.out.contains(QStringLiteral("%1: saved").arg(drive)), qPrintable(run.out));
            const QString file = QDir(m_backups).filePath(drive + QStringLiteral(".json"));
            QVERIFY2(readText(file).contains(QStringLiteral("\"drivedesk-parameters\"")),
                     qPrintable(file));
        }
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("^cabinet-7: not saved: failed: "),
                                                     QRegularExpression::MultilineOption)),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("^dead: not saved: unreachable: "),
                                                     QRegularExpression::MultilineOption)),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("4 of 6 drive")), qPrintable(run.out));
        QVERIFY2(run.err.contains(QStringLiteral("hoist: [")), qPrintable(run.err)); // progress
        // Nothing under a final name for a drive not read whole, and no half-written file.
        QCOMPARE(QDir(m_backups).entryList(QDir::Files | QDir::Hidden, QDir::Name),
                 QStringList({QStringLiteral("cabinet-2.json"), QStringLiteral("cabinet-5.json"),
                              QStringLiteral("cabinet-9.json"), QStringLiteral("hoist.json")}));
        // Each file is its own drive's: the drives on the bus differ.
        const Run diff = cli({QStringLiteral("diff"), QDir(m_backups).filePath(QStringLiteral("cabinet-2.json")),
                              QDir(m_backups).filePath(QStringLiteral("cabinet-5.json"))});
        QVERIFY2(diff.exitCode == 1 && diff.out.contains(QStringLiteral("op.28")), qPrintable(explain(diff)));
    }

    // Live values move on, settings do not: a drive just backed up is equal to its file.
    void verifyRightAfterBackupIsEqual()
    {
        const QString file = QDir(m_backups).filePath(QStringLiteral("cabinet-2.json"));
        const qint64 timer = valueInFile(file, QStringLiteral("Sy.32"));
        QVERIFY(timer >= 0);
        const Run read = cli({QStringLiteral("--connect"), m_bus->target(), QStringLiteral("--protocol"),
                              QStringLiteral("din66019ii"), QStringLiteral("--address"), QStringLiteral("2"),
                              QStringLiteral("--quiet"), QStringLiteral("read"), QStringLiteral("Sy.32")});
        QVERIFY2(read.exitCode == 0, qPrintable(explain(read)));
        QVERIFY2(!read.out.contains(QStringLiteral("(raw %1,").arg(timer)), qPrintable(read.out));

        const Run run = cli({QStringLiteral("plant"), QStringLiteral("verify"), m_live, m_backups,
                             QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        for (const QString &drive : {QStringLiteral("cabinet-2"), QStringLiteral("cabinet-5"),
                                     QStringLiteral("cabinet-9"), QStringLiteral("hoist")})
            QVERIFY2(run.out.contains(QStringLiteral("%1: equal\n").arg(drive)), qPrintable(run.out));
    }

    void aChangeIsFoundOnThatDriveOnly()
    {
        Run run = cli({QStringLiteral("--connect"), m_bus->target(), QStringLiteral("--protocol"),
                       QStringLiteral("din66019ii"), QStringLiteral("--address"), QStringLiteral("5"),
                       QStringLiteral("--quiet"), QStringLiteral("write"), QStringLiteral("op.11"),
                       QStringLiteral("2500"), QStringLiteral("--sets"), QStringLiteral("2")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));

        run = cli({QStringLiteral("plant"), QStringLiteral("verify"), m_live, m_backups,
                   QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral(
                     "cabinet-5: 1 difference.*\n  op.11  Maximum speed forward  set 2  file 3000 1/min  drive 2500 1/min\n"))),
                 qPrintable(run.out));
        for (const QString &drive : {QStringLiteral("cabinet-2"), QStringLiteral("cabinet-9"),
                                     QStringLiteral("hoist")})
            QVERIFY2(run.out.contains(QStringLiteral("%1: equal\n").arg(drive)), qPrintable(run.out));

        run = cli({QStringLiteral("plant"), QStringLiteral("verify"), m_live, m_backups,
                   QStringLiteral("--quiet"), QStringLiteral("--format"), QStringLiteral("json")});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
        const QJsonArray drives = QJsonDocument::fromJson(run.out.toUtf8()).object()
                                      .value(QStringLiteral("drives")).toArray();
        QCOMPARE(drives.size(), 4);
        for (const QJsonValue &drive : drives) {
            const QJsonObject object = drive.toObject();
            const bool five = object.value(QStringLiteral("address")).toInt() == 5;
            QCOMPARE(object.value(QStringLiteral("result")).toString(),
                     five ? QStringLiteral("different") : QStringLiteral("equal"));
            QCOMPARE(object.value(QStringLiteral("differences")).toArray().size(), five ? 1 : 0);
        }
        const QJsonObject difference = drives.at(1).toObject().value(QStringLiteral("differences"))
                                           .toArray().at(0).toObject();
        QCOMPARE(difference.value(QStringLiteral("id")).toString(), QStringLiteral("op.11"));
        QCOMPARE(difference.value(QStringLiteral("set")).toInt(), 2);
        QCOMPARE(difference.value(QStringLiteral("file")).toString(), QStringLiteral("3000 1/min"));
        QCOMPARE(difference.value(QStringLiteral("drive")).toString(), QStringLiteral("2500 1/min"));
    }

    void anotherKindOfDriveAndAMissingFileAreReported()
    {
        const QString other = m_dir.filePath(QStringLiteral("mixed"));
        QVERIFY(QDir().mkpath(other));
        // Drive 2's file taken from drive 9, which runs other software; drive 5 has none.
        QVERIFY(QFile::copy(QDir(m_backups).filePath(QStringLiteral("cabinet-9.json")),
                            QDir(other).filePath(QStringLiteral("cabinet-2.json"))));
        QVERIFY(QFile::copy(QDir(m_backups).filePath(QStringLiteral("cabinet-9.json")),
                            QDir(other).filePath(QStringLiteral("cabinet-9.json"))));
        QVERIFY(QFile::copy(QDir(m_backups).filePath(QStringLiteral("hoist.json")),
                            QDir(other).filePath(QStringLiteral("hoist.json"))));
        const Run run = cli({QStringLiteral("plant"), QStringLiteral("verify"), m_live, other,
                             QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
        // As the download judges it, naming what differs.
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-2: another kind of drive: the file was made "
                                                 "for another drive: In.06 Software version is ")),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-5: no file: ")), qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-9: equal\n")), qPrintable(run.out));
    }

    // Drive 5 still holds the change of aChangeIsFoundOnThatDriveOnly().
    void downloadWritesOnlyToTheDrivesThatDiffer()
    {
        const QStringList drive5{QStringLiteral("--connect"), m_bus->target(), QStringLiteral("--protocol"),
                                 QStringLiteral("din66019ii"), QStringLiteral("--address"), QStringLiteral("5"),
                                 QStringLiteral("--quiet"), QStringLiteral("read"), QStringLiteral("op.11"),
                                 QStringLiteral("--set"), QStringLiteral("2")};
        Run run = cli({QStringLiteral("plant"), QStringLiteral("download"), m_live, m_backups,
                       QStringLiteral("--dry-run"), QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-5: dry run: ")), qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("  op.11  Maximum speed forward, set 2: 2500 1/min -> 3000 1/min\n")),
                 qPrintable(run.out));
        Run read = cli(drive5);
        QVERIFY2(read.out.contains(QStringLiteral("2500 1/min")), qPrintable(explain(read)));

        const QString journal = m_dir.filePath(QStringLiteral("plant-journal.sqlite"));
        run = cli({QStringLiteral("plant"), QStringLiteral("download"), m_live, m_backups,
                   QStringLiteral("--quiet"), QStringLiteral("--journal"), journal});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-5: written\n")), qPrintable(run.out));
        // Each value written has its entry, of drive 5 alone: the others were not written to.
        const Run journaled = cli({QStringLiteral("journal"), QStringLiteral("--journal"), journal,
                                   QStringLiteral("--format"), QStringLiteral("json")});
        QVERIFY2(journaled.exitCode == 0, qPrintable(explain(journaled)));
        const QJsonArray entries = QJsonDocument::fromJson(journaled.out.toUtf8()).array();
        QVERIFY2(!entries.isEmpty(), qPrintable(journaled.out));
        int maximumSpeed = 0;
        for (const QJsonValue &value : entries) {
            const QJsonObject entry = value.toObject();
            QCOMPARE(entry.value(QStringLiteral("job")).toObject().value(QStringLiteral("description")).toString(),
                     QStringLiteral("plant download of live.json"));
            QCOMPARE(entry.value(QStringLiteral("drive")).toObject().value(QStringLiteral("address")).toInt(), 5);
            QCOMPARE(entry.value(QStringLiteral("outcome")).toString(), QStringLiteral("written"));
            if (entry.value(QStringLiteral("parameter")).toObject().value(QStringLiteral("id")).toString()
                != QLatin1String("op.11"))
                continue;
            ++maximumSpeed;
            QCOMPARE(entry.value(QStringLiteral("set")).toInt(), 2);
            QCOMPARE(entry.value(QStringLiteral("before")).toObject().value(QStringLiteral("raw")).toInt(), 2500);
            QCOMPARE(entry.value(QStringLiteral("written")).toObject().value(QStringLiteral("raw")).toInt(), 3000);
            QCOMPARE(entry.value(QStringLiteral("readBack")).toObject().value(QStringLiteral("raw")).toInt(), 3000);
        }
        QCOMPARE(maximumSpeed, 1);
        for (const QString &drive : {QStringLiteral("cabinet-2"), QStringLiteral("cabinet-9"),
                                     QStringLiteral("hoist")}) {
            QVERIFY2(run.out.contains(QStringLiteral("%1: already equal, nothing written\n").arg(drive)),
                     qPrintable(run.out));
        }
        read = cli(drive5);
        QVERIFY2(read.out.contains(QStringLiteral("3000 1/min")), qPrintable(explain(read)));
        run = cli({QStringLiteral("plant"), QStringLiteral("verify"), m_live, m_backups,
                   QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
    }

    // A drive with no identification parameters takes its own backup, matched by its
    // metadata, without --force; a file of another kind is refused, naming where it differs.
    void anUnidentifiedDriveTakesItsOwnBackup()
    {
        SimulatorProcess bus({QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                              QStringLiteral("--address"), QStringLiteral("9,11"),
                              QStringLiteral("--other-kind"), QStringLiteral("9"),
                              QStringLiteral("--unidentified"), QStringLiteral("11")});
        QVERIFY2(bus.started(), qPrintable(bus.error()));
        const QString plant = m_dir.filePath(QStringLiteral("unidentified.json"));
        QVERIFY(writeText(plant, planText(bus.target(), QStringLiteral("9, 11"), m_hoist->target())));
        const QString directory = m_dir.filePath(QStringLiteral("unidentified"));
        Run run = cli({QStringLiteral("plant"), QStringLiteral("backup"), plant, directory,
                       QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList drive11{QStringLiteral("--connect"), bus.target(), QStringLiteral("--protocol"),
                                  QStringLiteral("din66019ii"), QStringLiteral("--address"), QStringLiteral("11"),
                                  QStringLiteral("--quiet")};
        run = cli(drive11 + QStringList{QStringLiteral("write"), QStringLiteral("op.11"), QStringLiteral("2500"),
                                         QStringLiteral("--sets"), QStringLiteral("2")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));

        run = cli({QStringLiteral("plant"), QStringLiteral("download"), plant, directory,
                   QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-11: written\n")), qPrintable(run.out));
        run = cli(drive11 + QStringList{QStringLiteral("read"), QStringLiteral("op.11"), QStringLiteral("--set"),
                                         QStringLiteral("2")});
        QVERIFY2(run.out.contains(QStringLiteral("3000 1/min")), qPrintable(explain(run)));

        const QString own = QDir(directory).filePath(QStringLiteral("cabinet-11.json"));
        QVERIFY(QFile::remove(own));
        QVERIFY(QFile::copy(QDir(directory).filePath(QStringLiteral("cabinet-9.json")), own));
        run = cli({QStringLiteral("plant"), QStringLiteral("download"), plant, directory,
                   QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-11: failed: refused, nothing written: the drive has "
                                                 "no identification, and the file's metadata is not the "
                                                 "drive's: In.00 ")),
                 qPrintable(run.out));
        // A check against that file finds the same: not settings that differ, another kind.
        run = cli({QStringLiteral("plant"), QStringLiteral("verify"), plant, directory,
                   QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-11: another kind of drive: the drive has no "
                                                 "identification, and the file's metadata is not the "
                                                 "drive's: In.00 ")),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-9: equal\n")), qPrintable(run.out));
    }

    // Ctrl+C while the bus is searched: every link stops, what was done is reported, the run
    // ends with 130 as every command an interrupt ends, and no drive of the bus has a file.
    void anInterruptStopsEveryLink()
    {
        const QString plant = m_dir.filePath(QStringLiteral("search.json"));
        QVERIFY(writeText(plant, planText(m_bus->target(), {}, m_hoist->target())));
        const QString directory = m_dir.filePath(QStringLiteral("interrupted"));
        QProcess process;
        process.start(kCli, {QStringLiteral("plant"), QStringLiteral("backup"), plant, directory});
        QVERIFY(process.waitForStarted());
        QString err;
        QVERIFY(QTest::qWaitFor([&] {
            process.waitForReadyRead(100);
            err += QString::fromUtf8(process.readAllStandardError());
            return err.contains(QStringLiteral("cabinet: [  0%] searching"));
        }, 10000));
        ::kill(pid_t(process.processId()), SIGINT);
        QVERIFY2(process.waitForFinished(15000), qPrintable(err));
        const QString out = QString::fromUtf8(process.readAllStandardOutput());
        err += QString::fromUtf8(process.readAllStandardError());
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 130); // as any command ends on Ctrl+C, after the report
        QVERIFY2(err.contains(QStringLiteral("stopping every link")), qPrintable(err));
        QVERIFY2(out.contains(QStringLiteral("hoist: ")), qPrintable(out));
        QVERIFY2(out.contains(QRegularExpression(QStringLiteral("^\\d of \\d drive"),
                                                 QRegularExpression::MultilineOption)),
                 qPrintable(out));
        QVERIFY(QDir(directory).entryList({QStringLiteral("cabinet*")}, QDir::Files | QDir::Hidden).isEmpty());
    }

    void noLinkAnsweringIsExitThree()
    {
        const QString plant = m_dir.filePath(QStringLiteral("dead.json"));
        QVERIFY(writeText(plant, planText(m_dead, QStringLiteral("2"), m_dead)));
        const Run run = cli({QStringLiteral("plant"), QStringLiteral("verify"), plant, m_backups,
                             QStringLiteral("--quiet")});
        QVERIFY2(run.exitCode == 3, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-2: unreachable: ")), qPrintable(run.out));
    }

    void aBadPlantFileIsRefusedAndNothingIsSent()
    {
        // A gateway that would notice any connection.
        QTcpServer gateway;
        QVERIFY(gateway.listen(QHostAddress::LocalHost));
        const QString target = QStringLiteral("tcp:127.0.0.1:%1").arg(gateway.serverPort());
        const QString plant = m_dir.filePath(QStringLiteral("bad.json"));
        QVERIFY(writeText(plant, planText(target, QStringLiteral("2, 5, 2"), target)));
        for (const QString &action : {QStringLiteral("find"), QStringLiteral("backup"),
                                      QStringLiteral("verify")}) {
            QStringList arguments{QStringLiteral("plant"), action, plant};
            if (action != QLatin1String("find"))
                arguments << m_backups;
            const Run run = cli(arguments);
            QVERIFY2(run.exitCode == 2, qPrintable(explain(run)));
            QVERIFY2(run.err.contains(QStringLiteral("bad.json: links[0].addresses[2]: drive address 2 "
                                                     "appears twice (line 10, column")),
                     qPrintable(run.err));
        }
        QVERIFY(!gateway.waitForNewConnection(200));

        const Run run = cli({QStringLiteral("plant"), QStringLiteral("find"), plant,
                             QStringLiteral("--connect"), QStringLiteral("sim")});
        QVERIFY2(run.exitCode == 2 && run.err.contains(QStringLiteral("plant file")), qPrintable(explain(run)));
    }

private:
    std::unique_ptr<SimulatorProcess> m_bus;
    std::unique_ptr<SimulatorProcess> m_hoist;
    QString m_dead;
    QTemporaryDir m_dir;
    QString m_backups;
    QString m_plant;
    QString m_live;
};

QTEST_GUILESS_MAIN(TestCliPlant)
#include "tst_cliplant.moc"
