// A full scan of the simulated drive over a paced link, against the wire limit: the bytes on
// the line x bits per character / baud, taking the busier direction for HSP5 (full duplex)
// and both directions together for DIN66019II (one shared line). DIN66019II also waits for the
// drive's reply latency once per request: its half-duplex limit adds that. A reconnect scan
// takes the metadata from the cache the cold scan before it filled, in a temporary folder of
// its own: the user's cache is never read or written.
#include "bus/LinkFactory.h"
#include "client/ClientTiming.h"
#include "client/DriveClient.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QMap>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <functional>
#include <memory>

using namespace DriveDesk;

namespace {

constexpr int kLatencyUs = 1000;

// Cold: everything from the drive, into a fresh cache folder (MetadataSource::RefreshCache).
// Reconnect: a new client that takes the metadata from the folder of the cold scan before it.
enum class Scan : quint8 { Cold, Reconnect };

struct Case {
    Protocol protocol;
    qint32 baud;
    int inFlight;
    Scan scan = Scan::Cold;
};

// Runs the cases one after another, each on its own client, and quits after the last.
class ScanBenchmark : public QObject
{
public:
    ScanBenchmark(QList<Case> cases, bool breakdown)
        : m_breakdown(breakdown)
        , m_cases(std::move(cases))
    {}

    void next()
    {
        if (m_index >= m_cases.size()) {
            QCoreApplication::quit();
            return;
        }
        const Case c = m_cases[m_index++];
        if (c.scan == Scan::Cold) {
            m_cache = std::make_unique<QTemporaryDir>();
            if (!m_cache->isValid()) {
                std::fprintf(stderr, "cannot make a temporary cache folder: %s\n",
                             qPrintable(m_cache->errorString()));
                QCoreApplication::exit(1);
                return;
            }
        } else if (!m_cache) {
            std::fprintf(stderr, "a reconnect needs a cold scan before it\n");
            QCoreApplication::exit(1);
            return;
        }
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.protocol = c.protocol;
        settings.baudRate = c.baud;
        settings.simulation.baudRate = c.baud;
        settings.simulation.paced = true;
        settings.simulation.replyLatencyUs = kLatencyUs;
        ClientOptions options;
        options.maxInFlight = c.inFlight;

        m_client = std::make_unique<DriveClient>(settings, everyLink(), options);
        m_sent = m_received = m_requests = 0;
        m_answers.clear();
        m_codec = makeCodec(c.protocol);
        m_decoder = m_codec->makeDecoder(Role::Operator);
        connect(m_client.get(), &DriveClient::traffic, this, [this](const TrafficRecord &record) {
            if (record.kind == TrafficRecord::Kind::Sent) {
                m_sent += record.bytes.size();
                ++m_requests;
            }
            else if (record.kind == TrafficRecord::Kind::Received) {
                m_received += record.bytes.size();
                countAnswers(record.bytes);
            }
        });
        connect(m_client.get(), &DriveClient::connectionFailed, this, [](const QString &reason) {
            std::fprintf(stderr, "cannot connect: %s\n", qPrintable(reason));
            QCoreApplication::exit(1);
        });
        connect(m_client.get(), &DriveClient::connected, this,
                [this, c, settings] { startScan(c, settings); });
        m_client->connectToDrive();
    }

private:
    void startScan(const Case &c, const ConnectionSettings &settings)
    {
        auto *watcher = new QFutureWatcher<DriveDescription>(this);
        auto timer = std::make_shared<QElapsedTimer>();
        timer->start();
        connect(watcher, &QFutureWatcher<DriveDescription>::finished, this, [=, this] {
            const double seconds = timer->nsecsElapsed() / 1e9;
            const DriveDescription description = watcher->future().result();
            watcher->deleteLater();
            const double bits = bitsPerCharacter(settings);
            const qint64 lineBytes = c.protocol == Protocol::Hsp5 ? std::max(m_sent, m_received)
                                                                   : m_sent + m_received;
            const double wireSeconds = lineBytes * bits / c.baud;
            const bool cached = c.scan == Scan::Reconnect;
            const QString key = QStringLiteral("%1/%2/%3")
                                    .arg(protocolName(c.protocol))
                                    .arg(c.baud)
                                    .arg(c.inFlight);
            std::printf("%-11s %6d baud  %d in flight  %-9s %4d parameters  %7.2f s  wire limit "
                        "%7.2f s  ratio %.3f  (%lld requests, sent %lld B, received %lld B)\n",
                        qPrintable(protocolName(c.protocol)), c.baud, c.inFlight,
                        cached ? "reconnect" : "cold", description.parameterCount(), seconds,
                        wireSeconds, seconds / wireSeconds, m_requests, m_sent, m_received);
            if (c.protocol != Protocol::Hsp5) {
                const double halfDuplex = wireSeconds + m_requests * kLatencyUs / 1e6;
                std::printf("%-11s %6s       half-duplex limit (wire + requests x latency) %.2f s"
                            "  ratio %.3f\n",
                            "", "", halfDuplex, seconds / halfDuplex);
            }
            if (cached && m_coldSeconds.contains(key)) {
                std::printf("%-11s %6s       reconnect / cold scan: %.3f (goal <= 0.1)\n", "", "",
                            seconds / m_coldSeconds.value(key));
            } else if (!cached) {
                m_coldSeconds.insert(key, seconds);
            }
            if (!cached && m_breakdown)
                printAnswers();
            if (!description.incompleteReason.isEmpty())
                std::printf("  INCOMPLETE: %s\n", qPrintable(description.incompleteReason));
            if (cached != description.metadataFromCache)
                std::printf("  metadata %s the cache, not as asked\n",
                            description.metadataFromCache ? "from" : "not from");
            std::fflush(stdout);
            m_client.reset();
            QTimer::singleShot(0, this, [this] { next(); });
        });
        ScanOptions options;
        // A cold scan fills its own folder, the reconnect after it reads it; never the user's.
        options.metadata = c.scan == Scan::Reconnect ? MetadataSource::Cache
                                                     : MetadataSource::RefreshCache;
        options.cacheDirectory = m_cache->path();
        watcher->setFuture(m_client->scan(options));
    }

