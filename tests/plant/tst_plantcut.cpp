#include "../session/DownloadReportCheck.h"

#include "bus/LinkFactory.h"
#include "bus/SimulatorServer.h"
#include "parameters/ParameterComparison.h"
#include "parameters/ParameterDocument.h"
#include "parameters/ParameterList.h"
#include "plant/PlantRun.h"

#include <QDir>
#include <QFileInfo>
#include <QMap>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <map>

using namespace DriveDesk;
using namespace DriveDesk::DownloadCheck;

namespace {

constexpr int kChangedParameters = 32; // per drive, one set each

// Each drive answers a little after a request, so that a link can be cut part-way through a
// drive's reading or writing.
SimulationOptions bus(QList<int> addresses)
{
    SimulationOptions options;
    options.driveAddresses = std::move(addresses);
    options.replyLatencyUs = 1000;
    return options;
}

// The report of a download as PlantDrive::details gives it, back in its lists. Each value of
// the file written here differs from its drive in one set only, so the sets of a line are the
// sets its item is to write; a line naming a parameter twice shows as sets on two lines.
DownloadReport reportOf(const QString &text, const DownloadPlan &plan)
{
    DownloadReport report;
    const std::map<QString, QList<DownloadReport::Line> *> sections {
        { QStringLiteral("Written:"), &report.written },
        { QStringLiteral("Refused:"), &report.refused },
        { QStringLiteral("Skipped:"), &report.skipped },
        { QStringLiteral("Not written:"), &report.notWritten },
        { QStringLiteral("Unknown (sent, no answer):"), &report.unknown }
    };
    QList<DownloadReport::Line> *section = nullptr;
    for (const QString &line : text.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        if (!line.startsWith(QLatin1Char(' '))) {
            const auto title = sections.find(line);
            section = title == sections.end() ? nullptr : title->second;
            continue;
        }
        if (!section)
            continue;
        DownloadReport::Line entry;
        entry.id = line.trimmed().section(QLatin1Char(' '), 0, 0);
        entry.detail = line.trimmed();
        for (const DownloadItem &item : plan.items) {
            if (item.id == entry.id)
                entry.sets = wantedSets(item);
        }
        section->append(entry);
    }
    return report;
}

PlantLink link(const QString &name, const SimulatorServer &server, Protocol protocol,
               QList<int> addresses = {})
{
    PlantLink result;
    result.name = name;
    result.connect = QStringLiteral("tcp:127.0.0.1:%1").arg(server.tcpPort());
    result.protocol = protocol;
    result.addresses = std::move(addresses);
    return result;
}

// "cabinet-2 saved", or with the reason for a drive that is not done.
QStringList outcomes(const QList<PlantDrive> &drives)
{
    QStringList lines;
    for (const PlantDrive &drive : drives) {
        lines << drive.name() + QLatin1Char(' ') + PlantDrive::outcomeText(drive.outcome)
                + (drive.isGood() ? QString() : QStringLiteral(": ") + drive.reason);
    }
    return lines;
}

// A DIN66019II bus of two drives and an HSP5 drive, each behind a TCP port of its own.
struct Machine
{
    SimulatorServer cabinet { Protocol::Din66019II, bus({ 2, 5 }) };
    SimulatorServer hoist { Protocol::Hsp5, bus({ 1 }) };
    Plant plant;
    QTemporaryDir dir;
    ScanOptions reading;

    bool listen(const QString &cache)
    {
        if (!cabinet.listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr)
            || !hoist.listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr) || !dir.isValid()) {
            return false;
        }
        plant.name = QStringLiteral("Line 3");
        plant.links = { link(QStringLiteral("cabinet"), cabinet, Protocol::Din66019II, { 2, 5 }),
                        link(QStringLiteral("hoist"), hoist, Protocol::Hsp5) };
        // Metadata once per kind of drive, as the command line reads it.
        reading.metadata = MetadataSource::Cache;
        reading.cacheDirectory = cache;
        return QDir().mkpath(path(QStringLiteral("backup")));
    }
    QString path(const QString &name) const { return dir.filePath(name); }
    SimulatorServer &server(const QString &linkName)
    {
        return linkName == QLatin1String("hoist") ? hoist : cabinet;
    }

    // The run to its end; `cut` closes the link named `cutLink` once a progress of the drive
    // at `cutAddress` says so.
    QList<PlantDrive> run(PlantRun::Task task, const QString &directory,
                          const std::function<bool(int percent, const QString &what)> &cut = {},
                          const QString &cutLink = {}, int cutAddress = -1, bool *wasCut = nullptr)
    {
        PlantRun job(plant, task, directory, everyLink());
        job.setReading(reading);
        QObject::connect(
            &job, &PlantRun::progress, &job,
            [&](const QString &linkName, int address, int percent, const QString &what) {
                if (!cut || *wasCut || linkName != cutLink || address != cutAddress
                    || !cut(percent, what)) {
                    return;
                }
                *wasCut = true;
                // The device server goes: its connection closes, nothing answers.
                server(linkName).close();
            });
        QSignalSpy finished(&job, &PlantRun::finished);
        job.start();
        if (!finished.wait(20000))
            return {};
        return job.drives();
    }

    bool restore(const QString &linkName)
    {
        SimulatorServer &served = server(linkName);
        const quint16 port
            = quint16(plant.link(linkName)->connect.section(QLatin1Char(':'), 2).toUInt());
        return served.listenTcp(QStringLiteral("127.0.0.1"), port, nullptr);
    }
};

