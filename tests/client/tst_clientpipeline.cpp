#include "ClientTestSupport.h"
#include "Translations.h"

#include <QTest>

#include <algorithm>
#include <map>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

// Parameters with known defaults, each a different value: a mixed-up answer shows.
const std::map<quint16, qint32> &knownDefaults()
{
    static const std::map<quint16, qint32> values{
        {0x030B, 3000}, // op.11
        {0x0604, 400},  // dr.04
        {0x0418, 150},  // Pn.24
        {0x0E01, 105},  // In.01
        {0x0E00, 0x0F50}, // In.00
        {0x0601, 1450}, // dr.01
        {0x0602, 85},   // dr.02
        {0x0701, 1500}, // cn.01
        {0x0702, 500},  // cn.02
        {0x0F00, 300},  // CS.00
        {0x0F01, 100},  // CS.01
        {0x0E02, 189},  // In.02
    };
    return values;
}

// The most requests on the wire at once, from the order of the traffic records.
int mostInFlight(const QList<TrafficRecord> &records)
{
    int open = 0;
    int most = 0;
    for (const TrafficRecord &record : records) {
        if (record.meaning.startsWith(QStringLiteral("inverter request")))
            continue;
        const bool request = record.meaning.startsWith(QStringLiteral("request"));
        if (record.kind == TrafficRecord::Kind::Sent && request)
            most = std::max(most, ++open);
        else if (record.kind == TrafficRecord::Kind::Received)
            --open;
    }
    return most;
}

struct Batch {
    QList<QFuture<Reply>> futures;
    QList<quint16> addresses;
};

Batch readMany(DriveClient &client, int count)
{
    Batch batch;
    const auto &values = knownDefaults();
    auto it = values.begin();
    for (int i = 0; i < count; ++i, ++it) {
        if (it == values.end())
            it = values.begin();
        batch.addresses.append(it->first);
        batch.futures.append(client.readValue(it->first, 0x01));
    }
    return batch;
}

} // namespace

// HSP5 is full duplex: up to 4 requests in flight, answers matched by their invoke id, requests
// the inverter starts answered "service not available", busy answers tried again.
class TestClientPipeline : public QObject
{
    Q_OBJECT
private slots:
    // English as the programs show it: with its catalogue, which holds the plural forms.
    void initTestCase() { QVERIFY(installTranslations(QStringLiteral("en"))); }

    void fourRequestsInFlightAreAllMatchedCorrectly()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        const Batch batch = readMany(*s.client, 200);
        for (int i = 0; i < batch.futures.size(); ++i) {
            const Reply reply = replyOf(batch.futures.at(i));
            QVERIFY2(reply.ok(), qPrintable(describeReply(reply)));
            QCOMPARE(reply.data<ParameterValue>()->address, batch.addresses.at(i));
            QCOMPARE(reply.data<ParameterValue>()->value,
                     knownDefaults().at(batch.addresses.at(i)));
        }
        QTRY_COMPARE(s.traffic->size(), 400);
        QCOMPARE(mostInFlight(s.records()), 4);
    }

    void fewerInFlightWhenAsked()
    {
        ClientOptions options;
        options.maxInFlight = 2;
        // Replies that take a moment: the second request is always out before the first answer
        // is in, however the threads are scheduled.
        SimulationOptions simulation;
        simulation.replyLatencyUs = 2000;
        Session s(simulated(Protocol::Hsp5, simulation), options);
        QVERIFY(s.connected());
        const Batch batch = readMany(*s.client, 20);
        for (const QFuture<Reply> &future : batch.futures)
            QVERIFY(replyOf(future).ok());
        QTRY_COMPARE(s.traffic->size(), 40);
        QCOMPARE(mostInFlight(s.records()), 2);
    }

    void invokeIdsWrapToOne()
    {
        ClientOptions options;
        options.maxInFlight = 1;
        Session s(simulated(Protocol::Hsp5, fast()), options);
        QVERIFY(s.connected());
        QList<int> ids;
        for (int i = 0; i < 16; ++i)
            ids.append(s.call(s.client->readValue(kMaxSpeedForward, 1)).request.operatorInvoke);
        QCOMPARE(ids, (QList<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 1}));
    }

    void inverterRequestsAreAnsweredAndNeverTakenForReplies()
    {
        SimulationOptions simulation = fast();
        simulation.unsolicitedRate = 0.3;
        Session s(simulated(Protocol::Hsp5, simulation));
        QVERIFY(s.connected());
        const Batch batch = readMany(*s.client, 300);
        for (int i = 0; i < batch.futures.size(); ++i) {
            const Reply reply = replyOf(batch.futures.at(i));
            QVERIFY2(reply.ok(), qPrintable(describeReply(reply)));
            QCOMPARE(reply.data<ParameterValue>()->value,
                     knownDefaults().at(batch.addresses.at(i)));
            QCOMPARE(reply.attempts, 1);
        }
        int inverterRequests = 0;
        int refusals = 0;
        for (const TrafficRecord &record : s.records()) {
            if (record.meaning.startsWith(QStringLiteral("inverter request")))
                ++inverterRequests;
            if (record.kind == TrafficRecord::Kind::Sent
                && record.meaning.contains(QStringLiteral("service not available")))
                ++refusals;
        }
        QVERIFY2(inverterRequests > 20, qPrintable(QString::number(inverterRequests)));
        QCOMPARE(refusals, inverterRequests);
    }

    void busyAnswersAreTriedAgain_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }
    void busyAnswersAreTriedAgain()
    {
        QFETCH(Protocol, protocol);
        SimulationOptions simulation = fast();
        simulation.busyRate = 0.3;
        ClientOptions options;
        options.retries = 10;
        Session s(simulated(protocol, simulation), options);
        QVERIFY(s.connected());
        const Batch batch = readMany(*s.client, 100);
        int retried = 0;
        for (int i = 0; i < batch.futures.size(); ++i) {
            const Reply reply = replyOf(batch.futures.at(i));
            QVERIFY2(reply.ok(), qPrintable(describeReply(reply)));
            QCOMPARE(reply.data<ParameterValue>()->value,
                     knownDefaults().at(batch.addresses.at(i)));
            if (reply.attempts > 1) {
                ++retried;
                QVERIFY2(reply.detail.contains(QStringLiteral("inverter busy")),
                         qPrintable(reply.detail));
            }
        }
        QVERIFY(retried > 10);
    }

    void busyToTheEndIsARefusal()
    {
        SimulationOptions simulation = fast();
        simulation.busyRate = 1.0;
        ClientOptions options;
        options.retries = 2;
        Session s(simulated(Protocol::Hsp5, simulation), options);
        QVERIFY(s.connected());
        const Reply reply = s.call(s.client->readValue(kMaxSpeedForward, 1));
        QCOMPARE(reply.status, Reply::Status::Refused);
        QCOMPARE(reply.ack(), Ack::Busy);
        QCOMPARE(reply.attempts, 3);
        QCOMPARE(reply.message(),
                 QStringLiteral("drive refused: inverter busy (after 3 attempts)"));
    }
};

QTEST_GUILESS_MAIN(TestClientPipeline)
#include "tst_clientpipeline.moc"
