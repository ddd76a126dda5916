#include "ClientTestSupport.h"

#include "bus/LinkFactory.h"
#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"
#include "client/FindDrivesJob.h"

#include <QTest>

#include <map>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

namespace {

// Read-only or untouched parameters with known values, each value different.
const std::map<quint16, qint32> kKnown{
    {0x030B, 3000}, {0x0604, 400}, {0x0418, 150}, {0x0E01, 105}, {0x0E00, 0x0F50},
    {0x0601, 1450}, {0x0602, 85},  {0x0701, 1500}, {0x0702, 500}, {0x0F00, 300},
    {0x0F01, 100},  {0x0E02, 189},
};

struct Tally {
    int ok = 0;
    int wrong = 0;     // accepted with a value the drive does not hold (see below)
    int mixedUp = 0;   // of those, another parameter's value
    int failed = 0;
    int silent = 0;    // failed without a message: must stay 0
    QString firstWrong;
    QString firstFailure;
};

bool isAnotherParametersValue(quint16 address, qint32 value)
{
    for (const auto &[other, known] : kKnown) {
        if (other != address && known == value)
            return true;
    }
    return false;
}

// Keeps `window` requests open at a time until `total` were answered.
Tally readUnderFaults(DriveClient &client, int total, int window)
{
    Tally tally;
    struct Open {
        QFuture<Reply> future;
        quint16 address;
    };
    QList<Open> open;
    auto next = kKnown.begin();
    int sent = 0;
    while (sent < total || !open.isEmpty()) {
        while (sent < total && open.size() < window) {
            if (next == kKnown.end())
                next = kKnown.begin();
            open.append({client.readValue(next->first, 0x01), next->first});
            ++next;
            ++sent;
        }
        if (!waitFinished(open.first().future, kWaitMs))
            break;
        const Open done = open.takeFirst();
        const Reply reply = done.future.result();
        if (reply.ok()) {
            ++tally.ok;
            const qint32 value = reply.data<ParameterValue>()->value;
            if (value != kKnown.at(done.address)) {
                ++tally.wrong;
                tally.mixedUp += isAnotherParametersValue(done.address, value);
                if (tally.firstWrong.isEmpty())
                    tally.firstWrong = QStringLiteral("%1h read %2")
                                           .arg(done.address, 4, 16, QLatin1Char('0'))
                                           .arg(value);
            }
        } else {
            ++tally.failed;
            if (reply.message().isEmpty())
                ++tally.silent;
            if (tally.firstFailure.isEmpty())
                tally.firstFailure = reply.message();
        }
    }
    return tally;
}

} // namespace

