#include "ClientTestSupport.h"

#include "bus/LinkFactory.h"

#include <QFutureWatcher>
#include <QTest>

#include <cmath>

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

    // The bar follows the telegrams: at every step it stands near the share of the scan's
    // telegrams sent so far, with no long stall near the start or the end.
    void progressFollowsTheTelegrams()
    {
        // Slow enough for many steps: the future reports progress at most every few ms.
        SimulationOptions simulation;
        simulation.replyLatencyUs = 1000;
        Session s(simulated(Protocol::Hsp5, simulation));
        QVERIFY(s.connected());
        int sent = 0;
        QObject::connect(s.client.get(), &DriveClient::traffic, s.client.get(),
                         [&sent](const TrafficRecord &record) {
                             sent += record.kind == TrafficRecord::Kind::Sent;
                         });
        QList<std::pair<int, int>> steps; // progress, telegrams sent by then
        QFutureWatcher<DriveDescription> watcher;
        QObject::connect(&watcher, &QFutureWatcherBase::progressValueChanged, &watcher,
                         [&](int value) { steps.append({ value, sent }); });
        ScanOptions options;
        options.metadata = MetadataSource::Drive;
        watcher.setFuture(s.client->scan(options));
        QVERIFY(waitFinished(watcher.future(), 60000));
        QCoreApplication::processEvents();
        QVERIFY(sent > 1000);
        QVERIFY(steps.size() > 10);
        double worst = 0;
        for (const auto &[value, sentThen] : std::as_const(steps)) {
            if (value >= 1000)
                continue;
            worst = std::max(worst, std::abs(value / 1000.0 - double(sentThen) / sent));
        }
        QVERIFY2(worst < 0.15,
                 qPrintable(QStringLiteral("%1 telegrams; worst gap %2").arg(sent).arg(worst)));
    }

    // Stopped, not cancelled: the scan hands over what it has read, marked incomplete.
    void aStoppedScanGivesWhatItRead()
    {
        SimulationOptions simulation;
        simulation.replyLatencyUs = 2000;
        Session s(simulated(Protocol::Hsp5, simulation));
        QVERIFY(s.connected());
        ScanOptions options;
        options.metadata = MetadataSource::Drive;
        QFuture<DriveDescription> scan = s.client->scan(options);
        QTRY_VERIFY_WITH_TIMEOUT(scan.progressValue() > 500, 60000);
        s.client->stopScan();
        QVERIFY(waitFinished(scan, 5000));
        QVERIFY(!scan.isCanceled());
        QCOMPARE(scan.resultCount(), 1);
        const DriveDescription drive = scan.result();
        QVERIFY(!drive.incompleteReason.isEmpty());
        QVERIFY(drive.parameterCount() > 0);
        QVERIFY(drive.parameterCount() < 206);
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
