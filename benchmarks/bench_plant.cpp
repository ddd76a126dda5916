// A plant backed up over paced simulated lines (DIN66019II, kBaud, kLatencyUs reply latency),
// the drives' kind already in a temporary metadata cache (the user's is never read or written):
//  1. four links of three drives each, first each link alone, then all four at once
//     (goal: together at most 1.25 x the slowest link alone);
//  2. one bus of N drives: N single uploads one after another (connect, read, save, as
//     `drivedesk-cli upload` does), then a plant backup of the same N drives
//     (goal: at most 1.1 x the N single uploads).
// Every figure comes from this one run. Optional argument: how many times each is measured.
#include "bus/LinkFactory.h"
#include "plant/PlantRun.h"
#include "session/UploadRun.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>

using namespace DriveDesk;

namespace {

constexpr qint32 kBaud = 38400;
constexpr int kLatencyUs = 1000;
constexpr int kLinks = 4;
const QList<int> kBusAddresses{2, 5, 9};
const QList<int> kLongBus{1, 2, 3, 4, 5, 6};

PlantLink simulatedLink(const QString &name, const QList<int> &addresses)
{
    PlantLink link;
    link.name = name;
    link.connect = QStringLiteral("sim");
    link.protocol = Protocol::Din66019II;
    link.baudRate = kBaud;
    link.addresses = addresses;
    return link;
}

// Each connection a line of its own at the baud rate, as a plant's gateways are.
LinkMaker pacedLinks(bool paced)
{
    return [paced](ConnectionSettings settings) {
        settings.simulation.paced = paced;
        settings.simulation.replyLatencyUs = kLatencyUs;
        return makeLink(settings);
    };
}

class PlantBenchmark : public QObject
{
public:
    explicit PlantBenchmark(int runs)
        : m_runs(runs)
    {
        m_reading.metadata = MetadataSource::Cache;
        m_reading.cacheDirectory = m_cache.path();
    }

    void start()
    {
        std::printf("DIN66019II %d baud, reply latency %d us, each connection a paced line; "
                    "metadata cached; %d run(s)\n",
                    kBaud, kLatencyUs, m_runs);
        // The kind's metadata into the cache, unpaced: not measured.
        ScanOptions warm = m_reading;
        warm.metadata = MetadataSource::RefreshCache;
        Plant plant{QStringLiteral("warm"), {simulatedLink(QStringLiteral("warm"), {1})}};
        runPlant(plant, warm, false, [this](double, const QList<PlantDrive> &) { nextRun(); });
    }

private:
    void nextRun()
    {
        if (m_run++ == m_runs)
            return summarise();
        std::printf("run %d, load average %s\n", m_run, qPrintable(loadAverage()));
        m_alone.clear();
        linkAlone(0);
    }

    // 1. Each link alone, then all four together.
    void linkAlone(int index)
    {
        if (index == kLinks)
            return allLinks();
        Plant plant{QStringLiteral("alone"), {link(index)}};
        runPlant(plant, m_reading, true, [this, index](double seconds, const QList<PlantDrive> &) {
            std::printf("  link %d alone, %lld drives: %.2f s\n", index + 1,
                        qlonglong(kBusAddresses.size()), seconds);
            m_alone << seconds;
            linkAlone(index + 1);
        });
    }

    void allLinks()
    {
        Plant plant{QStringLiteral("four"), {}};
        for (int i = 0; i < kLinks; ++i)
            plant.links << link(i);
        runPlant(plant, m_reading, true, [this](double seconds, const QList<PlantDrive> &) {
            const double slowest = *std::max_element(m_alone.cbegin(), m_alone.cend());
            std::printf("  %d links together: %.2f s, slowest alone %.2f s: %.3f x (goal 1.25); "
                        "load average %s\n",
                        kLinks, seconds, slowest, seconds / slowest, qPrintable(loadAverage()));
            m_fourRatios << seconds / slowest;
            m_singles = 0;
            singleUpload(0);
        });
    }

    // 2. One bus: the drives one by one as single uploads, then as a plant backup.
    void singleUpload(int index)
    {
        if (index == kLongBus.size())
            return oneBus();
        const PlantLink bus = simulatedLink(QStringLiteral("single"), kLongBus);
        auto *client = new DriveClient(bus.settings(kLongBus.at(index)), pacedLinks(true), {}, this);
        m_timer.start();
        connect(client, &DriveClient::connected, this, [this, client, index] {
            auto *upload = new UploadRun(client, this);
            connect(upload, &UploadRun::finished, this,
                    [this, client, upload, index](const UploadResult &result) {
                        QString error;
                        if (!saveUpload(QDir(m_files.path()).filePath(QStringLiteral("single.json")),
                                        result, &error)) {
                            std::printf("  INCOMPLETE: %s\n", qPrintable(error));
                        }
                        upload->deleteLater();
                        client->disconnectFromDrive();
                        client->deleteLater();
                        const double seconds = m_timer.nsecsElapsed() / 1e9;
                        std::printf("  single upload, drive %d: %.2f s\n", kLongBus.at(index),
                                    seconds);
                        m_singles += seconds;
                        singleUpload(index + 1);
                    });
            upload->start(m_reading);
        });
        connect(client, &DriveClient::connectionFailed, this, [](const QString &reason) {
            std::fprintf(stderr, "cannot connect: %s\n", qPrintable(reason));
            QCoreApplication::exit(1);
        });
        client->connectToDrive();
    }

