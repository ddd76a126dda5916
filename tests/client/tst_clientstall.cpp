#include "ClientTestSupport.h"

#include "client/RequestJob.h"

#include <QThread>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

namespace {

// Holds the client's thread, as a busy machine does when it gives the thread no time: a job
// whose start does nothing but wait.
class StallJob : public RequestJob<int>
{
public:
    explicit StallJob(int ms)
        : m_ms(ms)
    {}

private:
    void start() override
    {
        QThread::msleep(m_ms);
        promise().addResult(m_ms);
        end();
    }

    const int m_ms;
};

constexpr int kTimeoutMs = 150;

} // namespace

// A busy machine may wake the client's thread only after an answer has come in and its
// deadline has passed. The answer came in time: the request is answered, not timed out.
class TestClientStall : public QObject
{
    Q_OBJECT
private slots:
    void anAnswerWaitingWhenTheDeadlineFiresCounts_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }

    void anAnswerWaitingWhenTheDeadlineFiresCounts()
    {
        QFETCH(Protocol, protocol);
        SimulatorServer server(protocol, fast());
        QVERIFY(server.listenTcp(QStringLiteral("127.0.0.1"), 0, nullptr));
        ClientOptions options;
        options.timeoutMs = kTimeoutMs;
        options.retries = 0; // one attempt: a timeout is the request's end
        Session session(tcpTo(server, protocol), options);
        QVERIFY(session.connected());
        for (int round = 0; round < 5; ++round) {
            const QFuture<Reply> read = session.client->readValue(kMaxSpeedForward, 1);
            // Queued behind the read: the client's thread sends it, then stalls past its
            // deadline while the answer arrives.
            const QFuture<int> stall = session.client->run(std::make_shared<StallJob>(3 * kTimeoutMs));
            const Reply reply = session.call(read);
            QVERIFY2(reply.ok(), qPrintable(QStringLiteral("round %1: %2")
                                                .arg(round)
                                                .arg(describeReply(reply))));
            QCOMPARE(valueOf(reply), kMaxSpeedDefault);
            QVERIFY(waitFinished(stall));
        }
    }
};

QTEST_GUILESS_MAIN(TestClientStall)
#include "tst_clientstall.moc"
