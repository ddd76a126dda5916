#include "ClientTestSupport.h"

#include "parameters/DriveIdentity.h"
#include "protocol/hsp5/Hsp5Codec.h"
#include "protocol/hsp5/Hsp5Layout.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

// The services of the requests the client put on the line, read back as a drive that knows
// DriveDesk's extensions would read them (so that an extension shows up as what it is).
QList<Service> sentServices(const Session &session)
{
    return ClientTest::sentServices(session.records(), Hsp5Codec(Hsp5Services::WithExtensions));
}

QStringList errors(const Session &session)
{
    QStringList list;
    for (const TrafficRecord &record : session.records()) {
        if (record.kind == TrafficRecord::Kind::Error)
            list.append(record.meaning);
    }
    return list;
}

DriveDescription scanned(const Session &session, ScanOptions options)
{
    QFuture<DriveDescription> scan = session.client->scan(options);
    if (!waitFinished(scan, 120000))
        return {};
    return scan.result();
}

// op (set-programmable values) and In (the identification).
ScanOptions someGroups()
{
    ScanOptions options;
    options.groupPages = {0x03, 0x0E};
    return options;
}

} // namespace

// Against a drive that knows exactly the services of seed 000 over HSP5: it cannot frame any
// other, so one stray request would cost it (and everything pipelined behind it) its framing.
class TestClientSeedOnly : public QObject
{
    Q_OBJECT
private slots:
    void everyCommandUsesOnlyTheSeedsServices()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        QVERIFY(s.call(s.client->writeValue(kMaxSpeedForward, 2500, 0x02)).ok());
        const Reply read = s.call(s.client->readValue(kMaxSpeedForward, 0x02));
        QVERIFY2(read.ok(), qPrintable(describeReply(read)));
        QCOMPARE(read.data<ParameterValue>()->value, 2500);

        const DriveDescription drive = scanned(s, {});
        QVERIFY2(drive.incompleteReason.isEmpty(), qPrintable(drive.incompleteReason));
        QCOMPARE(drive.parameterCount(), 206);
        // No identification service over HSP5: the identification parameters name the drive.
        QCOMPARE(drive.identification, QString());
        QVERIFY2(DriveIdentity::summary(drive).contains(QStringLiteral("software 1.82")),
                 qPrintable(DriveIdentity::summary(drive)));
        QCOMPARE(drive.find(kMaxSpeedForward)->values[1], std::optional<qint32>(2500));
        QCOMPARE(drive.find(kMaxSpeedForward)->values[0], std::optional<qint32>(3000));

        const QList<Service> services = sentServices(s);
        QVERIFY(services.size() > 1000);
        for (Service service : services) {
            QVERIFY2(hsp5Layout(service, Access::Read, Direction::Request)
                         || hsp5Layout(service, Access::Write, Direction::Request),
                     qPrintable(serviceName(service)));
        }
        QVERIFY2(errors(s).isEmpty(), qPrintable(errors(s).join(QLatin1Char('\n'))));
    }

    void setsAreReadTogetherWhereTheyAgree()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        QVERIFY(s.call(s.client->writeValue(kMotorVoltage, 230, 0x20)).ok()); // set 5 only
        ScanOptions options;
        options.onlyParameters = {kMaxSpeedForward, kMotorVoltage};
        options.groupPages = {0x03, 0x06};
        const DriveDescription drive = scanned(s, options);
        QVERIFY2(drive.incompleteReason.isEmpty(), qPrintable(drive.incompleteReason));
        for (int set = 0; set < kParameterSets; ++set) {
            QCOMPARE(drive.find(kMaxSpeedForward)->values[set], std::optional<qint32>(3000));
            QCOMPARE(drive.find(kMotorVoltage)->values[set],
                     std::optional<qint32>(set == 5 ? 230 : 400));
        }
        // op.11: one read over sets 0-7; dr.04: FFh, 0Fh, F0h, 30h, C0h, 10h, 20h.
        const QList<Service> services = sentServices(s);
        QCOMPARE(services.count(Service::ParameterValue), 1 + 1 + 7);
    }

    void theIdentificationServiceOnlyWhereTheUserOptsIn()
    {
        // Seed 003 marks DIN66019II's service 13 reserved: not sent unless asked for.
        Session din(simulated(Protocol::Din66019II, fast()));
        QVERIFY(din.connected());
        QCOMPARE(scanned(din, someGroups()).identification, QString());
        QVERIFY(!ClientTest::sentServices(din.records(), *makeCodec(Protocol::Din66019II))
                     .contains(Service::Fieldbus));
        ScanOptions optIn = someGroups();
        optIn.identificationText = true;
        QVERIFY(scanned(din, optIn).identification.contains(QStringLiteral("simulated")));

        ConnectionSettings settings = simulated(Protocol::Hsp5, fast());
        settings.hsp5Extensions = true;
        settings.simulation.hsp5Extensions = true;
        Session extended(settings);
        QVERIFY(extended.connected());
        const DriveDescription drive = scanned(extended, someGroups());
        QVERIFY(drive.identification.contains(QStringLiteral("simulated")));
        QVERIFY(sentServices(extended).contains(Service::Fieldbus));
    }

    void aDriveThatLostItsFramingIsBackWithinAFewTelegrams()
    {
        Session strict(simulated(Protocol::Hsp5, fast()));
        QVERIFY(strict.connected());
        const DriveDescription expected = scanned(strict, someGroups());
        QVERIFY(expected.incompleteReason.isEmpty());
        const qsizetype strictRequests = sentServices(strict).size();

        // A client told the drive has DriveDesk's extensions when it has not: its service 13
        // request breaks the drive's framing, and the requests pipelined behind it are lost.
        ConnectionSettings settings = simulated(Protocol::Hsp5, fast());
        settings.hsp5Extensions = true;
        Session s(settings);
        QVERIFY(s.connected());
        const DriveDescription drive = scanned(s, someGroups());
        QVERIFY2(drive.incompleteReason.isEmpty(), qPrintable(drive.incompleteReason));
        QCOMPARE(drive.identification, QString());
        QCOMPARE(drive.groups, expected.groups);
        const QStringList reported = errors(s);
        QVERIFY(std::any_of(reported.cbegin(), reported.cend(), [](const QString &error) {
            return error.contains(QStringLiteral("quiet line"));
        }));
        // Service 13's attempts and the requests lost with them: a handful of telegrams more.
        // The timeouts are errors on the line, so every answer after them is confirmed by a
        // second read: twice the telegrams, no more.
        const qsizetype requests = sentServices(s).size();
        QVERIFY2(requests <= 2 * strictRequests + 24,
                 qPrintable(QStringLiteral("%1 requests, %2 without the lost framing")
                                .arg(requests)
                                .arg(strictRequests)));
    }
};

QTEST_GUILESS_MAIN(TestClientSeedOnly)
#include "tst_clientseedonly.moc"
