// Backing a drive up and downloading a file back, over a paced link: what a user waits for.
// Per protocol and baud rate, on the simulated F5 whose metadata a first (cold) scan put into a
// temporary cache: the upload (every value of the parameter list), then a download of that file
// with kChanged values changed, split into reading the drive afresh and writing with read-back.
// The user's cache is never read or written. Each download's write runs twice, on a fresh
// drive: without the journal and with one (a temporary file), the entries begun before the
// write and completed as the values come back; `bench_transfer [ROUNDS]` repeats it all and
// prints each case's fastest, median and slowest write and the journal's share of the median;
// `bench_transfer ROUNDS PROTOCOL:BAUD` runs that line alone.
#include "bus/LinkFactory.h"
#include "client/ClientTiming.h"
#include "client/DriveClient.h"
#include "journal/Journal.h"
#include "parameters/ParameterList.h"
#include "session/DownloadRun.h"
#include "session/EditJournal.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QMap>
#include <QStringList>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>

using namespace DriveDesk;

namespace {

constexpr int kLatencyUs = 1000;
constexpr int kChanged = 40; // values the download writes (op and dr sets)

struct Case {
    Protocol protocol;
    qint32 baud;
    bool journaled = false;
};

struct Traffic {
    qint64 requests = 0;
    qint64 sent = 0;
    qint64 received = 0;
};

// The file to download: the upload with kChanged set values of op and dr one step away.
DriveDescription changed(DriveDescription file)
{
    int left = kChanged;
    for (GroupDescription &group : file.groups) {
        if (group.id != QLatin1String("op") && group.id != QLatin1String("dr"))
            continue;
        for (ParameterDescription &p : group.parameters) {
            if (!p.isSetProgrammable() || !ParameterList::isWrittenByDownload(p))
                continue;
            for (int set = 0; set < kParameterSets && left > 0; set += 2, --left) {
                std::optional<qint32> &value = p.values[std::size_t(set)];
                if (value)
                    value = *value > p.minimum ? *value - 1 : *value + 1;
            }
        }
    }
    return file;
}

class TransferBenchmark : public QObject
{
public:
    TransferBenchmark(QList<Case> cases, Journal *journal)
        : m_cases(std::move(cases))
        , m_journal(journal)
    {}

    // Each case's write times: fastest, median, slowest, and the journal's share.
    void summarize() const
    {
        std::printf("\nwrite with read-back, %lld round(s): fastest / median / slowest\n",
                    qlonglong(m_writes.isEmpty() ? 0 : m_writes.first().size()));
        for (auto it = m_writes.begin(); it != m_writes.end(); ++it) {
            QList<double> times = it.value();
            std::sort(times.begin(), times.end());
            std::printf("  %-32s %6.1f / %6.1f / %6.1f ms", qPrintable(it.key()),
                        times.first() * 1e3, median(times) * 1e3, times.last() * 1e3);
            if (it.key().endsWith(QLatin1String("journal"))) {
                const QString without = it.key().chopped(int(std::strlen(" journal")));
                QList<double> plain = m_writes.value(without);
                std::sort(plain.begin(), plain.end());
                if (!plain.isEmpty())
                    std::printf("  journal %+.1f %%", (median(times) / median(plain) - 1) * 100);
            }
            std::printf("\n");
        }
    }

