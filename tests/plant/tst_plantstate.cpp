#include "bus/LinkFactory.h"
#include "bus/SimulatorServer.h"
#include "plant/PlantState.h"

#include <QDir>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

namespace {

// A plant's link as the plant file names it.
PlantLink link(const QString &name, const QString &connect, Protocol protocol)
{
    return PlantLink { .name = name,
                       .connect = connect,
                       .protocol = protocol,
                       .baudRate = std::nullopt,
                       .addresses = {} };
}

using Reach = PlantState::Reach;

} // namespace

// What DriveDesk knows of a plant's drives, fed by real runs against simulated drives.
class TestPlantState : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString m_dead;
    std::unique_ptr<SimulatorServer> m_bus; // a DIN66019II bus of the drives 2 and 7
    Plant m_plant;

    // A run as the window makes it; a search with a short wait per address that no drive
    // answers.
    std::unique_ptr<PlantRun> makeRun(const Plant &plant, PlantRun::Task task,
                                      const QString &directory = {}) const
    {
        auto run = std::make_unique<PlantRun>(plant, task, directory, everyLink());
        if (task == PlantRun::Task::Find) {
            ClientOptions options;
            options.timeoutMs = 20;
            run->setClientOptions(options);
        }
        ScanOptions reading;
        reading.metadata = MetadataSource::Cache;
        reading.cacheDirectory = m_dir.filePath(QStringLiteral("cache"));
        run->setReading(reading);
        return run;
    }

    static bool runToEnd(PlantRun &run)
    {
        QSignalSpy finished(&run, &PlantRun::finished);
        run.start();
        return finished.wait(30000);
    }

    // Runs `task` on the plant `state` shows, followed by `state`, to its end.
    bool run(PlantState &state, PlantRun::Task task, const QString &directory = {}) const
    {
        const std::unique_ptr<PlantRun> run = makeRun(state.plant(), task, directory);
        state.follow(run.get());
        return runToEnd(*run);
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QTcpServer closed;
        QVERIFY(closed.listen(QHostAddress::LocalHost));
        m_dead = QStringLiteral("tcp:127.0.0.1:%1").arg(closed.serverPort());
        closed.close();
        SimulationOptions simulation;
        simulation.driveAddresses = { 2, 7 };
        m_bus = std::make_unique<SimulatorServer>(Protocol::Din66019II, simulation);
        QVERIFY(m_bus->listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr));
        m_plant.name = QStringLiteral("Line 3");
        m_plant.links = { link(QStringLiteral("bus"),
                               QStringLiteral("tcp:127.0.0.1:%1").arg(m_bus->tcpPort()),
                               Protocol::Din66019II),
                          link(QStringLiteral("single"), QStringLiteral("sim"), Protocol::Hsp5),
                          link(QStringLiteral("dead"), m_dead, Protocol::Hsp5) };
    }

    void findShowsWhoAnswers()
    {
        PlantState state;
        state.openPlant(m_plant, {});
        QCOMPARE(state.drive(QStringLiteral("single"), -1).reach, Reach::NotSearched);
        QCOMPARE(state.linkReach(QStringLiteral("bus")), Reach::NotSearched);
        QSignalSpy added(&state, &PlantState::driveAdded);
        QSignalSpy changed(&state, &PlantState::driveChanged);
        bool progressShown = false;
        connect(&state, &PlantState::linkChanged, this, [&](const QString &link) {
            progressShown = progressShown || state.link(link).percent >= 0;
        });
        QVERIFY(run(state, PlantRun::Task::Find));

        // The bus listed no drives: the two the search found belong to the plant now.
        QCOMPARE(added.size(), 2);
        QCOMPARE(state.plant().links.at(0).addresses, QList<int>({ 2, 7 }));
        QVERIFY(progressShown); // the bus's search
        QVERIFY(!changed.isEmpty());
        for (const auto &[link, address] : { std::pair { QStringLiteral("bus"), 2 },
                                             std::pair { QStringLiteral("bus"), 7 },
                                             std::pair { QStringLiteral("single"), -1 } }) {
            const PlantState::KnownDrive drive = state.drive(link, address);
            QCOMPARE(drive.reach, Reach::Answering);
            QVERIFY2(drive.identification.contains(QStringLiteral("software")),
                     qPrintable(drive.identification));
            QVERIFY(drive.result);
            QCOMPARE(drive.result->outcome, PlantDrive::Outcome::Found);
            QCOMPARE(drive.percent, -1);
        }
        const PlantState::KnownDrive dead = state.drive(QStringLiteral("dead"), -1);
        QCOMPARE(dead.reach, Reach::Unreachable);
        QVERIFY2(dead.why.contains(QStringLiteral("cannot connect")), qPrintable(dead.why));
        QCOMPARE(state.linkReach(QStringLiteral("bus")), Reach::Answering);
        QCOMPARE(state.linkReach(QStringLiteral("single")), Reach::Answering);
        QCOMPARE(state.linkReach(QStringLiteral("dead")), Reach::Unreachable);
    }

    void resultsAndBackupTimes()
    {
        const QString backups = m_dir.filePath(QStringLiteral("backups"));
        QVERIFY(QDir().mkpath(backups));
        Plant plant = m_plant;
        plant.links[0].addresses = { 7, 2 };
        PlantState state;
        state.openPlant(plant, backups);
        QVERIFY(!state.drive(QStringLiteral("bus"), 2).backup.isValid());
        QVERIFY(run(state, PlantRun::Task::Backup, backups));
        for (const auto &[link, address] : { std::pair { QStringLiteral("bus"), 2 },
                                             std::pair { QStringLiteral("bus"), 7 },
                                             std::pair { QStringLiteral("single"), -1 } }) {
            const PlantState::KnownDrive drive = state.drive(link, address);
            QCOMPARE(drive.result->outcome, PlantDrive::Outcome::Saved);
            QCOMPARE(drive.reach, Reach::Answering);
            QVERIFY(drive.backup.isValid());
        }
        QVERIFY(!state.drive(QStringLiteral("dead"), -1).backup.isValid());

        // A new job clears the last results as it starts; its own take their place.
        const std::unique_ptr<PlantRun> verify
            = makeRun(state.plant(), PlantRun::Task::Verify, backups);
        state.follow(verify.get());
        QVERIFY(!state.drive(QStringLiteral("bus"), 2).result);
        QVERIFY(runToEnd(*verify));
        QCOMPARE(state.drive(QStringLiteral("bus"), 7).result->outcome,
                 PlantDrive::Outcome::Equal);
        QCOMPARE(state.drive(QStringLiteral("dead"), -1).result->outcome,
                 PlantDrive::Outcome::NoFile);
        // No file: the link was not opened, so what the backup found out stands.
        QCOMPARE(state.drive(QStringLiteral("dead"), -1).reach, Reach::Unreachable);
        QCOMPARE(state.linkReach(QStringLiteral("dead")), Reach::Unreachable);
    }

    // A bus that cannot be opened says so as a whole; its drives that answered before are
    // reachable no more once they fail too.
    void aLinkIsUnreachableByItsOwnWordOrAllItsDrives()
    {
        Plant plant;
        plant.name = QStringLiteral("Line 5");
        plant.links = { link(QStringLiteral("bus"), m_dead, Protocol::Din66019II) };
        PlantState state;
        state.openPlant(plant, {});
        QVERIFY(run(state, PlantRun::Task::Find));
        QCOMPARE(state.linkReach(QStringLiteral("bus")), Reach::Unreachable);
        QVERIFY(state.link(QStringLiteral("bus")).result);
        QCOMPARE(state.link(QStringLiteral("bus")).result->outcome,
                 PlantDrive::Outcome::Unreachable);
        QVERIFY(state.plant().links.at(0).addresses.isEmpty());

        plant.links[0].addresses = { 2, 7 };
        state.setPlant(plant); // the addresses typed in: the link's own word still stands
        QCOMPARE(state.linkReach(QStringLiteral("bus")), Reach::Unreachable);
        QVERIFY(run(state, PlantRun::Task::Backup, m_dir.filePath(QStringLiteral("none"))));
        QCOMPARE(state.drive(QStringLiteral("bus"), 2).reach, Reach::Unreachable);
        QCOMPARE(state.drive(QStringLiteral("bus"), 7).reach, Reach::Unreachable);
        QCOMPARE(state.linkReach(QStringLiteral("bus")), Reach::Unreachable);
    }

    void anotherPlantWithTheSameLinkNamesStartsClean()
    {
        PlantState state;
        state.openPlant(m_plant, {});
        QVERIFY(run(state, PlantRun::Task::Find));
        QCOMPARE(state.drive(QStringLiteral("single"), -1).reach, Reach::Answering);
        QSignalSpy reset(&state, &PlantState::reset);
        state.openPlant(m_plant, {});
        QCOMPARE(reset.size(), 1);
        for (const auto &[link, address] : { std::pair { QStringLiteral("bus"), 2 },
                                             std::pair { QStringLiteral("single"), -1 },
                                             std::pair { QStringLiteral("dead"), -1 } }) {
            const PlantState::KnownDrive drive = state.drive(link, address);
            QCOMPARE(drive.reach, Reach::NotSearched);
            QVERIFY(drive.identification.isEmpty());
            QVERIFY(!drive.result);
        }
        QCOMPARE(state.linkReach(QStringLiteral("dead")), Reach::NotSearched);
    }

    // A run still on its way when another plant is opened leaves nothing in it.
    void aRunOfThePlantBeforeIsIgnored()
    {
        PlantState state;
        state.openPlant(m_plant, {});
        const std::unique_ptr<PlantRun> find = makeRun(m_plant, PlantRun::Task::Find);
        state.follow(find.get());
        QSignalSpy finished(find.get(), &PlantRun::finished);
        find->start();
        state.openPlant(m_plant, {});
        QSignalSpy changed(&state, &PlantState::driveChanged);
        QVERIFY(finished.wait(30000));
        QVERIFY(changed.isEmpty());
        QCOMPARE(state.drive(QStringLiteral("single"), -1).reach, Reach::NotSearched);
        QVERIFY(state.plant().links.at(0).addresses.isEmpty());
    }

    // A comparison reads two drives into files of its own: their last results stay.
    void aRunKeptForItsProgressOnlyLeavesTheResults()
    {
        PlantState state;
        state.openPlant(m_plant, {});
        QVERIFY(run(state, PlantRun::Task::Find));
        Plant single = state.plant();
        single.links = { single.links.at(1) };
        QTemporaryDir readings;
        QVERIFY(readings.isValid());
        const std::unique_ptr<PlantRun> read
            = makeRun(single, PlantRun::Task::Backup, readings.path());
        bool progressShown = false;
        connect(&state, &PlantState::driveChanged, this, [&](const QString &link, int address) {
            progressShown = progressShown || state.drive(link, address).percent >= 0;
        });
        state.follow(read.get(), PlantState::Keep::ProgressOnly);
        QVERIFY(runToEnd(*read));
        QCOMPARE(read->drives().value(0).outcome, PlantDrive::Outcome::Saved);
        QVERIFY(progressShown);
        const PlantState::KnownDrive drive = state.drive(QStringLiteral("single"), -1);
        QVERIFY(drive.result);
        QCOMPARE(drive.result->outcome, PlantDrive::Outcome::Found);
        QCOMPARE(drive.percent, -1);
    }

    void editingThePlantKeepsWhatIsKnown()
    {
        PlantState state;
        state.openPlant(m_plant, {});
        QVERIFY(run(state, PlantRun::Task::Find));
        Plant edited = state.plant();
        edited.links.append(link(QStringLiteral("press"), QStringLiteral("sim"), Protocol::Hsp5));
        edited.links[0].addresses.removeAll(7);
        QSignalSpy reset(&state, &PlantState::reset);
        state.setPlant(edited);
        QCOMPARE(reset.size(), 1);
        QCOMPARE(state.drive(QStringLiteral("single"), -1).reach, Reach::Answering);
        QVERIFY(state.drive(QStringLiteral("bus"), 2).identification.contains(
            QStringLiteral("software")));
        QCOMPARE(state.drive(QStringLiteral("dead"), -1).reach, Reach::Unreachable);
        QCOMPARE(state.linkReach(QStringLiteral("bus")), Reach::Answering);
        QCOMPARE(state.drive(QStringLiteral("press"), -1).reach, Reach::NotSearched);
        // A drive taken out of the plant is forgotten.
        QCOMPARE(state.drive(QStringLiteral("bus"), 7).reach, Reach::NotSearched);
    }
};

QTEST_MAIN(TestPlantState)
#include "tst_plantstate.moc"
