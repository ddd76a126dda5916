#include "ClientTestSupport.h"
#include "Translations.h"

#include "client/FindDrivesJob.h"

#include <QFutureWatcher>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

SimulationOptions bus(QList<int> addresses)
{
    SimulationOptions options = fast();
    options.driveAddresses = std::move(addresses);
    return options;
}

// The Sent records that carried an EOT selection, by drive address.
QList<int> selections(const QList<TrafficRecord> &records)
{
    QList<int> addresses;
    for (const TrafficRecord &record : records) {
        if (record.kind == TrafficRecord::Kind::Sent && record.bytes.startsWith('\x04'))
            addresses.append(record.bytes.mid(1, 2).toInt(nullptr, 16));
    }
    return addresses;
}

QList<int> addressesOf(const QFuture<FoundDrive> &search)
{
    QList<int> addresses;
    for (int i = 0; i < search.resultCount(); ++i)
        addresses.append(search.resultAt(i).address);
    return addresses;
}

} // namespace

// What only the multi-drop ASCII protocols have: drive selection, invoke ids 1..F, the legacy
// DIN66019 telegrams, the search for drives, group and broadcast writes.
class TestClientDin : public QObject
{
    Q_OBJECT
private slots:
    // English as the programs show it: with its catalogue, which holds the plural forms.
    void initTestCase() { QVERIFY(installTranslations(QStringLiteral("en"))); }

    void selectionIsSentOnlyWhenItMayBeGone()
    {
        Session s(simulated(Protocol::Din66019II, bus({1, 2})));
        QVERIFY(s.connected());
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
        QVERIFY(s.call(s.client->readValue(kMotorVoltage, 1)).ok());
        QCOMPARE(selections(s.records()), QList<int>{1});

        // A negative read answer ends with EOT: the drive dropped the selection.
        QCOMPARE(s.call(s.client->readValue(kMaxSpeedForward, 0)).ack(), Ack::SetInvalid);
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
        QCOMPARE(selections(s.records()), (QList<int>{1, 1}));

        // A negative write answer (NAK) keeps it.
        QCOMPARE(s.call(s.client->writeValue(kMaxSpeedForward, 9999, 1)).ack(), Ack::DataInvalid);
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
        QCOMPARE(selections(s.records()), (QList<int>{1, 1}));

        // A request's own drive address overrides the settings'.
        const Reply other = s.request(Service::ParameterValue, Access::Write,
                                      ParameterValue{kMaxSpeedForward, 1, 1234}, 2);
        QVERIFY2(other.ok(), qPrintable(describeReply(other)));
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
        QCOMPARE(selections(s.records()), (QList<int>{1, 1, 2, 1}));
        const Reply onTwo = s.request(Service::ParameterValue, Access::Read,
                                      ParameterValue{kMaxSpeedForward, 1, 0}, 2);
        QCOMPARE(onTwo.data<ParameterValue>()->value, 1234);
        QCOMPARE(valueOf(s.call(s.client->readValue(kMaxSpeedForward, 1))),
                 kMaxSpeedDefault);
    }

