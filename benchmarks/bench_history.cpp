// A plant's backups as revisions of a git repository (core/history), against simulated drives:
//  1. a plant of four DIN66019II links of three drives each (paced lines at kBaud, kLatencyUs
//     reply latency, the kind's metadata cached) backed up, then the backup committed as
//     `plant backup --commit` does, one setting of one drive changed in between so that every
//     run makes a commit (goal: backup and commit at most 1.1 x the backup alone);
//  2. a repository of kRevisions revisions of the 12 drives' files, one setting of one drive
//     changed in each (made with git fast-import, not measured), its history read as
//     `plant history` reads it: all of it, one drive, one parameter (goal: under 2 s).
// Optional argument: how many runs.
#include "bus/LinkFactory.h"
#include "history/BackupCommit.h"
#include "history/PlantHistory.h"
#include "parameters/ParameterComparison.h"
#include "parameters/ParameterDocument.h"
#include "plant/PlantRun.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>

using namespace DriveDesk;

namespace {

constexpr qint32 kBaud = 38400;
constexpr int kLatencyUs = 1000;
constexpr int kLinks = 4;
constexpr int kRevisions = 1000;
const QList<int> kAddresses{2, 5, 9};

QString loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("unknown");
    return QString::fromLatin1(file.readAll()).section(QLatin1Char(' '), 0, 2);
}

Plant simulatedPlant()
{
    Plant plant{QStringLiteral("Line 3"), {}};
    for (int i = 0; i < kLinks; ++i) {
        PlantLink link;
        link.name = QStringLiteral("cabinet%1").arg(i + 1);
        link.connect = QStringLiteral("sim");
        link.protocol = Protocol::Din66019II;
        link.baudRate = kBaud;
        link.addresses = kAddresses;
        plant.links << link;
    }
    return plant;
}

LinkMaker pacedLinks(bool paced)
{
    return [paced](ConnectionSettings settings) {
        settings.simulation.paced = paced;
        settings.simulation.replyLatencyUs = kLatencyUs;
        return makeLink(settings);
    };
}

// The first setting of a description that holds a value, one step up (at its maximum, back to
// its minimum): a user's edit, never the value it was.
void changeASetting(DriveDescription &drive)
{
    for (GroupDescription &group : drive.groups) {
        for (ParameterDescription &parameter : group.parameters) {
            if (countsAsSetting(parameter) && parameter.values[0]
                && parameter.minimum < parameter.maximum) {
                const qint64 span = qint64(parameter.maximum) - parameter.minimum;
                parameter.values[0] = qint32(parameter.minimum
                                             + (qint64(*parameter.values[0]) - parameter.minimum + 1)
                                                   % (span + 1));
                return;
            }
        }
    }
}

// User and system time of the whole process, every thread.
double processorSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec)
        + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

QString range(const QList<double> &values, int decimals)
{
    return QStringLiteral("%1 .. %2")
        .arg(*std::min_element(values.cbegin(), values.cend()), 0, 'f', decimals)
        .arg(*std::max_element(values.cbegin(), values.cend()), 0, 'f', decimals);
}

class HistoryBenchmark : public QObject
{
public:
    explicit HistoryBenchmark(int runs) : m_runs(runs)
    {
        m_reading.metadata = MetadataSource::Cache;
        m_reading.cacheDirectory = m_cache.path();
    }

    void start()
    {
        std::printf("%d links x %lld drives, DIN66019II %d baud, reply latency %d us, paced; "
                    "metadata cached; %d run(s)\n",
                    kLinks, qlonglong(kAddresses.size()), kBaud, kLatencyUs, m_runs);
        ScanOptions warm = m_reading;
        warm.metadata = MetadataSource::RefreshCache;
        Plant plant{QStringLiteral("warm"), {simulatedPlant().links.first()}};
        plant.links.first().addresses = {1};
        backup(plant, warm, false, m_warm.path(), [this](double) { nextRun(); });
    }

private:
    void nextRun()
    {
        if (m_run++ == m_runs)
            return history();
        std::printf("run %d, load average %s\n", m_run, qPrintable(loadAverage()));
        backup(simulatedPlant(), m_reading, true, m_folder.path(), [this](double seconds) {
            commit(seconds);
        });
    }

