#include "ClientTestSupport.h"

#include "bus/LinkFactory.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

// The drive scan through the client: progress and result in a QFuture, cancellable, and
// sharing the queue with everybody else's requests.
class TestClientScan : public QObject
{
    Q_OBJECT
private slots:
    void scanReadsGroupsParametersAndValues_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }
    void scanReadsGroupsParametersAndValues()
    {
        QFETCH(Protocol, protocol);
        Session s(simulated(protocol, fast()));
        QVERIFY(s.connected());
        QVERIFY(s.call(s.client->writeValue(kMaxSpeedForward, 2600, 0x04)).ok()); // set 2

        ScanOptions options;
        options.groupPages = {0x03, 0x0E}; // op, In
        QFuture<DriveDescription> scan = s.client->scan(options);
        QVERIFY(waitFinished(scan, 60000));
        QCOMPARE(scan.progressMaximum(), 1000);
        QCOMPARE(scan.progressValue(), 1000);
        const DriveDescription drive = scan.result();
        QCOMPARE(drive.protocol, protocolName(protocol));
        QVERIFY(!drive.connection.isEmpty());
        QCOMPARE(drive.groups.size(), 2);
        QVERIFY2(drive.incompleteReason.isEmpty(), qPrintable(drive.incompleteReason));

        const ParameterDescription *maxSpeed = drive.find(kMaxSpeedForward);
        QVERIFY(maxSpeed);
        QCOMPARE(maxSpeed->name, QStringLiteral("Maximum speed forward"));
        QCOMPARE(maxSpeed->maximum, 4000);
        QCOMPARE(maxSpeed->defaultValue, kMaxSpeedDefault);
        QVERIFY(maxSpeed->isSetProgrammable());
        QCOMPARE(maxSpeed->values[0], std::optional<qint32>(kMaxSpeedDefault));
        QCOMPARE(maxSpeed->values[2], std::optional<qint32>(2600));
        const ParameterDescription *ratedCurrent = drive.find(kRatedCurrent);
        QVERIFY(ratedCurrent);
        QCOMPARE(ratedCurrent->values[0], std::optional<qint32>(105));
    }

    void cancellingTheScanLeavesOtherRequestsAlone()
    {
        SimulationOptions simulation;
        simulation.replyLatencyUs = 2000;
        Session s(simulated(Protocol::Hsp5, simulation));
        QVERIFY(s.connected());
        QFuture<DriveDescription> scan = s.client->scan();
        QTRY_VERIFY(scan.progressValue() > 0);
        const QFuture<Reply> mine = s.client->readValue(kMaxSpeedForward, 1);
        scan.cancel();
        QVERIFY(waitFinished(scan, 2000));
        QVERIFY(scan.isCanceled());
        const Reply reply = replyOf(mine);
        QVERIFY2(reply.ok(), qPrintable(describeReply(reply)));
        QCOMPARE(reply.data<ParameterValue>()->value, kMaxSpeedDefault);
    }

    void scanWithoutConnectionSaysSo()
    {
        DriveClient client(simulated(Protocol::Hsp5, fast()), everyLink());
        QFuture<DriveDescription> scan = client.scan();
        QVERIFY(waitFinished(scan));
        QVERIFY(!scan.result().incompleteReason.isEmpty());
        QCOMPARE(scan.result().groups.size(), 0);
    }
};

QTEST_GUILESS_MAIN(TestClientScan)
#include "tst_clientscan.moc"