    void invokeIdsRunFromOneToFifteen()
    {
        Session s(simulated(Protocol::Din66019II, fast()));
        QVERIFY(s.connected());
        QList<int> ids;
        for (int i = 0; i < 17; ++i) {
            const Reply reply = s.call(s.client->readValue(kMaxSpeedForward, 1));
            QVERIFY2(reply.ok(), qPrintable(describeReply(reply)));
            ids.append(reply.request.operatorInvoke);
        }
        QCOMPARE(ids, (QList<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 1, 2}));
    }

    void legacyDin66019Values()
    {
        Session s(simulated(Protocol::Din66019, fast()));
        QVERIFY(s.connected());
        Reply read = s.call(s.client->readValueStandard(kMaxSpeedForward, 0));
        QVERIFY2(read.ok(), qPrintable(describeReply(read)));
        QCOMPARE(read.request.service, Service::Legacy);
        QCOMPARE(read.data<ParameterValue>()->value, kMaxSpeedDefault);

        const Reply written = s.call(s.client->writeValueStandard(kMaxSpeedForward, 1800, 0));
        QVERIFY2(written.ok(), qPrintable(describeReply(written)));
        read = s.call(s.client->readValueStandard(kMaxSpeedForward, 0));
        QCOMPARE(read.data<ParameterValue>()->value, 1800);

        const Reply readOnly = s.call(s.client->writeValueStandard(kRatedCurrent, 1, 0));
        QCOMPARE(readOnly.status, Reply::Status::Refused);
        QCOMPARE(readOnly.ack(), Ack::WriteProtected);
        const Reply outOfLimits = s.call(s.client->writeValueStandard(kMaxSpeedForward, 4001, 0));
        QCOMPARE(outOfLimits.ack(), Ack::DataInvalid);
        // The drive still answers after the refusals.
        const Reply after = s.call(s.client->readValueStandard(kRatedCurrent, 0));
        QCOMPARE(after.data<ParameterValue>()->value, 105);
    }

    void findDrivesFindsExactlyTheDrivesOnTheBus()
    {
        Session s(simulated(Protocol::Din66019II, bus({1, 5, 17})));
        QVERIFY(s.connected());
        QFuture<FoundDrive> search
            = s.client->run(std::make_shared<FindDrivesJob>(s.client->settings()));
        QVERIFY(waitFinished(search, 60000));
        QCOMPARE(addressesOf(search), (QList<int>{1, 5, 17}));
        QCOMPARE(search.progressMaximum(), 240);
        QCOMPARE(search.progressValue(), 240);
        // The client keeps working afterwards.
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
    }

    void findDrivesReportsEachDriveAsItAnswers()
    {
        Session s(simulated(Protocol::Din66019II, bus({1, 5, 17})));
        QVERIFY(s.connected());
        auto job = std::make_shared<FindDrivesJob>(s.client->settings());
        QFutureWatcher<FoundDrive> watcher;
        int askedWhenFirstCame = -1;
        connect(&watcher, &QFutureWatcherBase::resultReadyAt, this, [&](int index) {
            if (index == 0)
                askedWhenFirstCame = watcher.progressValue();
        });
        watcher.setFuture(s.client->run(job));
        QTRY_VERIFY_WITH_TIMEOUT(askedWhenFirstCame >= 0, kWaitMs);
        // Drive 1 came while 240 addresses were still to be asked, not with the end.
        QVERIFY2(askedWhenFirstCame < 240, qPrintable(QString::number(askedWhenFirstCame)));
        const FoundDrive first = watcher.future().resultAt(0);
        QCOMPARE(first.address, 1);
        // What the drive says about itself: its identification parameters, as it shows them.
        QCOMPARE(first.inverterIdentifier, QStringLiteral("0F51h"));
        QCOMPARE(first.softwareVersion, QStringLiteral("1.82"));
        QVERIFY(!first.serialNumber.isEmpty());
        QVERIFY2(first.identification().contains(QStringLiteral("software 1.82")),
                 qPrintable(first.identification()));
        watcher.cancel();
        QVERIFY(waitFinished(watcher.future()));
    }

    void findDrivesStoppedKeepsTheDrivesFound()
    {
        Session s(simulated(Protocol::Din66019II, bus({1, 5, 17})));
        QVERIFY(s.connected());
        auto job = std::make_shared<FindDrivesJob>(s.client->settings());
        QFutureWatcher<FoundDrive> watcher;
        // Stop once drive 5 is reported: every drive found before stays reported.
        connect(&watcher, &QFutureWatcherBase::resultReadyAt, this, [&](int index) {
            if (watcher.future().resultAt(index).address == 5)
                job->requestStop();
        });
        watcher.setFuture(s.client->run(job));
        QVERIFY(waitFinished(watcher.future(), 60000));
        QVERIFY(!watcher.future().isCanceled());
        const QList<int> found = addressesOf(watcher.future());
        QCOMPARE(found.mid(0, 2), (QList<int>{1, 5}));
        QVERIFY2(watcher.future().progressValue() < 240,
                 qPrintable(QString::number(watcher.future().progressValue())));
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
    }

    void findDrivesInLegacyDin66019()
    {
        Session s(simulated(Protocol::Din66019, bus({3})));
        QVERIFY(s.connected());
        QFuture<FoundDrive> search
            = s.client->run(std::make_shared<FindDrivesJob>(s.client->settings(), 0, 7));
        QVERIFY(waitFinished(search));
        QCOMPARE(addressesOf(search), QList<int>{3});
        // No service 5 in DIN66019: the values as they came.
        QCOMPARE(search.resultAt(0).softwareVersion, QStringLiteral("182"));
    }

    void findDrivesCanBeCancelled()
    {
        Session s(simulated(Protocol::Din66019II, bus({1})));
        QVERIFY(s.connected());
        QFuture<FoundDrive> search
            = s.client->run(std::make_shared<FindDrivesJob>(s.client->settings()));
        QTRY_VERIFY(search.progressValue() >= 3);
        search.cancel();
        QVERIFY(waitFinished(search, 2000));
        QVERIFY(search.isCanceled());
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 1)).ok());
    }

    void broadcastWriteIsCarriedOutByAllAndNeverAnswered()
    {
        Session s(simulated(Protocol::Din66019II, bus({1, 5, 17})));
        QVERIFY(s.connected());
        const Reply broadcast = s.request(Service::ParameterValue, Access::Write,
                                          ParameterValue{kMaxSpeedForward, 1, 2222}, 0xFF);
        QCOMPARE(broadcast.status, Reply::Status::NoReply);
        QVERIFY(broadcast.message().contains(QStringLiteral("never answer")));
        for (int drive : {1, 5, 17}) {
            const Reply read = s.request(Service::ParameterValue, Access::Read,
                                         ParameterValue{kMaxSpeedForward, 1, 0}, drive);
            QVERIFY2(read.ok(), qPrintable(describeReply(read)));
            QCOMPARE(read.data<ParameterValue>()->value, 2222);
        }

        // Group 0 (F0h) holds drives 0..15.
        const Reply group = s.request(Service::ParameterValue, Access::Write,
                                      ParameterValue{kMaxSpeedForward, 1, 1111}, 0xF0);
        QCOMPARE(group.status, Reply::Status::NoReply);
        const auto valueOn = [&s](int drive) {
            return valueOf(s.request(Service::ParameterValue, Access::Read,
                                     ParameterValue{kMaxSpeedForward, 1, 0}, drive));
        };
        QCOMPARE(valueOn(1), 1111);
        QCOMPARE(valueOn(5), 1111);
        QCOMPARE(valueOn(17), 2222);
    }

    void readsFromGroupsAreRefusedBeforeSending()
    {
        Session s(simulated(Protocol::Din66019II, fast()));
        QVERIFY(s.connected());
        const Reply read = s.request(Service::ParameterValue, Access::Read,
                                     ParameterValue{kMaxSpeedForward, 1, 0}, 0xFF);
        QCOMPARE(read.status, Reply::Status::Unsupported);
        QVERIFY2(read.detail.contains(QStringLiteral("writes only")), qPrintable(read.detail));
        const Reply nowhere = s.request(Service::ParameterValue, Access::Read,
                                        ParameterValue{kMaxSpeedForward, 1, 0}, 300);
        QCOMPARE(nowhere.status, Reply::Status::Unsupported);
        QVERIFY(nowhere.detail.contains(QStringLiteral("300")));
    }

    void absentDriveTimesOutWithAClearMessage()
    {
        ClientOptions options;
        options.retries = 1;
        options.timeoutMs = 40;
        Session s(simulated(Protocol::Din66019II, fast()), options);
        QVERIFY(s.connected());
        const Reply reply = s.request(Service::ParameterValue, Access::Read,
                                      ParameterValue{kMaxSpeedForward, 1, 0}, 9);
        QCOMPARE(reply.status, Reply::Status::Timeout);
        QCOMPARE(reply.attempts, 2);
        QCOMPARE(reply.message(), QStringLiteral("no valid answer from the drive after 2 attempts "
                                                 "(2 timeouts; timeout 40 ms)"));
    }
};

QTEST_GUILESS_MAIN(TestClientDin)
#include "tst_clientdin.moc"