const PlantDrive *driveNamed(const QList<PlantDrive> &drives, const QString &name)
{
    for (const PlantDrive &drive : drives) {
        if (drive.name() == name)
            return &drive;
    }
    return nullptr;
}

// One set of each of the first kChangedParameters values a download writes moved by one step,
// a different set from one parameter to the next.
DriveDescription changed(DriveDescription file)
{
    int count = 0;
    for (GroupDescription &group : file.groups) {
        for (ParameterDescription &p : group.parameters) {
            if (count == kChangedParameters || !p.isSetProgrammable()
                || !ParameterList::isWrittenByDownload(p)) {
                continue;
            }
            std::optional<qint32> &value = p.values[std::size_t(count % kParameterSets)];
            if (!value || p.minimum >= p.maximum)
                continue;
            value = *value > p.minimum ? *value - 1 : *value + 1;
            ++count;
        }
    }
    return file;
}

} // namespace

// A link lost part-way through a plant's backup or download: the other links go through, and
// what is said of each drive of the lost link is true of it, checked by reading it again.
class TestPlantCut : public QObject
{
    Q_OBJECT
private slots:
    void aLinkCutMidBackupSavesNothingForItsDrive_data()
    {
        QTest::addColumn<QString>("cutLink");
        QTest::addColumn<int>("cutAddress");
        // The bus while its second drive is read (the first one is done): that drive and no other.
        QTest::addRow("cabinet-5") << QStringLiteral("cabinet") << 5;
        QTest::addRow("hoist") << QStringLiteral("hoist") << -1;
    }

    void aLinkCutMidBackupSavesNothingForItsDrive()
    {
        QFETCH(QString, cutLink);
        QFETCH(int, cutAddress);
        Machine machine;
        QVERIFY(machine.listen(m_cache.path()));
        const QString backup = machine.path(QStringLiteral("backup"));
        bool cut = false;
        int cutAt = 0;
        const QList<PlantDrive> drives = machine.run(
            PlantRun::Task::Backup, backup,
            [&cutAt](int percent, const QString &) {
                cutAt = percent;
                return percent > 30 && percent < 100;
            },
            cutLink, cutAddress, &cut);
        QVERIFY2(cut, qPrintable(QString::number(cutAt)));
        QCOMPARE(drives.size(), 3);

        const QString lost
            = cutAddress < 0 ? cutLink : QStringLiteral("%1-%2").arg(cutLink).arg(cutAddress);
        QStringList saved;
        for (const PlantDrive &drive : drives) {
            if (drive.name() == lost) {
                QVERIFY2(drive.outcome == PlantDrive::Outcome::Failed
                             || drive.outcome == PlantDrive::Outcome::Unreachable,
                         qPrintable(outcomes(drives).join(QLatin1Char('\n'))));
                QVERIFY2(!drive.reason.isEmpty(), qPrintable(drive.name()));
                continue;
            }
            QVERIFY2(drive.outcome == PlantDrive::Outcome::Saved,
                     qPrintable(outcomes(drives).join(QLatin1Char('\n'))));
            QString error;
            const std::optional<DriveDescription> file
                = ParameterDocument::load(drive.file, &error);
            QVERIFY2(file, qPrintable(error));
            QVERIFY(drive.parameters > 100);
            saved << QFileInfo(drive.file).fileName();
        }
        // Nothing for the lost drive, under its name or any other: no partial or temporary file.
        QCOMPARE(QDir(backup).entryList(QDir::Files | QDir::Hidden | QDir::System, QDir::Name),
                 saved);
        QCOMPARE(QDir(backup).entryList(QDir::AllDirs | QDir::NoDotAndDotDot | QDir::Hidden),
                 QStringList());
    }

    void aLinkCutMidDownloadLeavesEveryReportTrue_data()
    {
        QTest::addColumn<QString>("cutLink");
        QTest::addColumn<int>("cutAddress");
        // The bus while its first drive is written: the second one is never reached.
        QTest::addRow("cabinet-2") << QStringLiteral("cabinet") << 2;
        QTest::addRow("hoist") << QStringLiteral("hoist") << -1;
    }

