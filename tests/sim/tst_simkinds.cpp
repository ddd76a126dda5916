#include "SimRequests.h"

#include <QTest>

using namespace DriveDesk;
using namespace SimRequests;

namespace {

constexpr quint16 kFixedSpeed1 = 0x0314;      // op.20, set-programmable
constexpr quint16 kAccelerationTime = 0x031C; // op.28, set-programmable
constexpr quint16 kQuickStopTime = 0x0323;     // op.35, set-programmable
constexpr quint16 kSetValueSource = 0x0301;   // op.01
constexpr quint16 kActualSpeed = 0x0207;      // ru.07, live
constexpr quint16 kInverterIdentifier = 0x0002; // Sy.02
constexpr quint16 kSoftwareVersion = 0x0E06;    // In.06
constexpr quint16 kMaximumCurrent = 0x0E02;     // In.02, no identification parameter
constexpr quint8 kIdentifyFunction = 1;         // service 13

SimulatedDrive driveAt(int address, SimulatedDriveKind kind = SimulatedDriveKind::Standard)
{
    SimulatedDriveOptions options;
    options.address = address;
    options.kind = kind;
    return SimulatedDrive(options);
}

QList<qint32> settingsOf(const SimulatedDrive &drive)
{
    QList<qint32> values;
    for (quint16 address : {kFixedSpeed1, kAccelerationTime, kQuickStopTime}) {
        for (int set = 0; set < 8; ++set)
            values.append(drive.value(address, set).value_or(-1));
    }
    return values;
}

Telegram identify()
{
    return read(Service::Fieldbus, FieldbusData { kIdentifyFunction, 0, 0, {} });
}

} // namespace

// Drives that differ: user settings by address, another kind, a drive with no identification.
class TestSimKinds : public QObject
{
    Q_OBJECT
private slots:
    void userSettingsFollowTheAddress()
    {
        // Drive 1 keeps the data's values.
        const SimulatedDrive first = driveAt(1);
        QCOMPARE(first.value(kAccelerationTime, 0), 500);
        QCOMPARE(first.value(kQuickStopTime, 3), 50);
        QCOMPARE(first.value(kFixedSpeed1, 7), 100);

        const SimulatedDrive two = driveAt(2);
        const SimulatedDrive five = driveAt(5);
        QCOMPARE(five.value(kAccelerationTime, 0), 600);
        QCOMPARE(five.value(kQuickStopTime, 0), 70);
        QCOMPARE(five.value(kFixedSpeed1, 0), 140);
        QVERIFY(settingsOf(two) != settingsOf(five));
        QVERIFY(settingsOf(two) != settingsOf(first));
        // The same address, the same drive: a backup of it is reproducible.
        QCOMPARE(settingsOf(driveAt(5)), settingsOf(five));
        // Within limits at both ends of the address range.
        for (int address : {0, 239}) {
            SimulatedDrive drive = driveAt(address);
            for (quint16 parameter : {kFixedSpeed1, kAccelerationTime, kQuickStopTime}) {
                const qint32 value = *drive.value(parameter, 0);
                QCOMPARE(drive.respond(writeValue(parameter, value, 0x01), 0).ack, Ack::Ok);
            }
        }
    }

    void liveValuesStayLive()
    {
        SimulatedDrive five = driveAt(5);
        QCOMPARE(five.value(kSetValueSource, 0), driveAt(1).value(kSetValueSource, 0));
        // The demo cycle runs the motor on every drive.
        five.respond(readValue(kActualSpeed), 0);
        const Telegram later = five.respond(readValue(kActualSpeed), 5000);
        QCOMPARE(later.ack, Ack::Ok);
        QVERIFY(valueOf(later) != 0);
    }

    void otherKindHasOtherMetadata()
    {
        SimulatedDrive standard = driveAt(2);
        SimulatedDrive other = driveAt(9, SimulatedDriveKind::Other);
        QVERIFY(other.parameterCount() > standard.parameterCount());
        QVERIFY(other.groupCount() > standard.groupCount());
        QVERIFY(*other.value(kSoftwareVersion, 0) > *standard.value(kSoftwareVersion, 0));
        QVERIFY(other.identification() != standard.identification());
        // Two drives of the other kind, with seeds of their own: the same metadata.
        SimulatedDriveOptions options;
        options.kind = SimulatedDriveKind::Other;
        options.seed = 7;
        options.metadataSeed = 1;
        SimulatedDrive again(options);
        for (quint16 address = 0x2000; address < 0x2000 + 24; ++address) {
            const Telegram limits = read(Service::Limits, ParameterLimits { address });
            QCOMPARE(again.respond(limits, 0), other.respond(limits, 0));
        }
    }

    void unidentifiedDriveHasNoIdentification()
    {
        SimulatedDrive bare = driveAt(3, SimulatedDriveKind::Unidentified);
        SimulatedDrive standard = driveAt(3);
        QCOMPARE(bare.parameterCount(), standard.parameterCount() - 8);
        QVERIFY(!bare.value(kInverterIdentifier, 0));
        QVERIFY(!bare.value(kSoftwareVersion, 0));
        QVERIFY(bare.respond(readValue(kSoftwareVersion), 0).ack != Ack::Ok);
        QCOMPARE(bare.respond(identify(), 0).ack, Ack::ServiceNotAvailable);
        QVERIFY(bare.identification().isEmpty());
        // Everything else is still there.
        QCOMPARE(bare.respond(readValue(kMaximumCurrent), 0).ack, Ack::Ok);
        QCOMPARE(bare.value(kAccelerationTime, 0), standard.value(kAccelerationTime, 0));
        QCOMPARE(standard.respond(identify(), 0).ack, Ack::Ok);
    }
};

QTEST_GUILESS_MAIN(TestSimKinds)
#include "tst_simkinds.moc"
