#include "ClientTestSupport.h"
#include "bus/SimulatorServer.h"

#include <QFutureWatcher>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

// A link that goes away in the middle of a scan: the scan ends at once, says why, and keeps
// what it had read.
class TestClientUnplug : public QObject
{
    Q_OBJECT
private:
    // Starts a scan and pulls the plug once a tenth of it is done.
    static DriveDescription scanAndUnplug(Session &s, SimulatorServer &server)
    {
        QFutureWatcher<DriveDescription> watcher;
        bool unplugged = false;
        connect(&watcher, &QFutureWatcher<DriveDescription>::progressValueChanged, &server,
                [&](int value) {
                    if (!unplugged && value > watcher.progressMaximum() / 10) {
                        unplugged = true;
                        server.close();
                    }
                });
        watcher.setFuture(s.client->scan());
        if (!waitFinished(watcher.future(), 10000) || !unplugged || watcher.future().resultCount() == 0)
            return {};
        return watcher.future().result();
    }

    static void checkPartial(Session &s, const DriveDescription &drive)
    {
        QVERIFY2(!drive.incompleteReason.isEmpty(), "the scan claims to be complete");
        QVERIFY(!drive.groups.isEmpty());     // what was read is kept
        QVERIFY(drive.parameterCount() < 206); // and nothing is made up
        for (const GroupDescription &group : drive.groups) {
            for (const ParameterDescription &parameter : group.parameters)
                QVERIFY(!parameter.name.isEmpty() || !parameter.error.isEmpty());
        }
        // The client reports the lost link through its own queued signals.
        QTRY_COMPARE_WITH_TIMEOUT(s.client->state(), DriveClient::State::Lost, 3000);
    }

private slots:
    void gatewayConnectionClosedMidScan()
    {
        SimulationOptions simulation;
        simulation.replyLatencyUs = 2000;
        SimulatorServer server(Protocol::Hsp5, simulation);
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = server.tcpPort();
        ClientOptions options;
        options.timeoutMs = 10000; // the lost link, not a timeout, must end it
        Session s(settings, options);
        QVERIFY(s.connected());
        QSignalSpy lost(s.client.get(), &DriveClient::linkLost);

        const DriveDescription drive = scanAndUnplug(s, server);
        checkPartial(s, drive);
        QVERIFY2(drive.incompleteReason.contains(QStringLiteral("closed")), qPrintable(drive.incompleteReason));
        QTRY_COMPARE_WITH_TIMEOUT(lost.size(), 1, 3000);
    }

    void serialAdapterUnpluggedMidScan()
    {
        QTemporaryDir dir;
        const QString device = dir.filePath(QStringLiteral("ttyDrive"));
        SimulationOptions simulation;
        simulation.replyLatencyUs = 2000;
        SimulatorServer server(Protocol::Din66019II, simulation);
        QString error;
        QVERIFY2(server.listenPty(device, &error), qPrintable(error));
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Serial;
        settings.device = device;
        settings.protocol = Protocol::Din66019II;
        ClientOptions options;
        options.timeoutMs = 10000;
        Session s(settings, options);
        QVERIFY(s.connected());

        const DriveDescription drive = scanAndUnplug(s, server);
        checkPartial(s, drive);
    }
};

QTEST_GUILESS_MAIN(TestClientUnplug)
#include "tst_clientunplug.moc"
