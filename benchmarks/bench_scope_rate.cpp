// The scope's sample rate against what the wire allows, on the paced simulated drive: per
// protocol and baud rate, a recording of kSeconds as fast as the link goes, several runs.
// HSP5 answers in full duplex with four requests on the way: the reply direction is the limit,
// baud / (11 bits x 18 characters). DIN66019II carries one request at a time: 37 characters of
// 10 bits there and back, plus the drive's reply latency. Neither brings more than one new
// sample per tick of the drive's clock (1 kHz): the goal is the lower of the two.
// Usage: bench_scope_rate [RUNS]
#include "bus/LinkFactory.h"
#include "client/DriveClient.h"
#include "scope/ScopeRecording.h"
#include "session/ScopeRecorder.h"

#include <QCoreApplication>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

using namespace DriveDesk;

namespace {

constexpr int kLatencyUs = 1000;
constexpr qint64 kSeconds = 5;
constexpr double kDriveClockHz = 1000.0;

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

// The spread of one case's runs.
struct Spread
{
    double least = 0;
    double most = 0;
    void add(double value, bool first)
    {
        least = first ? value : std::min(least, value);
        most = first ? value : std::max(most, value);
    }
};

struct Outcome
{
    Spread distinctHz;
    Spread answersHz;
    Spread share;
    int runs = 0;
};

class RateBenchmark : public QObject
{
public:
    RateBenchmark(QList<Case> cases, int runs)
        : m_cases(std::move(cases))
        , m_runs(runs)
    {}

    void next()
    {
        if (m_index >= m_cases.size() * m_runs) {
            summarise();
            return QCoreApplication::quit();
        }
        m_case = m_cases[m_index++ % m_cases.size()];
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
            const double goal = std::min(wireLimitHz(m_case), kDriveClockHz);
            // Answers over the same span by the drive's clock as the distinct samples.
            const double answersHz = status.samples > 1
                ? status.averageHz * double(end.counts.answered - 1) / double(status.samples - 1)
                : 0.0;
            std::printf("%-11s %7d Bd  distinct %7.1f Hz  answers %7.1f Hz  goal %7.1f Hz  "
                        "%5.1f %%  lost %lld  failed %lld%s\n",
                        qPrintable(protocolName(m_case.protocol)), m_case.baud, status.averageHz, answersHz,
                        goal, 100.0 * status.averageHz / goal,
                        static_cast<long long>(end.counts.lost),
                        static_cast<long long>(end.counts.failed),
                        end.reason.isEmpty() ? "" : qPrintable(QStringLiteral("  (%1)").arg(end.reason)));
            std::fflush(stdout);
            Outcome &outcome = m_outcomes[key(m_case)];
            const bool first = outcome.runs++ == 0;
            outcome.distinctHz.add(status.averageHz, first);
            outcome.answersHz.add(answersHz, first);
            outcome.share.add(100.0 * status.averageHz / goal, first);
            QTimer::singleShot(0, this, &RateBenchmark::next);
        });
        ScopeRecorderOptions options;
        options.durationMs = kSeconds * 1000;
        m_recorder->start(m_recording.get(), options);
    }

    static int key(const Case &c) { return int(c.protocol) * 10'000'000 + c.baud; }

    void summarise() const
    {
        std::printf("\nover %d runs (least-most): distinct samples, answers, share of the goal\n",
                    m_runs);
        for (const Case &c : m_cases) {
            const Outcome &o = m_outcomes.at(key(c));
            std::printf("%-11s %7d Bd  %7.1f-%7.1f Hz  %7.1f-%7.1f Hz  %5.1f-%5.1f %%\n",
                        qPrintable(protocolName(c.protocol)), c.baud, o.distinctHz.least, o.distinctHz.most,
                        o.answersHz.least, o.answersHz.most, o.share.least, o.share.most);
        }
    }

    QList<Case> m_cases;
    int m_runs = 1;
    std::map<int, Outcome> m_outcomes;
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
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    std::printf("scope sample rate over %lld s against the lower of the wire limit and the "
                "drive's clock (reply latency %d us), %d runs\n",
                static_cast<long long>(kSeconds), kLatencyUs, runs);
    RateBenchmark benchmark(cases, runs);
    QTimer::singleShot(0, &benchmark, &RateBenchmark::next);
    return app.exec();
}