    void aLinkCutMidDownloadLeavesEveryReportTrue()
    {
        QFETCH(QString, cutLink);
        QFETCH(int, cutAddress);
        Machine machine;
        QVERIFY(machine.listen(m_cache.path()));
        const QString backup = machine.path(QStringLiteral("backup"));
        QCOMPARE(outcomes(machine.run(PlantRun::Task::Backup, backup)),
                 QStringList({ QStringLiteral("cabinet-2 saved"), QStringLiteral("cabinet-5 saved"),
                               QStringLiteral("hoist saved") }));
        // What the drives hold now, and files that differ from each in a few values.
        QMap<QString, DriveDescription> before;
        QMap<QString, DriveDescription> files;
        for (const QString &name : { QStringLiteral("cabinet-2"), QStringLiteral("cabinet-5"),
                                     QStringLiteral("hoist") }) {
            const QString path = QDir(backup).filePath(name + QStringLiteral(".json"));
            QString error;
            const std::optional<DriveDescription> held = ParameterDocument::load(path, &error);
            QVERIFY2(held, qPrintable(error));
            before.insert(name, *held);
            files.insert(name, changed(*held));
            QVERIFY2(ParameterDocument::save(path, files.value(name), &error), qPrintable(error));
        }

        bool cut = false;
        const QList<PlantDrive> drives = machine.run(
            PlantRun::Task::Download, backup,
            // Progress comes at most every 40 ms, the first at once: after the first value
            // written and read back, with most of them still to go.
            [](int percent, const QString &what) {
                return what.startsWith(QLatin1String("writing")) && percent > 0 && percent < 100;
            },
            cutLink, cutAddress, &cut);
        QVERIFY(cut);
        QCOMPARE(drives.size(), 3);

        QVERIFY(machine.restore(cutLink));
        const QString again = machine.path(QStringLiteral("again"));
        QVERIFY(QDir().mkpath(again));
        const QList<PlantDrive> read = machine.run(PlantRun::Task::Backup, again);
        QCOMPARE(outcomes(read),
                 QStringList({ QStringLiteral("cabinet-2 saved"), QStringLiteral("cabinet-5 saved"),
                               QStringLiteral("hoist saved") }));

        const QString lost
            = cutAddress < 0 ? cutLink : QStringLiteral("%1-%2").arg(cutLink).arg(cutAddress);
        for (const PlantDrive &drive : drives) {
            const QString name = drive.name();
            const PlantDrive *readAgain = driveNamed(read, name);
            QVERIFY(readAgain);
            QString error;
            const std::optional<DriveDescription> after
                = ParameterDocument::load(readAgain->file, &error);
            QVERIFY2(after, qPrintable(error));
            const DownloadPlan plan = planDownload(files.value(name), before.value(name), {});
            QVERIFY(plan.items.size() >= kChangedParameters);
            if (drive.link != cutLink) {
                QVERIFY2(drive.outcome == PlantDrive::Outcome::Written,
                         qPrintable(outcomes(drives).join(QLatin1Char('\n'))));
                QVERIFY2(compareDescriptions(files.value(name), *after).isEqual(),
                         qPrintable(name));
            } else if (name == lost) {
                QVERIFY2(drive.outcome == PlantDrive::Outcome::Failed,
                         qPrintable(outcomes(drives).join(QLatin1Char('\n')) + QLatin1Char('\n')
                                    + drive.details));
                QVERIFY(!drive.reason.isEmpty());
            } else {
                // After the lost drive on its bus: never reached, nothing written.
                QVERIFY2(drive.outcome == PlantDrive::Outcome::Unreachable, qPrintable(name));
                QVERIFY2(compareDescriptions(before.value(name), *after).isEqual(),
                         qPrintable(name));
                continue;
            }
            const DownloadReport report = reportOf(drive.details, plan);
            const QString untrue = untrueLines(plan, report, *after);
            QVERIFY2(untrue.isEmpty(),
                     qPrintable(name + QStringLiteral(":\n") + untrue + QStringLiteral("\n")
                                + drive.details));
            if (name == lost) {
                // Cut part-way: some values went, some did not.
                QVERIFY2(!report.written.isEmpty(), qPrintable(drive.details));
                QVERIFY2(!report.notWritten.isEmpty() || !report.unknown.isEmpty(),
                         qPrintable(drive.details));
            }
        }
    }

private:
    QTemporaryDir m_cache; // the drives' metadata, read once for the whole test
};

QTEST_GUILESS_MAIN(TestPlantCut)
#include "tst_plantcut.moc"