    // Where the received bytes go: answers by service, accepted or refused.
    void countAnswers(const QByteArray &bytes)
    {
        m_decoder->feed(bytes);
        while (const std::optional<Decoded> item = m_decoder->next()) {
            QString key = QStringLiteral("decode errors");
            qsizetype size = 0;
            if (const auto *telegram = std::get_if<Telegram>(&*item)) {
                key = QStringLiteral("%1 %2").arg(serviceName(telegram->service),
                                                  telegram->ack == Ack::Ok ? QStringLiteral("ok")
                                                                           : QStringLiteral("refused"));
                size = m_codec->encode(*telegram).size();
            } else {
                size = std::get<DecodeError>(*item).bytes.size();
            }
            Tally &tally = m_answers[key];
            ++tally.count;
            tally.bytes += size;
        }
    }

    void printAnswers() const
    {
        for (auto it = m_answers.cbegin(); it != m_answers.cend(); ++it) {
            std::printf("    %-40s %5d answers %7lld B\n", qPrintable(it.key()), it->count,
                        it->bytes);
        }
    }

    struct Tally {
        int count = 0;
        qint64 bytes = 0;
    };

    bool m_breakdown = false;
    QMap<QString, Tally> m_answers;
    std::unique_ptr<ProtocolCodec> m_codec;
    std::unique_ptr<FrameDecoder> m_decoder;
    QList<Case> m_cases;
    qsizetype m_index = 0;
    std::unique_ptr<DriveClient> m_client;
    qint64 m_sent = 0;
    qint64 m_received = 0;
    qint64 m_requests = 0;
    std::unique_ptr<QTemporaryDir> m_cache; // a fresh one per cold scan
    QMap<QString, double> m_coldSeconds;    // by protocol/baud/in flight
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    // DIN66019II is half duplex: one request at a time whatever the options say.
    QList<Case> cases;
    for (qint32 baud : {38400, 115200}) {
        cases << Case{Protocol::Hsp5, baud, 4}
              << Case{Protocol::Hsp5, baud, 4, Scan::Reconnect}
              << Case{Protocol::Hsp5, baud, 1};
    }
    for (qint32 baud : {38400, 115200}) {
        cases << Case{Protocol::Din66019II, baud, 1}
              << Case{Protocol::Din66019II, baud, 1, Scan::Reconnect};
    }
    // --by-service: where each cold scan's received bytes go.
    ScanBenchmark benchmark(cases, app.arguments().contains(QStringLiteral("--by-service")));
    QTimer::singleShot(0, &benchmark, [&] { benchmark.next(); });
    return app.exec();
}