    void next()
    {
        if (m_index >= m_cases.size())
            return QCoreApplication::quit();
        m_case = m_cases[m_index++];
        m_cache = std::make_unique<QTemporaryDir>();
        m_settings = ConnectionSettings{};
        m_settings.kind = ConnectionSettings::Kind::Simulated;
        m_settings.protocol = m_case.protocol;
        m_settings.baudRate = m_case.baud;
        m_settings.simulation.baudRate = m_case.baud;
        m_settings.simulation.paced = true;
        m_settings.simulation.replyLatencyUs = kLatencyUs;
        m_client = std::make_unique<DriveClient>(m_settings, everyLink());
        connect(m_client.get(), &DriveClient::traffic, this, [this](const TrafficRecord &record) {
            if (record.kind == TrafficRecord::Kind::Sent) {
                m_traffic.sent += record.bytes.size();
                ++m_traffic.requests;
            } else if (record.kind == TrafficRecord::Kind::Received) {
                m_traffic.received += record.bytes.size();
            }
            if (m_writing && m_telegrams) {
                const QChar way = record.kind == TrafficRecord::Kind::Sent       ? u'>'
                                : record.kind == TrafficRecord::Kind::Received ? u'<'
                                                                               : u'!';
                m_log << QStringLiteral("%1 ms  %2 %3  %4")
                             .arg(m_timer.nsecsElapsed() / 1e6, 7, 'f', 2)
                             .arg(way)
                             .arg(record.bytes.size(), 2)
                             .arg(record.meaning);
            }
        });
        connect(m_client.get(), &DriveClient::connectionFailed, this, [](const QString &reason) {
            std::fprintf(stderr, "cannot connect: %s\n", qPrintable(reason));
            QCoreApplication::exit(1);
        });
        connect(m_client.get(), &DriveClient::connected, this, [this] {
            scan(MetadataSource::RefreshCache, false, [this](const DriveDescription &) {
                m_timer.start();
                m_traffic = {};
                scan(MetadataSource::Cache, true, [this](const DriveDescription &file) {
                    print("upload", file.parameterCount());
                    download(changed(file));
                });
            });
        });
        m_client->connectToDrive();
    }

private:
    template<typename Next>
    void scan(MetadataSource metadata, bool parameterList, Next next)
    {
        auto *watcher = new QFutureWatcher<DriveDescription>(this);
        connect(watcher, &QFutureWatcher<DriveDescription>::finished, this, [watcher, next] {
            const DriveDescription description = watcher->future().result();
            watcher->deleteLater();
            if (!description.incompleteReason.isEmpty())
                std::printf("  INCOMPLETE: %s\n", qPrintable(description.incompleteReason));
            next(description);
        });
        ScanOptions options;
        options.metadata = metadata;
        options.cacheDirectory = m_cache->path();
        options.parameterList = parameterList;
        watcher->setFuture(m_client->scan(options));
    }

    static double median(const QList<double> &sorted)
    {
        const qsizetype n = sorted.size();
        return n % 2 ? sorted.at(n / 2) : (sorted.at(n / 2 - 1) + sorted.at(n / 2)) / 2;
    }

    QString caseName() const
    {
        return QStringLiteral("%1 %2%3")
            .arg(protocolName(m_case.protocol))
            .arg(m_case.baud)
            .arg(m_case.journaled ? QStringLiteral(" journal") : QString());
    }

    void download(const DriveDescription &file)
    {
        auto *run = new DownloadRun(m_client.get(), m_case.protocol, file, this);
        if (m_case.journaled) {
            m_entries = std::make_unique<EditJournal>(m_journal, JournalDrive {},
                                                      QStringLiteral("download of bench.json"));
            run->setJournal(m_entries.get());
        }
        m_timer.start();
        m_traffic = {};
        connect(run, &DownloadRun::planned, this, [this, run](const DownloadPlan &plan) {
            print("download: read", run->drive().parameterCount());
            m_timer.start();
            m_traffic = {};
            m_values = plan.valueCount();
            m_writing = true;
            m_log.clear();
            run->write();
        });
        connect(run, &DownloadRun::failed, this, [](const QString &reason) {
            std::fprintf(stderr, "download failed: %s\n", qPrintable(reason));
            QCoreApplication::exit(1);
        });
        connect(run, &DownloadRun::finished, this, [this, run](const DownloadReport &report) {
            m_writes[caseName()] << m_timer.nsecsElapsed() / 1e9;
            print(m_case.journaled ? "download: write+j" : "download: write", m_values);
            m_writing = false;
            for (const QString &line : std::as_const(m_log))
                std::printf("    %s\n", qPrintable(line));
            if (!report.isComplete())
                std::printf("  INCOMPLETE:\n%s", qPrintable(report.text()));
            run->deleteLater();
            m_client.reset();
            QTimer::singleShot(0, this, [this] { next(); });
        });
        ScanOptions reading;
        reading.metadata = MetadataSource::Cache;
        reading.cacheDirectory = m_cache->path();
        run->start(reading);
    }

