#include "ClientTestSupport.h"

#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"
#include "client/ClientTiming.h"

#include <QElapsedTimer>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

namespace {

ClientOptions checkingIdleLine(int idleCheckMs = ClientOptions::kInteractiveIdleCheckMs)
{
    ClientOptions options;
    options.idleCheckMs = idleCheckMs;
    return options;
}

int sentCount(const QList<TrafficRecord> &records)
{
    return int(std::count_if(records.begin(), records.end(), [](const TrafficRecord &record) {
        return record.kind == TrafficRecord::Kind::Sent;
    }));
}

} // namespace

// ClientOptions::idleCheckMs: a drive that freezes while nobody asks it anything is reported
// all the same, and the check stands in front of no request.
class TestClientIdleCheck : public QObject
{
    Q_OBJECT
private slots:
    void theBoundStaysWithinFiveSeconds_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<int>("baud");
        QTest::addColumn<bool>("tcp");
        QTest::addColumn<int>("limitMs");
        // The lines of docs/client.md, checked after 2 s of quiet.
        QTest::newRow("hsp5 38400") << Protocol::Hsp5 << 38400 << false << 2472;
        QTest::newRow("hsp5 9600") << Protocol::Hsp5 << 9600 << false << 3212;
        QTest::newRow("din 38400") << Protocol::Din66019II << 38400 << false << 2492;
        QTest::newRow("din 9600") << Protocol::Din66019II << 9600 << false << 3368;
        QTest::newRow("hsp5 tcp 38400") << Protocol::Hsp5 << 38400 << true << 3132;
    }

    void theBoundStaysWithinFiveSeconds()
    {
        QFETCH(Protocol, protocol);
        QFETCH(int, baud);
        QFETCH(bool, tcp);
        QFETCH(int, limitMs);
        ConnectionSettings settings;
        settings.kind = tcp ? ConnectionSettings::Kind::Tcp : ConnectionSettings::Kind::Serial;
        settings.protocol = protocol;
        settings.baudRate = baud;
        QCOMPARE(idleSilenceLimitMs(settings, checkingIdleLine()), limitMs);
        QVERIFY(limitMs <= 5000);
    }

    void aDriveFrozenOnAnIdleLineIsReported_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
        QTest::newRow("din66019") << Protocol::Din66019;
    }

    void aDriveFrozenOnAnIdleLineIsReported()
    {
        QFETCH(Protocol, protocol);
        SimulatorServer server(protocol, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, protocol), checkingIdleLine());
        QVERIFY(s.connected());
        const Reply read = s.call(s.client->readValueStandard(kMaxSpeedForward, 0));
        QCOMPARE(read.status, Reply::Status::Ok);
        QSignalSpy silent(s.client.get(), &DriveClient::driveSilentChanged);

        // Nobody asks the frozen drive anything: the client finds out by itself.
        server.bus().setSilent(true);
        QElapsedTimer sinceFreeze;
        sinceFreeze.start();
        const int limitMs = idleSilenceLimitMs(s.client->settings(), checkingIdleLine());
        const bool reported
            = QTest::qWaitFor([&] { return s.client->isDriveSilent(); }, limitMs + 1500);
        QVERIFY2(reported, qPrintable(QStringLiteral("not reported %1 ms after the freeze")
                                          .arg(sinceFreeze.elapsed())));
        QCOMPARE(s.client->state(), DriveClient::State::Connected);
        QVERIFY(sentCount(s.records()) > 1); // the checks, on the telegram monitor too

        // Back: the next check is answered, and the silence ends by itself.
        server.bus().setSilent(false);
        QTRY_VERIFY_WITH_TIMEOUT(!s.client->isDriveSilent(), kWaitMs);
        QCOMPARE(silent.size(), 2);
        const Reply again = s.call(s.client->readValueStandard(kMaxSpeedForward, 0));
        QCOMPARE(again.status, Reply::Status::Ok);
    }

    // HSP5 sends up to 4 requests at once: a request made while the check waits for its answer
    // goes out at once, not after it.
    void theCheckStandsInFrontOfNoRequest()
    {
        SimulationOptions slow = fast();
        slow.replyLatencyUs = 150000; // within the answer timeout over TCP (242 ms)
        SimulatorServer server(Protocol::Hsp5, slow);
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, Protocol::Hsp5), checkingIdleLine(300));
        QVERIFY(s.connected());
        QTRY_VERIFY_WITH_TIMEOUT(sentCount(s.records()) == 1, kWaitMs); // the check is out
        const QFuture<Reply> read = s.client->readValue(kMaxSpeedForward, 0x01);
        QTRY_VERIFY_WITH_TIMEOUT(sentCount(s.records()) == 2, kWaitMs);
        const QList<TrafficRecord> records = s.records();
        const bool checkAnswered = std::any_of(records.begin(), records.end(),
                                               [](const TrafficRecord &record) {
                                                   return record.kind
                                                       == TrafficRecord::Kind::Received;
                                               });
        QVERIFY2(!checkAnswered, "the request waited for the check's answer");
        QCOMPARE(replyOf(read).status, Reply::Status::Ok);
    }

    // Told a parameter the drive has, the check reads it and is answered with its value: no
    // refusal ("address invalid") in the monitor every two seconds.
    void theCheckReadsTheParameterItIsGiven()
    {
        SimulatorServer server(Protocol::Hsp5, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, Protocol::Hsp5), checkingIdleLine(300));
        QVERIFY(s.connected());
        s.client->setIdleCheckAddress(kMaxSpeedForward);
        const auto answers = [&s] {
            const auto decoder = makeCodec(Protocol::Hsp5)->makeDecoder(Role::Operator);
            QList<Telegram> telegrams;
            for (const TrafficRecord &record : s.records()) {
                if (record.kind != TrafficRecord::Kind::Received)
                    continue;
                decoder->feed(record.bytes);
                while (const std::optional<Decoded> item = decoder->next()) {
                    if (const auto *telegram = std::get_if<Telegram>(&*item))
                        telegrams << *telegram;
                }
            }
            return telegrams;
        };
        QTRY_VERIFY_WITH_TIMEOUT(answers().size() >= 2, kWaitMs);
        const Telegram last = answers().constLast();
        QCOMPARE(last.ack, Ack::Ok);
        const auto *value = last.as<ParameterValue>();
        QVERIFY(value);
        QCOMPARE(value->value, kMaxSpeedDefault);
    }

    // Without the option the line stays as quiet as the caller leaves it.
    void withoutTheOptionNothingIsSentUnasked()
    {
        SimulatorServer server(Protocol::Hsp5, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, Protocol::Hsp5));
        QVERIFY(s.connected());
        QTest::qWait(2 * ClientOptions::kInteractiveIdleCheckMs);
        QCOMPARE(sentCount(s.records()), 0);
    }
};

QTEST_GUILESS_MAIN(TestClientIdleCheck)
#include "tst_clientidlecheck.moc"