    void commit(double backupSeconds)
    {
        // Not measured: the edit a user would have made on the drive between two backups.
        const QString edited = QDir(m_folder.path()).filePath(QStringLiteral("cabinet1-5.json"));
        auto drive = ParameterDocument::load(edited);
        if (m_run > 1 && drive) {
            changeASetting(*drive);
            ParameterDocument::save(edited, *drive);
        }
        QElapsedTimer timer;
        // Where the commit's time goes: reading the files is part of it.
        QMap<QString, QByteArray> files;
        for (const QString &name : QDir(m_folder.path()).entryList({QStringLiteral("*.json")})) {
            QFile file(QDir(m_folder.path()).filePath(name));
            if (file.open(QIODevice::ReadOnly))
                files.insert(name, file.readAll());
        }
        timer.start();
        const DriveFiles read = readDriveFiles(files);
        const double reading = timer.nsecsElapsed() / 1e9;
        std::printf("  the %lld files read (%lld bytes each): %.3f s\n", qlonglong(read.drives.size()),
                    qlonglong(files.isEmpty() ? 0 : files.first().size()), reading);
        timer.start();
        QString error;
        auto repository = BackupRepository::open(m_folder.path(), true, &error);
        BackupCommit backup;
        backup.plantName = QStringLiteral("Line 3");
        for (const QString &name : QDir(m_folder.path()).entryList({QStringLiteral("*.json")}))
            backup.saved << name;
        const auto outcome = repository ? backup.commit(*repository, &error) : std::nullopt;
        const double seconds = timer.nsecsElapsed() / 1e9;
        if (!outcome)
            std::printf("  COMMIT FAILED: %s\n", qPrintable(error));
        std::printf("  backup of 12 drives %.2f s, commit %.3f s (%s, %lld drives changed): "
                    "%.3f x (goal 1.1)\n",
                    backupSeconds, seconds, outcome && outcome->committed ? "committed" : "none",
                    qlonglong(outcome ? outcome->changes.size() : 0),
                    (backupSeconds + seconds) / backupSeconds);
        m_commitRatios << (backupSeconds + seconds) / backupSeconds;
        m_commitSeconds << seconds;
        nextRun();
    }

    void history()
    {
        QString error;
        QElapsedTimer timer;
        timer.start();
        if (!generate(&error)) {
            std::printf("GENERATING FAILED: %s\n", qPrintable(error));
            return QCoreApplication::exit(1);
        }
        std::printf("%d revisions of 12 drives generated in %.1f s (not measured)\n", kRevisions,
                    timer.nsecsElapsed() / 1e9);
        auto repository = BackupRepository::open(m_generated.path(), false, &error);
        for (int run = 1; run <= m_runs; ++run) {
            for (const HistoryFilter &filter :
                 {HistoryFilter{}, HistoryFilter{QStringLiteral("cabinet2-5"), {}},
                  HistoryFilter{{}, m_parameter}}) {
                timer.start();
                const double processorBefore = processorSeconds();
                const auto revisions = readPlantHistory(*repository, filter, &error);
                const double seconds = timer.nsecsElapsed() / 1e9;
                const double processor = processorSeconds() - processorBefore;
                qsizetype changes = 0;
                for (const PlantRevision &revision : revisions.value_or(QList<PlantRevision>{}))
                    changes += revision.changes.size();
                const QString what = filter.isEmpty() ? QStringLiteral("all")
                                     : filter.drive.isEmpty() ? QStringLiteral("--parameter %1").arg(m_parameter)
                                                              : QStringLiteral("--drive %1").arg(filter.drive);
                std::printf("  run %d, history %s: %lld revisions, %lld drive changes, %.3f s "
                            "(goal 2 s; processor %.2f s, git's not counted), load average %s\n",
                            run, qPrintable(what), qlonglong(revisions ? revisions->size() : -1),
                            qlonglong(changes), seconds, processor, qPrintable(loadAverage()));
                if (filter.isEmpty())
                    m_historySeconds << seconds;
            }
        }
        std::printf("backup and commit / backup: %s (goal <= 1.1); commit alone %s s\n",
                    qPrintable(range(m_commitRatios, 3)), qPrintable(range(m_commitSeconds, 3)));
        std::printf("history of %d revisions: %s s (goal < 2 s)\n", kRevisions,
                    qPrintable(range(m_historySeconds, 3)));
        QCoreApplication::quit();
    }

