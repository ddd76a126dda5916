#include "bus/LinkFactory.h"
#include "bus/SimulatorServer.h"
#include "plant/PlantRun.h"

#include <QMap>

#include <QDir>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

namespace {

PlantLink link(const QString &name, const QString &connect, Protocol protocol,
               QList<int> addresses = {})
{
    PlantLink result;
    result.name = name;
    result.connect = connect;
    result.protocol = protocol;
    result.addresses = std::move(addresses);
    return result;
}

// "bus-2 saved", one line a drive, for a readable comparison.
QStringList outcomes(const QList<PlantDrive> &drives)
{
    QStringList lines;
    for (const PlantDrive &drive : drives)
        lines << drive.name() + QLatin1Char(' ') + PlantDrive::outcomeText(drive.outcome)
                     + (drive.isGood() || drive.outcome == PlantDrive::Outcome::Unreachable
                                || drive.outcome == PlantDrive::Outcome::NoFile
                            ? QString()
                            : QStringLiteral(": ") + drive.reason);
    return lines;
}

QList<PlantDrive> runToEnd(PlantRun &run)
{
    QSignalSpy finished(&run, &PlantRun::finished);
    run.start();
    if (!finished.wait(30000))
        return {};
    return run.drives();
}

} // namespace

// The job behind `drivedesk-cli plant`: links side by side, each failing only its own drives.
class TestPlantRun : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QTcpServer closed;
        QVERIFY(closed.listen(QHostAddress::LocalHost));
        m_dead = QStringLiteral("tcp:127.0.0.1:%1").arg(closed.serverPort());
        closed.close();
        m_plant.name = QStringLiteral("Line 3");
        m_plant.links = {link(QStringLiteral("bus"), QStringLiteral("sim"), Protocol::Din66019II, {5, 2}),
                         link(QStringLiteral("single"), QStringLiteral("sim"), Protocol::Hsp5),
                         link(QStringLiteral("dead"), m_dead, Protocol::Hsp5)};
    }

    void fileNames()
    {
        QCOMPARE(PlantRun::fileFor(QStringLiteral("/b"), m_plant.links[0], 5), QStringLiteral("/b/bus-5.json"));
        QCOMPARE(PlantRun::fileFor(QStringLiteral("/b"), m_plant.links[1], -1), QStringLiteral("/b/single.json"));
    }

    void backUpThenVerify()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        // Metadata once per kind of drive, as the command line reads it.
        ScanOptions reading;
        reading.metadata = MetadataSource::Cache;
        reading.cacheDirectory = dir.filePath(QStringLiteral("cache"));
        PlantRun backup(m_plant, PlantRun::Task::Backup, dir.path(), everyLink());
        backup.setReading(reading);
        QCOMPARE(outcomes(runToEnd(backup)),
                 QStringList({QStringLiteral("bus-2 saved"), QStringLiteral("bus-5 saved"),
                              QStringLiteral("single saved"), QStringLiteral("dead unreachable")}));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden, QDir::Name),
                 QStringList({QStringLiteral("bus-2.json"), QStringLiteral("bus-5.json"),
                              QStringLiteral("single.json")}));

        PlantRun verify(m_plant, PlantRun::Task::Verify, dir.path(), everyLink());
        verify.setReading(reading);
        const QList<PlantDrive> drives = runToEnd(verify);
        QCOMPARE(outcomes(drives),
                 QStringList({QStringLiteral("bus-2 equal"), QStringLiteral("bus-5 equal"),
                              QStringLiteral("single equal"), QStringLiteral("dead no file")}));
    }

    void findNamesTheDrivesOnTheBus()
    {
        // The whole bus is searched, whatever the plant says is on it.
        const Plant plant = m_plant;
        PlantRun find(plant, PlantRun::Task::Find, {}, everyLink());
        ClientOptions options;
        options.timeoutMs = 20; // a short wait per address that no drive answers
        find.setClientOptions(options);
        const QList<PlantDrive> drives = runToEnd(find);
        QCOMPARE(outcomes(drives),
                 QStringList({QStringLiteral("bus-2 found"), QStringLiteral("bus-5 found"),
                              QStringLiteral("single found"), QStringLiteral("dead unreachable")}));
        QVERIFY(drives.at(0).identification.contains(QStringLiteral("software")));
        QCOMPARE(find.plant().links.at(0).addresses, QList<int>({2, 5})); // as found
        QCOMPARE(find.plant().links.at(1), plant.links.at(1));
        QCOMPARE(find.plant().links.at(2), plant.links.at(2));
    }

    void aStoppedRunSavesNothingItDidNotReadWhole()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        PlantRun backup(m_plant, PlantRun::Task::Backup, dir.path(), everyLink());
        QSignalSpy finished(&backup, &PlantRun::finished);
        backup.start();
        backup.stop();
        QVERIFY(finished.wait(30000));
        for (const PlantDrive &drive : backup.drives()) {
            QVERIFY2(drive.outcome == PlantDrive::Outcome::Stopped
                         || drive.outcome == PlantDrive::Outcome::Unreachable,
                     qPrintable(drive.name()));
        }
        QCOMPARE(backup.drives().size(), 4);
        QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    }

    // A bus is one line: its drives are asked one after another over the one connection, not
    // each over a connection of its own.
    void everyDriveOfALinkOverOneConnection()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QMap<QString, int> opened;
        const LinkMaker every = everyLink();
        const LinkMaker counting = [&opened, every](const ConnectionSettings &settings) {
            ++opened[settings.displayName()];
            return every(settings);
        };
        Plant plant = m_plant;
        plant.links.removeLast();
        plant.links.first().addresses = {2, 5, 7};
        for (PlantRun::Task task : {PlantRun::Task::Backup, PlantRun::Task::Verify}) {
            opened.clear();
            PlantRun run(plant, task, dir.path(), counting);
            ScanOptions reading;
            reading.metadata = MetadataSource::Cache;
            reading.cacheDirectory = dir.filePath(QStringLiteral("cache"));
            run.setReading(reading);
            const QList<PlantDrive> drives = runToEnd(run);
            const QString good = task == PlantRun::Task::Backup ? QStringLiteral("saved")
                                                                : QStringLiteral("equal");
            QCOMPARE(outcomes(drives),
                     QStringList({QStringLiteral("bus-2 ") + good, QStringLiteral("bus-5 ") + good,
                                  QStringLiteral("bus-7 ") + good,
                                  QStringLiteral("single ") + good}));
            QCOMPARE(opened.size(), 2);
            for (auto it = opened.cbegin(); it != opened.cend(); ++it)
                QVERIFY2(it.value() == 1, qPrintable(QStringLiteral("%1 opened %2 times")
                                                          .arg(it.key()).arg(it.value())));
        }
    }

    // A drive switched off on a bus fails alone: the drives after it on the same line are
    // read as if it were not there.
    void aSilentDriveOnABusFailsOnlyItself()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        SimulationOptions simulation;
        simulation.driveAddresses = {2, 7};
        SimulatorServer server(Protocol::Din66019II, simulation);
        QVERIFY(server.listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr));
        Plant plant;
        plant.name = QStringLiteral("Line 4");
        plant.links = {link(QStringLiteral("bus"),
                            QStringLiteral("tcp:127.0.0.1:%1").arg(server.tcpPort()),
                            Protocol::Din66019II, {2, 5, 7})};
        PlantRun backup(plant, PlantRun::Task::Backup, dir.path(), everyLink());
        ScanOptions reading;
        reading.metadata = MetadataSource::Cache;
        reading.cacheDirectory = dir.filePath(QStringLiteral("cache"));
        backup.setReading(reading);
        const QList<PlantDrive> drives = runToEnd(backup);
        QCOMPARE(drives.size(), 3);
        QCOMPARE(drives.at(0).outcome, PlantDrive::Outcome::Saved);
        QCOMPARE(drives.at(1).outcome, PlantDrive::Outcome::Failed);
        QVERIFY2(drives.at(1).reason.contains(QStringLiteral("stopped answering")),
                 qPrintable(drives.at(1).reason));
        QCOMPARE(drives.at(2).outcome, PlantDrive::Outcome::Saved);
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("bus-7.json"))));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("bus-5.json"))));
    }

private:
    Plant m_plant;
    QString m_dead;
};

QTEST_GUILESS_MAIN(TestPlantRun)
#include "tst_plantrun.moc"