    void oneBus()
    {
        Plant plant{QStringLiteral("bus"), {simulatedLink(QStringLiteral("bus"), kLongBus)}};
        runPlant(plant, m_reading, true, [this](double seconds, const QList<PlantDrive> &) {
            std::printf("  one bus, %lld drives: plant backup %.2f s, %lld single uploads %.2f s: "
                        "%.3f x (goal 1.1)\n",
                        qlonglong(kLongBus.size()), seconds, qlonglong(kLongBus.size()), m_singles,
                        seconds / m_singles);
            m_busRatios << seconds / m_singles;
            nextRun();
        });
    }

    void summarise()
    {
        const auto range = [](const QList<double> &ratios) {
            return QStringLiteral("%1 .. %2")
                .arg(*std::min_element(ratios.cbegin(), ratios.cend()), 0, 'f', 3)
                .arg(*std::max_element(ratios.cbegin(), ratios.cend()), 0, 'f', 3);
        };
        std::printf("four links together / slowest alone: %s (goal <= 1.25)\n",
                    qPrintable(range(m_fourRatios)));
        std::printf("plant backup of one bus / single uploads: %s (goal <= 1.1)\n",
                    qPrintable(range(m_busRatios)));
        QCoreApplication::quit();
    }

    PlantLink link(int index) const
    {
        return simulatedLink(QStringLiteral("link%1").arg(index + 1), kBusAddresses);
    }

    void runPlant(const Plant &plant, const ScanOptions &reading, bool paced,
                  std::function<void(double, const QList<PlantDrive> &)> done)
    {
        auto *run = new PlantRun(plant, PlantRun::Task::Backup, m_files.path(), pacedLinks(paced),
                                 this);
        run->setReading(reading);
        auto timer = std::make_shared<QElapsedTimer>();
        auto finished = std::make_shared<QStringList>(); // when each drive was done
        connect(run, &PlantRun::driveDone, this, [timer, finished](const PlantDrive &drive) {
            *finished << QStringLiteral("%1 %2").arg(drive.name()).arg(timer->nsecsElapsed() / 1e9,
                                                                        0, 'f', 2);
        });
        const double cpuBefore = processorSeconds();
        connect(run, &PlantRun::finished, this, [this, run, timer, finished, cpuBefore, done] {
            const double seconds = timer->nsecsElapsed() / 1e9;
            const QList<PlantDrive> drives = run->drives();
            for (const PlantDrive &drive : drives) {
                if (drive.outcome != PlantDrive::Outcome::Saved)
                    std::printf("  NOT SAVED: %s: %s\n", qPrintable(drive.name()),
                                qPrintable(drive.reason));
            }
            if (m_verbose) {
                std::printf("    done at: %s; processor %.2f s\n",
                            qPrintable(finished->join(QStringLiteral(", "))),
                            processorSeconds() - cpuBefore);
            }
            run->deleteLater();
            done(seconds, drives);
        });
        timer->start();
        run->start();
    }

    // The machine's load over the last minute, five and fifteen minutes.
    static QString loadAverage()
    {
        QFile file(QStringLiteral("/proc/loadavg"));
        if (!file.open(QIODevice::ReadOnly))
            return QStringLiteral("unknown");
        return QString::fromLatin1(file.readAll()).section(QLatin1Char(' '), 0, 2);
    }

    // User and system time of the whole process, every thread.
    static double processorSeconds()
    {
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec)
            + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
    }

    const int m_runs;
    const bool m_verbose = qEnvironmentVariableIsSet("BENCH_PLANT_VERBOSE");
    int m_run = 0;
    QTemporaryDir m_cache;
    QTemporaryDir m_files;
    ScanOptions m_reading;
    QElapsedTimer m_timer;
    QList<double> m_alone;
    QList<double> m_fourRatios;
    QList<double> m_busRatios;
    double m_singles = 0;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const int runs = argc > 1 ? std::max(1, QByteArray(argv[1]).toInt()) : 1;
    PlantBenchmark benchmark(runs);
    QTimer::singleShot(0, &benchmark, [&benchmark] { benchmark.start(); });
    return app.exec();
}