    // kRevisions commits through git fast-import: the 12 files the backups saved, then one
    // setting of one drive (drive by drive in turn) changed in each.
    bool generate(QString *error)
    {
        auto repository = BackupRepository::open(m_generated.path(), true, error);
        if (!repository)
            return false;
        QMap<QString, DriveDescription> drives;
        for (const QString &name : QDir(m_folder.path()).entryList({QStringLiteral("*.json")})) {
            auto drive = ParameterDocument::load(QDir(m_folder.path()).filePath(name), error);
            if (!drive)
                return false;
            drives.insert(name, *drive);
        }
        const QStringList names = drives.keys();
        QByteArray stream;
        const auto data = [&stream](const QByteArray &bytes) {
            stream += "data " + QByteArray::number(bytes.size()) + '\n' + bytes + '\n';
        };
        for (int revision = 0; revision < kRevisions; ++revision) {
            QStringList changed = revision == 0 ? names : QStringList{names[revision % names.size()]};
            for (const QString &name : std::as_const(changed)) {
                if (revision > 0)
                    changeASetting(drives[name]);
            }
            stream += "commit refs/heads/history\n";
            const QByteArray when = QByteArray::number(1764000000 + revision * 600) + " +0000\n";
            stream += "author Bench <bench@example.org> " + when;
            stream += "committer Bench <bench@example.org> " + when;
            data(QByteArrayLiteral("Line 3: backup"));
            for (const QString &name : std::as_const(changed)) {
                stream += "M 100644 inline " + name.toUtf8() + '\n';
                data(ParameterDocument::toJson(drives[name]));
            }
        }
        const Git::Result imported = repository->git().run({QStringLiteral("fast-import"),
                                                            QStringLiteral("--quiet")},
                                                           stream);
        if (!imported.ok) {
            *error = imported.error;
            return false;
        }
        const Git::Result head = repository->git().run({QStringLiteral("symbolic-ref"),
                                                        QStringLiteral("HEAD"),
                                                        QStringLiteral("refs/heads/history")});
        if (!head.ok) {
            *error = head.error;
            return false;
        }
        // The parameter the edits change, as the history names it.
        DriveDescription before = drives.first();
        DriveDescription after = before;
        changeASetting(after);
        const auto differences = compareDescriptions(before, after).differences;
        m_parameter = differences.isEmpty() ? QString() : differences.first().id;
        return true;
    }

    void backup(const Plant &plant, const ScanOptions &reading, bool paced, const QString &folder,
                std::function<void(double)> done)
    {
        auto *run = new PlantRun(plant, PlantRun::Task::Backup, folder, pacedLinks(paced), this);
        run->setReading(reading);
        auto timer = std::make_shared<QElapsedTimer>();
        connect(run, &PlantRun::finished, this, [run, timer, done] {
            const double seconds = timer->nsecsElapsed() / 1e9;
            for (const PlantDrive &drive : run->drives()) {
                if (drive.outcome != PlantDrive::Outcome::Saved)
                    std::printf("  NOT SAVED: %s: %s\n", qPrintable(drive.name()),
                                qPrintable(drive.reason));
            }
            run->deleteLater();
            done(seconds);
        });
        timer->start();
        run->start();
    }

    const int m_runs;
    int m_run = 0;
    QTemporaryDir m_cache;
    QTemporaryDir m_warm;
    QTemporaryDir m_folder;
    QTemporaryDir m_generated;
    ScanOptions m_reading;
    QString m_parameter;
    QList<double> m_commitRatios;
    QList<double> m_commitSeconds;
    QList<double> m_historySeconds;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    // git's configuration of whoever runs it plays no part: an author of the benchmark's own.
    QTemporaryDir home;
    qputenv("HOME", home.path().toUtf8());
    qputenv("XDG_CONFIG_HOME", home.path().toUtf8());
    qputenv("GIT_CONFIG_NOSYSTEM", "1");
    qputenv("GIT_AUTHOR_NAME", "Bench");
    qputenv("GIT_AUTHOR_EMAIL", "bench@example.org");
    qputenv("GIT_COMMITTER_NAME", "Bench");
    qputenv("GIT_COMMITTER_EMAIL", "bench@example.org");
    const int runs = argc > 1 ? std::max(1, QByteArray(argv[1]).toInt()) : 1;
    HistoryBenchmark benchmark(runs);
    QTimer::singleShot(0, &benchmark, [&benchmark] { benchmark.start(); });
    return app.exec();
}
