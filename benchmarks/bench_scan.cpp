// A full scan of the simulated drive over a paced link, against the wire limit: the bytes on
// the line x bits per character / baud, taking the busier direction for HSP5 (full duplex)
// and both directions together for DIN66019II (one shared line).
#include "client/DriveClient.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QTimer>

#include <cstdio>
#include <functional>
#include <memory>

using namespace DriveDesk;

namespace {

struct Case {
    Protocol protocol;
    qint32 baud;
    int inFlight;
};

// Runs the cases one after another, each on its own client, and quits after the last.
class ScanBenchmark : public QObject
{
public:
    explicit ScanBenchmark(QList<Case> cases)
        : m_cases(std::move(cases))
    {}

    void next()
    {
        if (m_index >= m_cases.size()) {
            QCoreApplication::quit();
            return;
        }
        const Case c = m_cases[m_index++];
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.protocol = c.protocol;
        settings.baudRate = c.baud;
        settings.simulation.baudRate = c.baud;
        settings.simulation.paced = true;
        settings.simulation.replyLatencyUs = 1000;
        ClientOptions options;
        options.maxInFlight = c.inFlight;

        m_client = std::make_unique<DriveClient>(settings, options);
        m_sent = m_received = 0;
        connect(m_client.get(), &DriveClient::traffic, this, [this](const TrafficRecord &record) {
            if (record.kind == TrafficRecord::Kind::Sent)
                m_sent += record.bytes.size();
            else if (record.kind == TrafficRecord::Kind::Received)
                m_received += record.bytes.size();
        });
        connect(m_client.get(), &DriveClient::connectionFailed, this, [](const QString &reason) {
            std::fprintf(stderr, "cannot connect: %s\n", qPrintable(reason));
            QCoreApplication::exit(1);
        });
        connect(m_client.get(), &DriveClient::connected, this, [this, c] { startScan(c); });
        m_client->connectToDrive();
    }

private:
    void startScan(const Case &c)
    {
        auto *watcher = new QFutureWatcher<DriveDescription>(this);
        auto timer = std::make_shared<QElapsedTimer>();
        timer->start();
        connect(watcher, &QFutureWatcher<DriveDescription>::finished, this, [=, this] {
            const double seconds = timer->nsecsElapsed() / 1e9;
            const DriveDescription description = watcher->future().result();
            watcher->deleteLater();
            const auto codec = makeCodec(c.protocol);
            const double bits = codec->bitsPerCharacter();
            const qint64 lineBytes = c.protocol == Protocol::Hsp5 ? std::max(m_sent, m_received)
                                                                   : m_sent + m_received;
            const double wireSeconds = lineBytes * bits / c.baud;
            std::printf("%-11s %6d baud  %d in flight  %4d parameters  %7.2f s  wire limit %7.2f s"
                        "  ratio %.2f  (sent %lld B, received %lld B)%s\n",
                        qPrintable(protocolName(c.protocol)), c.baud, c.inFlight,
                        description.parameterCount(), seconds, wireSeconds,
                        seconds / wireSeconds, m_sent, m_received,
                        description.incompleteReason.isEmpty()
                            ? ""
                            : qPrintable(QStringLiteral("  INCOMPLETE: ")
                                         + description.incompleteReason));
            std::fflush(stdout);
            m_client.reset();
            QTimer::singleShot(0, this, [this] { next(); });
        });
        watcher->setFuture(m_client->scan());
    }

    QList<Case> m_cases;
    qsizetype m_index = 0;
    std::unique_ptr<DriveClient> m_client;
    qint64 m_sent = 0;
    qint64 m_received = 0;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QList<Case> cases;
    for (qint32 baud : {38400, 115200}) {
        cases << Case{Protocol::Hsp5, baud, 1} << Case{Protocol::Hsp5, baud, 4}
              << Case{Protocol::Din66019II, baud, 1};
    }
    ScanBenchmark benchmark(cases);
    QTimer::singleShot(0, &benchmark, [&] { benchmark.next(); });
    return app.exec();
}
