// The scope's sample rate against what the wire allows, on the paced simulated drive: per
// protocol and baud rate, a recording of kSeconds as fast as the link goes.
// HSP5 answers in full duplex with four requests on the way: the reply direction is the limit,
// baud / (11 bits x 18 characters). DIN66019II carries one request at a time: 37 characters of
// 10 bits there and back, plus the drive's reply latency.
#include "bus/LinkFactory.h"
#include "client/DriveClient.h"
#include "scope/ScopeRecording.h"
#include "session/ScopeRecorder.h"

#include <QCoreApplication>
#include <QTimer>

#include <cstdio>
#include <memory>

using namespace DriveDesk;

namespace {

constexpr int kLatencyUs = 1000;
constexpr qint64 kSeconds = 5;

struct Case
{
    Protocol protocol;
    qint32 baud;
};

double wireLimitHz(const Case &c)
{
    if (c.protocol == Protocol::Hsp5)
        return double(c.baud) / (11.0 * 18.0);
    return 1.0 / (37.0 * 10.0 / double(c.baud) + kLatencyUs / 1e6);
}

class RateBenchmark : public QObject
{
public:
    explicit RateBenchmark(QList<Case> cases)
        : m_cases(std::move(cases))
    {}

    void next()
    {
        if (m_index >= m_cases.size())
            return QCoreApplication::quit();
        m_case = m_cases[m_index++];
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.protocol = m_case.protocol;
        settings.baudRate = m_case.baud;
        settings.simulation.baudRate = m_case.baud;
        settings.simulation.paced = true;
        settings.simulation.replyLatencyUs = kLatencyUs;
        m_recorder.reset();
        m_client = std::make_unique<DriveClient>(settings, everyLink());
        connect(m_client.get(), &DriveClient::connected, this, &RateBenchmark::record);
        m_client->connectToDrive();
    }

private:
    void record()
    {
        m_recording = std::make_unique<ScopeRecording>();
        m_recorder = std::make_unique<ScopeRecorder>(m_client.get());
        connect(m_recorder.get(), &ScopeRecorder::finished, this, [this](const ScopePollEnd &end) {
            const ScopeRecorderStatus status = m_recorder->status();
            const double limit = wireLimitHz(m_case);
            std::printf("%-11s %7d Bd  %9.1f Hz  limit %9.1f Hz  %5.1f %%  samples %7lld  "
                        "lost %lld  failed %lld%s\n",
                        m_case.protocol == Protocol::Hsp5 ? "HSP5" : "DIN66019II", m_case.baud,
                        status.averageHz, limit, 100.0 * status.averageHz / limit,
                        static_cast<long long>(status.samples),
                        static_cast<long long>(end.counts.lost),
                        static_cast<long long>(end.counts.failed),
                        end.reason.isEmpty() ? "" : qPrintable(QStringLiteral("  (%1)").arg(end.reason)));
            std::fflush(stdout);
            QTimer::singleShot(0, this, &RateBenchmark::next);
        });
        ScopeRecorderOptions options;
        options.durationMs = kSeconds * 1000;
        m_recorder->start(m_recording.get(), options);
    }

    QList<Case> m_cases;
    qsizetype m_index = 0;
    Case m_case{};
    std::unique_ptr<DriveClient> m_client;
    std::unique_ptr<ScopeRecording> m_recording;
    std::unique_ptr<ScopeRecorder> m_recorder;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QList<Case> cases;
    for (const Protocol protocol : {Protocol::Hsp5, Protocol::Din66019II}) {
        for (const qint32 baud : {38400, 115200, 250000})
            cases.append({protocol, baud});
    }
    std::printf("scope sample rate over %lld s against the wire limit (reply latency %d us)\n",
                static_cast<long long>(kSeconds), kLatencyUs);
    RateBenchmark benchmark(cases);
    QTimer::singleShot(0, &benchmark, &RateBenchmark::next);
    return app.exec();
}
