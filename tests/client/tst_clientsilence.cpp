#include "ClientTestSupport.h"

#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"
#include "client/ClientTiming.h"
#include "parameters/ParameterProperties.h"
#include "session/DownloadRun.h"
#include "session/ValueChange.h"

#include <QElapsedTimer>
#include <QFutureWatcher>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

namespace {

// How long a job may take from the freeze to its end: the client's bound, the check that goes
// out after the stop, and room for a busy machine.
int allowedMs(const ConnectionSettings &settings)
{
    const ClientOptions options;
    return silenceLimitMs(settings, options) + 2 * answerTimeoutMs(settings, options) + 1500;
}

} // namespace

// A drive that freezes behind an open connection: every job ends within a bound of seconds,
// with the reason, instead of spending every attempt on every request it still has.
class TestClientSilence : public QObject
{
    Q_OBJECT
private slots:
    void theBoundFollowsTheLine_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<int>("baud");
        QTest::addColumn<bool>("tcp");
        QTest::addColumn<int>("timeoutMs");
        QTest::addColumn<int>("limitMs");
        // The figures of docs/client.md, "A drive that stops answering".
        QTest::newRow("hsp5 38400") << Protocol::Hsp5 << 38400 << false << 92 << 1980;
        QTest::newRow("hsp5 9600") << Protocol::Hsp5 << 9600 << false << 215 << 5063;
        QTest::newRow("din 38400") << Protocol::Din66019II << 38400 << false << 123 << 2091;
        QTest::newRow("din 9600") << Protocol::Din66019II << 9600 << false << 342 << 5814;
        QTest::newRow("hsp5 tcp 38400") << Protocol::Hsp5 << 38400 << true << 242 << 4770;
    }

    void theBoundFollowsTheLine()
    {
        QFETCH(Protocol, protocol);
        QFETCH(int, baud);
        QFETCH(bool, tcp);
        QFETCH(int, timeoutMs);
        QFETCH(int, limitMs);
        ConnectionSettings settings;
        settings.kind = tcp ? ConnectionSettings::Kind::Tcp : ConnectionSettings::Kind::Serial;
        settings.protocol = protocol;
        settings.baudRate = baud;
        QCOMPARE(answerTimeoutMs(settings, {}), timeoutMs);
        QCOMPARE(silenceLimitMs(settings, {}), limitMs);
    }

    void aScanEndsWithinTheBound_data() { protocols(); }
    void aScanEndsWithinTheBound()
    {
        QFETCH(Protocol, protocol);
        QFETCH(bool, upload);
        SimulatorServer server(protocol, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, protocol));
        QVERIFY(s.connected());
        QSignalSpy stopped(s.client.get(), &DriveClient::driveStoppedAnswering);

        ScanOptions options;
        options.parameterList = upload;
        QFutureWatcher<DriveDescription> watcher;
        QElapsedTimer sinceFreeze;
        connect(&watcher, &QFutureWatcherBase::progressValueChanged, this, [&](int value) {
            if (value >= 150 && !server.bus().isSilent()) {
                server.bus().setSilent(true);
                sinceFreeze.start();
            }
        });
        watcher.setFuture(s.client->scan(options));
        QVERIFY(waitFinished(watcher.future(), 60000));
        const qint64 took = sinceFreeze.elapsed();
        QVERIFY2(sinceFreeze.isValid(), "the scan ended before the drive froze");
        QVERIFY2(took < allowedMs(s.client->settings()),
                 qPrintable(QStringLiteral("%1 ms after the freeze").arg(took)));
        const DriveDescription drive = watcher.future().result();
        QVERIFY(!drive.incompleteReason.isEmpty());
        QVERIFY(!drive.groups.isEmpty()); // what was read is kept

        QCOMPARE(stopped.size(), 1);
        const QString reason = stopped.first().at(0).toString();
        QVERIFY2(reason.contains(QRegularExpression(
                     QStringLiteral("^no answer to \\d+ request.* in [0-9.]+ s$"))),
                 qPrintable(reason));
        QVERIFY(s.client->isDriveSilent());
        QCOMPARE(s.client->state(), DriveClient::State::Connected);
        // The scan says why it stopped, not the first of its timeouts "and N more".
        QVERIFY2(drive.incompleteReason.startsWith(QStringLiteral("the drive stopped answering")),
                 qPrintable(drive.incompleteReason));

        // The drive comes back: the next request is the check, answered, and all is as before.
        server.bus().setSilent(false);
        const Reply back = s.call(s.client->readValue(kMotorVoltage, 1));
        QVERIFY2(back.ok(), qPrintable(back.message()));
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
        QTRY_VERIFY(!s.client->isDriveSilent());
    }

    void requestsMadeWhileStoppedFailAtOnce_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<int>("retries");
        QTest::addColumn<int>("requestsToStop");
        QTest::newRow("hsp5") << Protocol::Hsp5 << 3 << kUnansweredRequestsToStop;
        QTest::newRow("din66019ii") << Protocol::Din66019II << 3 << kUnansweredRequestsToStop;
        // Without retries, a stop needs as many attempts as with them: 8 requests, not 4.
        QTest::newRow("hsp5 no retries") << Protocol::Hsp5 << 0 << kUnansweredAttemptsToStop;
        QTest::newRow("din66019ii no retries")
            << Protocol::Din66019II << 0 << kUnansweredAttemptsToStop;
    }
    void requestsMadeWhileStoppedFailAtOnce()
    {
        QFETCH(Protocol, protocol);
        QFETCH(int, retries);
        QFETCH(int, requestsToStop);
        SimulatorServer server(protocol, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        ClientOptions options;
        options.retries = retries;
        Session s(tcpTo(server, protocol), options);
        QVERIFY(s.connected());
        server.bus().setSilent(true);
        QList<QFuture<Reply>> reads;
        for (int i = 0; i < 40; ++i)
            reads << s.client->readValue(kMotorVoltage, 1);
        QElapsedTimer timer;
        timer.start();
        for (const QFuture<Reply> &read : reads)
            QVERIFY(waitFinished(read, 60000));
        QVERIFY2(timer.elapsed() < allowedMs(s.client->settings()),
                 qPrintable(QStringLiteral("%1 ms").arg(timer.elapsed())));
        int timeouts = 0;
        int silent = 0;
        for (const QFuture<Reply> &read : reads) {
            const Reply reply = read.result();
            timeouts += reply.status == Reply::Status::Timeout;
            if (reply.status == Reply::Status::DriveSilent) {
                ++silent;
                QVERIFY2(reply.message().startsWith(
                             QStringLiteral("the drive stopped answering: no answer to")),
                         qPrintable(reply.message()));
                QVERIFY(reply.isConnectionFailure());
            }
        }
        QCOMPARE(timeouts, requestsToStop - 1);
        QCOMPARE(silent, int(reads.size()) - timeouts);

        // While stopped: one request goes out once, the others fail at once.
        const QFuture<Reply> check = s.client->readValue(kMotorVoltage, 1);
        const QFuture<Reply> meanwhile = s.client->readValue(kMaxSpeedForward, 1);
        QVERIFY(waitFinished(meanwhile, 200));
        QCOMPARE(meanwhile.result().status, Reply::Status::DriveSilent);
        const Reply checked = replyOf(check);
        QCOMPARE(checked.status, Reply::Status::DriveSilent);
        QCOMPARE(checked.attempts, 1);
    }

    void aWriteEndsWithinTheBound_data() { bothProtocols(); }
    void aWriteEndsWithinTheBound()
    {
        QFETCH(Protocol, protocol);
        SimulatorServer server(protocol, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, protocol));
        QVERIFY(s.connected());
        ValueChange change;
        change.address = kMaxSpeedForward;
        change.setProgrammable = true;
        for (int set = 0; set < kParameterSets; ++set)
            change.steps.append(WriteStep { quint8(1u << set), 2000 + set, false });

        server.bus().setSilent(true);
        QElapsedTimer timer;
        timer.start();
        const QFuture<WriteOutcome> written
            = s.client->run(std::make_shared<WriteValueJob>(protocol, change));
        QVERIFY(waitFinished(written, 60000));
        QVERIFY2(timer.elapsed() < allowedMs(s.client->settings()),
                 qPrintable(QStringLiteral("%1 ms").arg(timer.elapsed())));
        const WriteOutcome outcome = written.result();
        QVERIFY(!outcome.anyAcknowledged());
        QVERIFY(outcome.connectionFailed);
        QVERIFY2(!outcome.error.isEmpty(), "no reason given");
        QCOMPARE(s.client->isDriveSilent(), true);
    }

    void aDownloadEndsWithinTheBound_data() { bothProtocols(); }
    void aDownloadEndsWithinTheBound()
    {
        QFETCH(Protocol, protocol);
        SimulatorServer server(protocol, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, protocol));
        QVERIFY(s.connected());
        // A few groups of settings keep it short; the drive's kind is in others.
        ScanOptions reading;
        reading.groupPages = { quint8(kMaxSpeedForward >> 8), quint8(kCurrentLimit >> 8),
                               quint8(kMotorVoltage >> 8) };
        const QFuture<DriveDescription> scanned = s.client->scan(reading);
        QVERIFY(waitFinished(scanned, 60000));
        DriveDescription file = scanned.result();
        QVERIFY2(file.incompleteReason.isEmpty(), qPrintable(file.incompleteReason));
        // Every writable value of every set one step from where it is: a long download.
        int changed = 0;
        for (GroupDescription &group : file.groups) {
            for (ParameterDescription &parameter : group.parameters) {
                const ParameterProperties properties(parameter.properties1, parameter.properties2);
                if (properties.isReadOnly() || !parameter.plaintexts.isEmpty())
                    continue;
                for (std::optional<qint32> &value : parameter.values) {
                    if (value && *value < parameter.maximum) {
                        *value = *value + 1;
                        ++changed;
                    }
                }
            }
        }
        QVERIFY(changed > 50);

        DownloadRun run(s.client.get(), protocol, file);
        std::optional<DownloadPlan> planned;
        std::optional<DownloadReport> report;
        QString failed;
        connect(&run, &DownloadRun::planned, this,
                [&](const DownloadPlan &plan) { planned = plan; });
        connect(&run, &DownloadRun::failed, this, [&](const QString &why) { failed = why; });
        connect(&run, &DownloadRun::finished, this,
                [&](const DownloadReport &written) { report = written; });
        // Frozen when the fifth write went out: counted in telegrams, which the drive answers
        // from this thread, not in progress reports, which come at most 25 times a second and
        // may not come before a quick download is over.
        QElapsedTimer sinceFreeze;
        int writesSent = 0;
        connect(s.client.get(), &DriveClient::traffic, this, [&](const TrafficRecord &record) {
            if (record.kind == TrafficRecord::Kind::Sent && record.telegram
                && record.telegram->isWrite() && ++writesSent == 5) {
                server.bus().setSilent(true);
                sinceFreeze.start();
            }
        });
        DownloadOptions forced; // the drive's kind is in the groups left out
        forced.force = true;
        run.setOptions(forced);
        run.start(reading);
        QTRY_VERIFY_WITH_TIMEOUT(planned || !failed.isEmpty(), 60000);
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
        QVERIFY2(!planned->isRefused(), qPrintable(planned->problems.join(QLatin1Char('\n'))));
        QVERIFY(planned->items.size() > 20);
        run.write();
        QTRY_VERIFY_WITH_TIMEOUT(report.has_value(), 60000);
        QVERIFY2(sinceFreeze.isValid(), "the download ended before the drive froze");
        QVERIFY2(sinceFreeze.elapsed() < allowedMs(s.client->settings()),
                 qPrintable(QStringLiteral("%1 ms after the freeze").arg(sinceFreeze.elapsed())));
        QVERIFY(!report->isComplete());
        QVERIFY2(report->text().contains(QStringLiteral("stopped answering")),
                 qPrintable(report->text()));
    }

private:
    static void bothProtocols()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }

    static void protocols()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<bool>("upload");
        QTest::newRow("hsp5") << Protocol::Hsp5 << false;
        QTest::newRow("hsp5 upload") << Protocol::Hsp5 << true;
        QTest::newRow("din66019ii") << Protocol::Din66019II << false;
        QTest::newRow("din66019ii upload") << Protocol::Din66019II << true;
    }
};

QTEST_GUILESS_MAIN(TestClientSilence)
#include "tst_clientsilence.moc"