    void print(const char *what, int count)
    {
        const double seconds = m_timer.nsecsElapsed() / 1e9;
        const double bits = bitsPerCharacter(m_settings);
        const qint64 lineBytes = m_case.protocol == Protocol::Hsp5
            ? std::max(m_traffic.sent, m_traffic.received)
            : m_traffic.sent + m_traffic.received;
        double limit = lineBytes * bits / m_case.baud;
        if (m_case.protocol != Protocol::Hsp5)
            limit += m_traffic.requests * kLatencyUs / 1e6; // one request at a time
        std::printf("%-11s %6d baud  %-16s %5d  %7.2f s  limit %6.2f s  ratio %.3f  "
                    "(%lld requests, sent %lld B, received %lld B)\n",
                    qPrintable(protocolName(m_case.protocol)), m_case.baud, what, count, seconds,
                    limit, seconds / limit, m_traffic.requests, m_traffic.sent,
                    m_traffic.received);
        std::fflush(stdout);
    }

    QList<Case> m_cases;
    Journal *const m_journal;
    std::unique_ptr<EditJournal> m_entries; // the journaled download's
    QMap<QString, QList<double>> m_writes; // per case: each round's write, in seconds
    qsizetype m_index = 0;
    Case m_case{};
    ConnectionSettings m_settings;
    std::unique_ptr<QTemporaryDir> m_cache;
    std::unique_ptr<DriveClient> m_client;
    QElapsedTimer m_timer;
    Traffic m_traffic;
    int m_values = 0;
    // BENCH_TRANSFER_TELEGRAMS=1: each telegram of the write, as the client reported it, with
    // the time it reached this thread.
    const bool m_telegrams = qEnvironmentVariableIsSet("BENCH_TRANSFER_TELEGRAMS");
    bool m_writing = false;
    QStringList m_log;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    std::printf("count: parameters read, or values written\n");
    const int rounds = argc > 1 ? std::max(1, QString::fromLocal8Bit(argv[1]).toInt()) : 1;
    QTemporaryDir folder;
    Journal journal(folder.filePath(QStringLiteral("journal.sqlite")));
    if (!journal.open()) {
        std::fprintf(stderr, "%s\n", qPrintable(journal.errorString()));
        return 1;
    }
    QList<Case> lines { Case { Protocol::Hsp5, 38400 }, Case { Protocol::Hsp5, 115200 },
                        Case { Protocol::Din66019II, 38400 } };
    if (argc > 2) {
        // `bench_transfer ROUNDS hsp5:115200`: that line alone, for more rounds in less time.
        const QStringList line = QString::fromLocal8Bit(argv[2]).split(u':');
        const std::optional<Protocol> protocol = protocolFromName(line.value(0));
        const qint32 baud = line.value(1).toInt();
        if (!protocol || baud <= 0) {
            std::fprintf(stderr, "usage: bench_transfer [ROUNDS [PROTOCOL:BAUD]]\n");
            return 2;
        }
        lines = { Case { *protocol, baud } };
    }
    QList<Case> cases;
    for (int round = 0; round < rounds; ++round) {
        for (const Case &line : std::as_const(lines)) {
            // Alternating, so that a change in the machine's load falls on both alike.
            const bool journalFirst = round % 2 == 1;
            cases << Case { line.protocol, line.baud, journalFirst }
                  << Case { line.protocol, line.baud, !journalFirst };
        }
    }
    TransferBenchmark benchmark(cases, &journal);
    QTimer::singleShot(0, &benchmark, [&benchmark] { benchmark.next(); });
    const int code = app.exec();
    benchmark.summarize();
    return code;
}