// Faults on the line: corrupted and dropped bytes, a lost link, cancelled requests. Whatever
// happens every request ends, every failure says why, and only what the protocols' BCC cannot
// see gets through.
class TestClientFaults : public QObject
{
    Q_OBJECT
private slots:
    void corruptedBytesAreCaughtWhereTheBccCan_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<int>("requests");
        QTest::addColumn<int>("window");
        QTest::newRow("hsp5") << Protocol::Hsp5 << 10000 << 8;
        QTest::newRow("din66019ii") << Protocol::Din66019II << 3000 << 2;
    }
    void corruptedBytesAreCaughtWhereTheBccCan()
    {
        QFETCH(Protocol, protocol);
        QFETCH(int, requests);
        QFETCH(int, window);
        SimulationOptions simulation = fast();
        simulation.corruptByteRate = 0.01;
        simulation.seed = 7;
        ClientOptions options;
        options.timeoutMs = 30; // no latency in process: keep the lost answers cheap
        Session s(simulated(protocol, simulation), options);
        QVERIFY(s.connected());

        const Tally tally = readUnderFaults(*s.client, requests, window);
        qInfo("%d ok, %d failed (first: %s), %d accepted with a value the BCC could not guard, "
              "%d of them another parameter's (first: %s)",
              tally.ok, tally.failed, qPrintable(tally.firstFailure), tally.wrong, tally.mixedUp,
              qPrintable(tally.firstWrong));
        QCOMPARE(tally.ok + tally.failed, requests);
        QCOMPARE(tally.silent, 0);
        QVERIFY(tally.ok > requests * 99 / 100);
        // The line's parity catches every corrupted character (the link reports it, the drive
        // drops the request): not one wrong value may be accepted.
        QVERIFY2(tally.wrong == 0,
                 qPrintable(QStringLiteral("%1 wrong values (%2 of another parameter), first: %3")
                                .arg(tally.wrong)
                                .arg(tally.mixedUp)
                                .arg(tally.firstWrong)));
    }

    void droppedBytesEndInRetriesOrTimeouts()
    {
        SimulationOptions simulation = fast();
        simulation.dropByteRate = 0.01;
        ClientOptions options;
        options.timeoutMs = 30;
        Session s(simulated(Protocol::Hsp5, simulation), options);
        QVERIFY(s.connected());
        const Tally tally = readUnderFaults(*s.client, 1000, 4);
        QCOMPARE(tally.ok + tally.failed, 1000);
        QVERIFY(tally.wrong <= 2);
        QCOMPARE(tally.silent, 0);
    }

    void lostLinkFailsEveryPendingRequestAtOnce()
    {
        SimulationOptions simulation;
        simulation.replyLatencyUs = 300000; // answers take long: requests are still pending
        SimulatorServer server(Protocol::Hsp5, simulation);
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));

        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = server.tcpPort();
        settings.protocol = Protocol::Hsp5;
        ClientOptions options;
        options.timeoutMs = 10000; // a timeout must not be what ends them
        Session s(settings, options);
        QVERIFY(s.connected());
        QSignalSpy lost(s.client.get(), &DriveClient::linkLost);

        QList<QFuture<Reply>> pending;
        for (int i = 0; i < 10; ++i)
            pending.append(s.client->readValue(kMaxSpeedForward, 1));
        QTRY_VERIFY(server.hasClient());
        QTest::qWait(50);
        server.close();

        QTRY_COMPARE_WITH_TIMEOUT(lost.size(), 1, 3000);
        for (const QFuture<Reply> &future : pending) {
            QVERIFY(waitFinished(future, 3000));
            const Reply reply = future.result();
            QCOMPARE(reply.status, Reply::Status::LinkLost);
            QVERIFY2(reply.message().contains(QStringLiteral("closed the connection")),
                     qPrintable(reply.message()));
        }
        QCOMPARE(s.client->state(), DriveClient::State::Lost);
        QCOMPARE(replyOf(s.client->readValue(kMaxSpeedForward, 1)).status,
                 Reply::Status::NotConnected);
    }

    void silentDriveIsReportedAndClearsWhenItAnswers()
    {
        // The drive freezes behind an open TCP connection: no answers, no closed socket.
        SimulatorServer server(Protocol::Hsp5, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = server.tcpPort();
        settings.protocol = Protocol::Hsp5;
        ClientOptions options;
        options.timeoutMs = 50;
        Session s(settings, options);
        QVERIFY(s.connected());
        QSignalSpy silence(s.client.get(), &DriveClient::driveSilentChanged);
        QVERIFY(s.call(s.client->readValue(kMotorVoltage, 1)).ok());
        QVERIFY(!s.client->isDriveSilent());

        server.bus().setSilent(true);
        const Reply unanswered = s.call(s.client->readValue(kMotorVoltage, 1));
        QCOMPARE(unanswered.status, Reply::Status::Timeout);
        QTRY_VERIFY(s.client->isDriveSilent());
        QCOMPARE(silence.size(), 1);
        QCOMPARE(silence.first().at(0).toBool(), true);
        QCOMPARE(s.client->state(), DriveClient::State::Connected); // the link is still open
        QVERIFY(server.bus().counters().ignoredWhileSilent > 0);

        server.bus().setSilent(false);
        const Reply answered = s.call(s.client->readValue(kMotorVoltage, 1));
        QVERIFY2(answered.ok(), qPrintable(describeReply(answered)));
        QTRY_VERIFY(!s.client->isDriveSilent());
        QCOMPARE(silence.size(), 2);
        QCOMPARE(silence.last().at(0).toBool(), false);
    }

    void probesThatGoUnansweredDoNotMakeTheDriveSilent()
    {
        // A search asks addresses where no drive is: that is no silence of the connected drive.
        Session s(simulated(Protocol::Din66019II, fast()));
        QVERIFY(s.connected());
        const QFuture<FoundDrive> search
            = s.client->run(std::make_shared<FindDrivesJob>(s.client->settings(), 2, 4));
        QVERIFY(waitFinished(search));
        QVERIFY(s.call(s.client->readValue(kMotorVoltage, 1)).ok());
        QCoreApplication::processEvents();
        QVERIFY(!s.client->isDriveSilent());
    }

    void refusedConnectionIsReported()
    {
        SimulatorServer server(Protocol::Hsp5, fast());
        QString error;
        QVERIFY(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error));
        const quint16 port = server.tcpPort();
        server.close();

        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = port;
        DriveClient client(settings, everyLink());
        QSignalSpy failed(&client, &DriveClient::connectionFailed);
        client.connectToDrive();
        const QFuture<Reply> queued = client.readValue(kMaxSpeedForward, 1);
        QTRY_COMPARE(failed.size(), 1);
        QVERIFY(!failed.first().at(0).toString().isEmpty());
        const Reply reply = replyOf(queued);
        QCOMPARE(reply.status, Reply::Status::NotConnected);
        QVERIFY(!reply.detail.isEmpty());
        QCOMPARE(client.state(), DriveClient::State::Disconnected);
    }

    void cancelAllEndsEveryRequest_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }
    void cancelAllEndsEveryRequest()
    {
        QFETCH(Protocol, protocol);
        SimulationOptions simulation;
        simulation.replyLatencyUs = 20000;
        Session s(simulated(protocol, simulation));
        QVERIFY(s.connected());
        QList<QFuture<Reply>> pending;
        for (int i = 0; i < 30; ++i)
            pending.append(s.client->readValue(kMaxSpeedForward, 1));
        s.client->cancelAll();
        int cancelled = 0;
        for (const QFuture<Reply> &future : pending) {
            QVERIFY(waitFinished(future, 1000));
            const Reply reply = future.result();
            QVERIFY(reply.status == Reply::Status::Cancelled || reply.ok());
            cancelled += reply.status == Reply::Status::Cancelled;
        }
        QVERIFY(cancelled >= 25);
        // The answers still on their way are ignored; the client goes on.
        const Reply after = replyOf(s.client->readValue(kMotorVoltage, 1));
        QVERIFY2(after.ok(), qPrintable(describeReply(after)));
        QCOMPARE(after.data<ParameterValue>()->value, 400);
    }

    void cancellingAFutureDropsItsRequest()
    {
        SimulationOptions simulation;
        simulation.replyLatencyUs = 20000;
        Session s(simulated(Protocol::Din66019II, simulation));
        QVERIFY(s.connected());
        const QFuture<Reply> first = s.client->readValue(kMaxSpeedForward, 1);
        QFuture<Reply> second = s.client->writeValue(kMaxSpeedForward, 1234, 1);
        const QFuture<Reply> third = s.client->readValue(kMaxSpeedForward, 1);
        second.cancel();
        QVERIFY(replyOf(first).ok());
        QVERIFY(waitFinished(second));
        QVERIFY(second.isCanceled());
        const Reply read = replyOf(third);
        QVERIFY(read.ok());
        QCOMPARE(read.data<ParameterValue>()->value, kMaxSpeedDefault); // never written
    }

    void destroyingTheClientEndsItsRequests()
    {
        SimulationOptions simulation;
        simulation.replyLatencyUs = 50000;
        QList<QFuture<Reply>> pending;
        {
            Session s(simulated(Protocol::Hsp5, simulation));
            QVERIFY(s.connected());
            for (int i = 0; i < 10; ++i)
                pending.append(s.client->readValue(kMaxSpeedForward, 1));
        }
        for (const QFuture<Reply> &future : pending)
            QVERIFY(future.isFinished());
    }
};

QTEST_GUILESS_MAIN(TestClientFaults)
#include "tst_clientfaults.moc"
