// A cold scan on a quiet machine and on one with a core kept busy, against a client that sends
// one request at a time and blocks reading its answer. Both talk to the same paced drivedesk-sim
// over a pseudo-terminal, as a program on a real serial port would; the blocking client sends
// exactly the requests DriveDesk's scan sent, so the two do the same work and differ only in how
// they wait. Rounds alternate quiet and loaded, so that a drift of the machine touches both.
//
//   bench_scan_loaded [ROUNDS] [--baud N] [--protocol hsp5|din66019ii]
#include "bus/LinkFactory.h"
#include "client/DriveClient.h"
#include "protocol/Codec.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QProcess>
#include <QSerialPort>
#include <QTemporaryDir>
#include <QThread>

#include <algorithm>

#include <sys/resource.h>
#include <cstdio>

using namespace DriveDesk;

namespace {

constexpr int kLatencyUs = 1000;
constexpr int kAnswerTimeoutMs = 2000;

// Processor time of this program so far (every thread), in seconds: what a client costs the
// machine beside the time it takes.
double processorSeconds()
{
    rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval &t) { return double(t.tv_sec) + t.tv_usec / 1e6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The one event loop of this program, run from main's straight-line flow until `done`.
template<typename Done>
void runUntil(Done done)
{
    // Without a time limit: processEvents(flags, maxTime) ignores WaitForMoreEvents and spins,
    // and a benchmark that burns a core measures itself on a loaded machine.
    QEventLoop loop;
    while (!done())
        loop.processEvents(QEventLoop::WaitForMoreEvents);
}

// drivedesk-sim serving one paced drive over a pseudo-terminal linked in a folder of its own.
class SimulatedDrive
{
public:
    SimulatedDrive(Protocol protocol, qint32 baud)
    {
        m_link = m_folder.filePath(QStringLiteral("drive"));
        m_process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_process.start(QStringLiteral(DRIVEDESK_SIM),
                        {QStringLiteral("--pty"), m_link, QStringLiteral("--protocol"),
                         protocolName(protocol), QStringLiteral("--pace"),
                         QStringLiteral("--baud"), QString::number(baud),
                         QStringLiteral("--latency-us"), QString::number(kLatencyUs)});
        QElapsedTimer waited;
        waited.start();
        while (!QFileInfo::exists(m_link) && waited.elapsed() < 10000
               && m_process.state() != QProcess::NotRunning)
            QThread::msleep(10);
    }
    ~SimulatedDrive()
    {
        m_process.terminate();
        m_process.waitForFinished(5000);
    }
    bool ready() const { return QFileInfo::exists(m_link); }
    QString link() const { return m_link; }

private:
    QTemporaryDir m_folder;
    QString m_link;
    QProcess m_process;
};

// A shell loop that keeps one core busy at normal priority while it lives.
class BusyCore
{
public:
    BusyCore()
    {
        m_process.start(QStringLiteral("/bin/sh"), {QStringLiteral("-c"),
                                                   QStringLiteral("while :; do :; done")});
        m_process.waitForStarted();
    }
    ~BusyCore()
    {
        m_process.kill();
        m_process.waitForFinished(5000);
    }

private:
    QProcess m_process;
};

struct Timed {
    double seconds = -1; // < 0: the run failed
    double processor = 0; // processor seconds the program used meanwhile
};

struct ScanRun {
    Timed timed;
    QList<QByteArray> requests;
};

ConnectionSettings serialTo(const QString &link, Protocol protocol, qint32 baud)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.device = link;
    settings.protocol = protocol;
    settings.baudRate = baud;
    return settings;
}

// DriveDesk's cold scan (metadata refreshed into a fresh cache folder), timed from the scan's
// start to its result; the connection is made before the clock starts. With `requests`, what
// it sent is recorded there: the client then describes every telegram, as it does for the
// window's telegram monitor, so the timed runs leave it out, as the command line does.
ScanRun driveDeskScan(const ConnectionSettings &settings, bool recordRequests)
{
    ScanRun run;
    QTemporaryDir cache;
    DriveClient client(settings, everyLink());
    bool connected = false;
    bool failed = false;
    QObject::connect(&client, &DriveClient::connected, [&] { connected = true; });
    QObject::connect(&client, &DriveClient::connectionFailed, [&](const QString &reason) {
        std::fprintf(stderr, "cannot connect: %s\n", qPrintable(reason));
        failed = true;
    });
    if (recordRequests) {
        QObject::connect(&client, &DriveClient::traffic, [&](const TrafficRecord &record) {
            if (record.kind == TrafficRecord::Kind::Sent)
                run.requests.append(record.bytes);
        });
    }
    client.connectToDrive();
    runUntil([&] { return connected || failed; });
    if (failed)
        return run;
    run.requests.clear();
    ScanOptions options;
    options.metadata = MetadataSource::RefreshCache;
    options.cacheDirectory = cache.path();
    QElapsedTimer timer;
    timer.start();
    const double processor = processorSeconds();
    QFutureWatcher<DriveDescription> watcher;
    watcher.setFuture(client.scan(options));
    runUntil([&] { return watcher.isFinished(); });
    const Timed timed{timer.nsecsElapsed() / 1e9, processorSeconds() - processor};
    const DriveDescription description = watcher.future().result();
    if (!description.incompleteReason.isEmpty()) {
        std::fprintf(stderr, "incomplete scan: %s\n", qPrintable(description.incompleteReason));
        return run;
    }
    run.timed = timed;
    return run;
}

// The same requests, one at a time: write one, block until its answer is read whole.
Timed blockingScan(const ConnectionSettings &settings, const QList<QByteArray> &requests)
{
    QSerialPort port(settings.device);
    port.setBaudRate(settings.baudRate);
    port.setDataBits(settings.effectiveDataBits());
    port.setParity(settings.effectiveParity());
    port.setStopBits(settings.effectiveStopBits());
    if (!port.open(QIODevice::ReadWrite)) {
        std::fprintf(stderr, "cannot open %s: %s\n", qPrintable(settings.device),
                     qPrintable(port.errorString()));
        return {};
    }
    const std::unique_ptr<ProtocolCodec> codec = makeCodec(settings.protocol);
    const std::unique_ptr<FrameDecoder> decoder = codec->makeDecoder(Role::Operator);
    QElapsedTimer timer;
    timer.start();
    const double processor = processorSeconds();
    for (const QByteArray &request : requests) {
        port.write(request);
        port.waitForBytesWritten(kAnswerTimeoutMs);
        std::optional<Decoded> answer;
        while (!(answer = decoder->next())) {
            if (!port.waitForReadyRead(kAnswerTimeoutMs)) {
                std::fprintf(stderr, "blocking client: no answer in %d ms\n", kAnswerTimeoutMs);
                return {};
            }
            decoder->feed(port.readAll());
        }
        if (!std::holds_alternative<Telegram>(*answer)) {
            std::fprintf(stderr, "blocking client: an answer did not decode\n");
            return {};
        }
    }
    return Timed{timer.nsecsElapsed() / 1e9, processorSeconds() - processor};
}

struct Series {
    QList<double> seconds;
    QList<double> processor;
    void add(const Timed &run)
    {
        if (run.seconds < 0)
            return;
        seconds.append(run.seconds);
        processor.append(run.processor);
    }
    static double median(QList<double> values)
    {
        std::sort(values.begin(), values.end());
        const qsizetype n = values.size();
        return n == 0 ? 0 : n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
    }
    double median() const { return median(seconds); }
    QString spread() const
    {
        if (seconds.isEmpty())
            return QStringLiteral("no run");
        const auto [low, high] = std::minmax_element(seconds.begin(), seconds.end());
        return QStringLiteral("%1 s (%2-%3, %4 runs; processor %5 s)")
            .arg(median(), 0, 'f', 2)
            .arg(*low, 0, 'f', 2)
            .arg(*high, 0, 'f', 2)
            .arg(seconds.size())
            .arg(median(processor), 0, 'f', 2);
    }
};

int benchmark(Protocol protocol, qint32 baud, int rounds)
{
    SimulatedDrive drive(protocol, baud);
    if (!drive.ready()) {
        std::fprintf(stderr, "drivedesk-sim did not open its pseudo-terminal\n");
        return 1;
    }
    const ConnectionSettings settings = serialTo(drive.link(), protocol, baud);
    // The requests of a scan, once, untimed: the blocking client sends the same.
    const QList<QByteArray> requests = driveDeskScan(settings, true).requests;
    if (requests.isEmpty())
        return 1;
    Series quietDriveDesk, quietBlocking, loadedDriveDesk, loadedBlocking;
    const auto round = [&](Series &driveDesk, Series &blocking) {
        driveDesk.add(driveDeskScan(settings, false).timed);
        blocking.add(blockingScan(settings, requests));
    };
    for (int i = 0; i < rounds; ++i) {
        round(quietDriveDesk, quietBlocking);
        const BusyCore load;
        round(loadedDriveDesk, loadedBlocking);
        std::fprintf(stderr, "%s round %d of %d done\n", qPrintable(protocolName(protocol)), i + 1,
                     rounds);
    }
    const char *name = qPrintable(protocolName(protocol));
    std::printf("%s cold scan at %d baud, %lld requests, median (min-max):\n", name, baud,
                qlonglong(requests.size()));
    std::printf("  quiet    DriveDesk %s   blocking client %s\n",
                qPrintable(quietDriveDesk.spread()), qPrintable(quietBlocking.spread()));
    std::printf("  one core busy  DriveDesk %s   blocking client %s\n",
                qPrintable(loadedDriveDesk.spread()), qPrintable(loadedBlocking.spread()));
    std::printf("  DriveDesk loaded / quiet %.3f; loaded, DriveDesk / blocking client %.3f\n",
                loadedDriveDesk.median() / quietDriveDesk.median(),
                loadedDriveDesk.median() / loadedBlocking.median());
    std::fflush(stdout);
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QStringList arguments = app.arguments().mid(1);
    int rounds = 5;
    qint32 baud = 115200;
    QList<Protocol> protocols{Protocol::Din66019II, Protocol::Hsp5};
    while (!arguments.isEmpty()) {
        const QString argument = arguments.takeFirst();
        bool ok = true;
        if (argument == QLatin1String("--baud") && !arguments.isEmpty())
            baud = arguments.takeFirst().toInt(&ok);
        else if (argument == QLatin1String("--protocol") && !arguments.isEmpty()) {
            const std::optional<Protocol> protocol = protocolFromName(arguments.takeFirst());
            ok = protocol.has_value();
            if (ok)
                protocols = {*protocol};
        }
        else
            rounds = argument.toInt(&ok);
        if (!ok || rounds < 1 || baud < 50) {
            std::fprintf(stderr, "usage: bench_scan_loaded [ROUNDS] [--baud N] "
                                 "[--protocol hsp5|din66019ii]\n");
            return 2;
        }
    }
    for (const Protocol protocol : protocols) {
        if (const int status = benchmark(protocol, baud, rounds))
            return status;
    }
    return 0;
}
