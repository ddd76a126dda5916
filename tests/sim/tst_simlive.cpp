#include "SimRequests.h"

#include <QTest>

using namespace DriveDesk;
using namespace SimRequests;

namespace {

constexpr quint16 kState = 0x0200; // ru.00
constexpr quint16 kActualFrequency = 0x0203; // ru.03, 0.0125 Hz
constexpr quint16 kActualSpeed = 0x0207; // ru.07, 0.125 rpm
constexpr quint16 kCurrent = 0x020F; // ru.15, 0.1 A
constexpr quint16 kPeakCurrent = 0x0210; // ru.16
constexpr quint16 kDcVoltage = 0x0212; // ru.18
constexpr quint16 kHeatSink = 0x0214; // ru.20, degC + 40
constexpr quint16 kSetValueSource = 0x0301; // op.01
constexpr quint16 kCommandSpeed = 0x0303; // op.03
constexpr quint16 kAccelerationTime = 0x031C; // op.28
constexpr quint16 kActiveSet = 0x0902; // Fr.02
constexpr quint16 kScopeTimer = 0x0020; // Sy.32
constexpr quint16 kStatusLow = 0x0033; // Sy.51
constexpr quint16 kEncoderPosition = 0x1014; // Ec.20
constexpr quint16 kReadChannel1 = 0x0010; // Sy.16; Sy.17 its set, Sy.18.. channel 2
constexpr quint16 kWriteChannel1 = 0x0018; // Sy.24; Sy.25 its set

enum State { NoP = 0, Facc = 64, Fdec = 65, Fcon = 66, RAcc = 67, RDec = 68, RCon = 69 };

// A multiple of the 20 s demo cycle, far from 0 like a monotonic clock.
constexpr qint64 kStart = 20000 * 1000;

void set(SimulatedDrive &drive, quint16 address, qint32 value, qint64 nowMs = kStart)
{
    const Telegram r = drive.respond(writeValue(address, value), nowMs);
    QVERIFY2(r.ack == Ack::Ok, qPrintable(describe(r)));
}

qint32 get(SimulatedDrive &drive, quint16 address, qint64 nowMs)
{
    return valueOf(drive.respond(readValue(address), nowMs));
}

// Asks the drive the time every 100 ms from `fromMs` to `toMs`, as a polling operator would.
void runUntil(SimulatedDrive &drive, qint64 fromMs, qint64 toMs)
{
    for (qint64 t = fromMs; t <= toMs; t += 100)
        drive.respond(readValue(kState), t);
}

// Runs the bus set value op.03 instead of the demo cycle.
void driveFromCommandSpeed(SimulatedDrive &drive)
{
    set(drive, kSetValueSource, 0);
}

} // namespace

// The live drive: the motor over time, ru.00 states, process data in and out, the scope
// channels of Sy.16..Sy.23, offline records and the parameter channel of services 50/53.
class TestSimLive : public QObject
{
    Q_OBJECT
private slots:
    void demoCycleRunsThroughTheStates()
    {
        SimulatedDrive drive;
        QList<int> states;
        qint32 highestSpeed = 0;
        qint32 lowestSpeed = 0;
        for (qint64 t = kStart; t <= kStart + 20000; t += 50) {
            const int state = get(drive, kState, t);
            if (states.isEmpty() || states.last() != state)
                states << state;
            highestSpeed = std::max(highestSpeed, get(drive, kActualSpeed, t));
            lowestSpeed = std::min(lowestSpeed, get(drive, kActualSpeed, t));
        }
        QCOMPARE(states, (QList<int> { NoP, Facc, Fcon, Fdec, RAcc, RCon, RDec, NoP }));
        QVERIFY(highestSpeed > 1400 * 8 && highestSpeed <= 1501 * 8); // 1500 rpm less slip
        QVERIFY(lowestSpeed < -950 * 8 && lowestSpeed >= -1001 * 8); // 2/3 of it in reverse
    }

    void measurementsFollowTheMotor()
    {
        SimulatedDrive drive;
        get(drive, kState, kStart);
        // Standstill: no modulation, no current.
        QCOMPARE(get(drive, kCurrent, kStart + 500), 0);
        QCOMPARE(get(drive, kActualFrequency, kStart + 500), 0);
        const qint32 dcStill = get(drive, kDcVoltage, kStart + 500);
        QVERIFY(dcStill > 530 && dcStill < 550);
        const qint32 coldSink = get(drive, kHeatSink, kStart + 500);

        // Constant forward: 50 Hz = 1500 rpm at two pole pairs.
        QCOMPARE(get(drive, kState, kStart + 6000), int(Fcon));
        QCOMPARE(get(drive, kActualFrequency, kStart + 6000), 50 * 80);
        const qint32 running = get(drive, kCurrent, kStart + 6000);
        QVERIFY(running > 30);
        // Braking feeds the DC link.
        QCOMPARE(get(drive, kState, kStart + 9000), int(Fdec));
        QVERIFY(get(drive, kDcVoltage, kStart + 9000) > dcStill + 10);
        QVERIFY(get(drive, kEncoderPosition, kStart + 9000) != 0);

        for (qint64 t = kStart + 9000; t < kStart + 120000; t += 1000)
            get(drive, kState, t);
        QVERIFY(get(drive, kHeatSink, kStart + 120000) > coldSink);
        QVERIFY(get(drive, kPeakCurrent, kStart + 120000) >= running);

        // The peak value is reset by writing it.
        set(drive, kPeakCurrent, 0, kStart + 120500);
        QVERIFY(get(drive, kPeakCurrent, kStart + 120500) < 10);
    }

    void sameRequestsGiveSameAnswers()
    {
        SimulatedDrive a;
        SimulatedDrive b;
        for (qint64 t = kStart; t < kStart + 30000; t += 37) {
            for (quint16 address : { kState, kActualSpeed, kCurrent, kDcVoltage, kHeatSink })
                QCOMPARE(a.respond(readValue(address), t), b.respond(readValue(address), t));
        }
    }

    // Two simulated drives of a plant are two drives: each its serial number (In.10), eight
    // digits, the same at every read and again when made again; one given keeps it.
    void everyDriveHasASerialNumberOfItsOwn()
    {
        constexpr quint16 kSerialNumber = 0x0E0A;
        SimulatedDriveOptions second;
        second.address = 2;
        SimulatedDrive a;
        SimulatedDrive b(second);
        SimulatedDrive again;
        const qint32 serialA = get(a, kSerialNumber, kStart);
        QVERIFY(serialA >= 10000000 && serialA <= 99999999);
        QVERIFY(serialA != get(b, kSerialNumber, kStart));
        QCOMPARE(get(again, kSerialNumber, kStart), serialA);
        QCOMPARE(get(a, kSerialNumber, kStart + 5000), serialA);
        SimulatedDriveOptions given;
        given.serialNumber = 12345678;
        SimulatedDrive c(given);
        QCOMPARE(get(c, kSerialNumber, kStart), 12345678);
    }

    void motorFollowsCommandSpeedFromProcessData()
    {
        SimulatedDrive drive;
        driveFromCommandSpeed(drive);
        set(drive, kWriteChannel1, kCommandSpeed);
        set(drive, kReadChannel1, kActualSpeed);
        set(drive, kReadChannel1 + 2, kState);

        Telegram r = drive.respond(write(Service::ProcessData1, ProcessData32 { { 1000, 0 } }),
                                   kStart + 100);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(drive.value(kCommandSpeed, 0), 1000);

        r = drive.respond(read(Service::ProcessData1, ProcessData32 {}), kStart + 600);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(r.as<ProcessData32>()->values[1], int(Facc));
        const qint32 accelerating = r.as<ProcessData32>()->values[0];
        QVERIFY(accelerating > 0 && accelerating < 1000 * 8);

        r = drive.respond(read(Service::ProcessData1, ProcessData32 {}), kStart + 5000);
        QCOMPARE(r.as<ProcessData32>()->values[1], int(Fcon));
        QVERIFY(r.as<ProcessData32>()->values[0] > 950 * 8);

        // Outside op.03's limits: refused, nothing written.
        r = drive.respond(write(Service::ProcessData1, ProcessData32 { { 5000, 0 } }),
                          kStart + 5100);
        QCOMPARE(r.ack, Ack::DataInvalid);
        QCOMPARE(drive.value(kCommandSpeed, 0), 1000);

        // Reverse through 4 x 16 bit.
        r = drive.respond(write(Service::ProcessData2, ProcessData16 { { -500, 0, 0, 0 } }),
                          kStart + 5200);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(drive.value(kCommandSpeed, 0), -500);
        r = drive.respond(read(Service::ProcessData2, ProcessData16 {}), kStart + 12000);
        QCOMPARE(r.as<ProcessData16>()->values[1], qint16(RCon));
    }

    void rampTimeOfTheActiveSetApplies()
    {
        SimulatedDrive drive;
        driveFromCommandSpeed(drive);
        set(drive, kAccelerationTime, 0, kStart); // in set 0: no ramp
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 2000, 0x02), kStart).ack, Ack::Ok);
        set(drive, kCommandSpeed, 1500, kStart);
        QCOMPARE(get(drive, kActualFrequency, kStart + 1), 50 * 80);

        set(drive, kCommandSpeed, 0, kStart + 10);
        get(drive, kState, kStart + 10000);
        set(drive, kActiveSet, 1, kStart + 10000);
        QCOMPARE(get(drive, kStatusLow, kStart + 10000) >> 4 & 7, 1); // Sy.51 shows the set
        set(drive, kCommandSpeed, 1500, kStart + 10000);
        // 20 s per 100 Hz: 50 Hz take 10 s.
        const qint32 halfway = get(drive, kActualFrequency, kStart + 15000);
        QVERIFY2(qAbs(halfway - 25 * 80) <= 2, qPrintable(QString::number(halfway)));
        QCOMPARE(get(drive, kStatusLow, kStart + 15000) & 0x5, 0x5); // released, running
    }

    void scopeChannelsFollowSy16ToSy23()
    {
        SimulatedDrive drive;
        const qint64 t0 = kStart + 6000; // constant forward in the demo cycle
        runUntil(drive, kStart, t0);
        set(drive, kReadChannel1, kActualFrequency, t0);
        set(drive, kReadChannel1 + 2, kActualSpeed, t0);
        set(drive, kReadChannel1 + 4, kState, t0);
        set(drive, kReadChannel1 + 6, kCurrent, t0);

        Telegram r = drive.respond(read(Service::Scope, ScopeData {}), t0 + 3);
        QCOMPARE(r.ack, Ack::Ok);
        const auto *scope = r.as<ScopeData>();
        QCOMPARE(scope->timestamp, quint16((t0 + 3) & 0xFFFF));
        QCOMPARE(scope->wide[0], *drive.value(kActualFrequency, 0));
        QCOMPARE(scope->wide[1], *drive.value(kActualSpeed, 0));
        QCOMPARE(scope->narrow[0], qint16(Fcon));
        QCOMPARE(scope->narrow[1], qint16(*drive.value(kCurrent, 0)));
        QCOMPARE(get(drive, kScopeTimer, t0 + 3), qint32((t0 + 3) & 0xFFFF));

        // Channel 2 off, channel 1 to a set-programmable parameter in set 2 (Sy.17 = 04h).
        set(drive, kReadChannel1 + 2, -1, t0);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 1234, 0x04), t0).ack, Ack::Ok);
        set(drive, kReadChannel1, kAccelerationTime, t0);
        set(drive, kReadChannel1 + 1, 0x04, t0);
        r = drive.respond(read(Service::Scope, ScopeData {}), t0 + 10);
        QCOMPARE(r.as<ScopeData>()->wide[0], 1234);
        QCOMPARE(r.as<ScopeData>()->wide[1], 0);

        // Invalid channel targets: unknown, not permitted (Sy.32), above the password level.
        QCOMPARE(drive.respond(writeValue(kReadChannel1, 0x0299), t0).ack, Ack::DataInvalid);
        QCOMPARE(drive.respond(writeValue(kReadChannel1, kScopeTimer), t0).ack, Ack::DataInvalid);
        QCOMPARE(drive.respond(writeValue(kReadChannel1, 0x0E28), t0).ack, Ack::DataInvalid);
        QCOMPARE(drive.respond(writeValue(kWriteChannel1, kActualSpeed), t0).ack, Ack::DataInvalid);
        QCOMPARE(drive.respond(writeValue(kReadChannel1 + 1, 0), t0).ack, Ack::DataInvalid);
    }

    void scopeTimestampWraps()
    {
        SimulatedDrive drive;
        Telegram r = drive.respond(read(Service::Scope, ScopeData {}), 65534);
        QCOMPARE(r.as<ScopeData>()->timestamp, quint16(65534));
        r = drive.respond(read(Service::Scope, ScopeData {}), 65536 + 4);
        QCOMPARE(r.as<ScopeData>()->timestamp, quint16(4));
    }

    void offlineRecordsKeepTheLastTicks()
    {
        SimulatedDrive drive;
        set(drive, kReadChannel1, kActualFrequency, kStart);
        set(drive, kReadChannel1 + 2, kState, kStart);
        QCOMPARE(
            drive.respond(read(Service::ScopeRecord, ScopeRecordData { 1, 0, 0, {} }), kStart).ack,
            Ack::DataInvalid); // nothing recorded yet

        // Accelerating forward from 1 s: records rise by 10 ms.
        for (qint64 t = kStart + 1000; t <= kStart + 2000; t += 7)
            drive.respond(readValue(kState), t);
        Telegram r = drive.respond(read(Service::ScopeRecord, ScopeRecordData { 0, 0, 0, {} }),
                                   kStart + 2000);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(r.as<ScopeRecordData>()->timestamp, quint16((kStart + 2000) & 0xFFFF));
        QCOMPARE(r.as<ScopeRecordData>()->values[0], *drive.value(kActualFrequency, 0));

        r = drive.respond(read(Service::ScopeRecord, ScopeRecordData { 1, 0, 0, {} }),
                          kStart + 2000);
        QCOMPARE(r.ack, Ack::Ok);
        const quint16 highest = r.as<ScopeRecordData>()->timestamp;
        QCOMPARE(highest, quint16(63));
        qint32 previous = -1;
        for (quint16 index = 0; index <= highest; ++index) {
            r = drive.respond(read(Service::ScopeRecord, ScopeRecordData { 1, index, 0, {} }),
                              kStart + 2000);
            QCOMPARE(r.ack, Ack::Ok);
            QCOMPARE(r.as<ScopeRecordData>()->values[1], qint32(Facc));
            QVERIFY(r.as<ScopeRecordData>()->values[0] > previous);
            previous = r.as<ScopeRecordData>()->values[0];
        }
        QCOMPARE(previous, *drive.value(kActualFrequency, 0));
        QCOMPARE(drive
                     .respond(read(Service::ScopeRecord, ScopeRecordData { 1, 64, 0, {} }),
                              kStart + 2000)
                     .ack,
                 Ack::DataInvalid);
        QCOMPARE(
            drive
                .respond(read(Service::ScopeRecord, ScopeRecordData { 2, 0, 0, {} }), kStart + 2000)
                .ack,
            Ack::DataInvalid);
        QCOMPARE(drive.respond(write(Service::ScopeRecord, ScopeRecordData {}), kStart + 2000).ack,
                 Ack::ServiceNotAvailable);
    }

    void duplexProcessDataWritesThenReads()
    {
        SimulatedDrive drive;
        driveFromCommandSpeed(drive);
        set(drive, kWriteChannel1, kCommandSpeed);
        set(drive, kReadChannel1, kCommandSpeed);
        Telegram r = drive.respond(write(Service::ProcessDataDuplex1, ProcessData32 { { 700, 0 } }),
                                   kStart + 10);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(r.as<ProcessData32>()->values[0], 700);
        r = drive.respond(write(Service::ProcessDataDuplex2, ProcessData16 { { -300, 1, 2, 3 } }),
                          kStart + 20);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(r.as<ProcessData16>()->values[0], qint16(-300));
        r = drive.respond(write(Service::ProcessDataDuplex4, ProcessData32 { { 4001, 0 } }),
                          kStart + 30);
        QCOMPARE(r.ack, Ack::DataInvalid);
        QCOMPARE(r.as<ProcessData32>()->values[0], -300);
        // The duplex services have no read form.
        for (Service s : { Service::ProcessDataDuplex1, Service::ProcessDataDuplex2,
                           Service::ProcessDataDuplex3 })
            QCOMPARE(drive.respond(read(s, emptyDataFor(s)), kStart).ack, Ack::ServiceNotAvailable);
    }

    void parameterChannelOfServices50And53()
    {
        SimulatedDrive drive;
        driveFromCommandSpeed(drive);
        set(drive, kWriteChannel1, kCommandSpeed);
        set(drive, kReadChannel1, kCommandSpeed);
        for (Service s : { Service::ProcessDataDuplex3, Service::ProcessDataDuplex6 }) {
            // Read op.28 while writing the set speed.
            Telegram r = drive.respond(
                write(s, ProcessParameterData { 800, 0, 0, kAccelerationTime, 0 }), kStart + 10);
            QCOMPARE(r.ack, Ack::Ok);
            QCOMPARE(r.as<ProcessParameterData>()->parameterValue, 500);
            QCOMPARE(r.as<ProcessParameterData>()->value1, 800);

            // MSB set: write op.28 in the active set.
            r = drive.respond(
                write(s,
                      ProcessParameterData { 800, 0, 0, quint16(0x8000 | kAccelerationTime), 777 }),
                kStart + 20);
            QCOMPARE(r.ack, Ack::Ok);
            QCOMPARE(drive.value(kAccelerationTime, 0), 777);
            set(drive, kAccelerationTime, 500, kStart + 20);

            r = drive.respond(
                write(s, ProcessParameterData { 800, 0, 0, quint16(0x8000 | kActualSpeed), 1 }),
                kStart + 30);
            QCOMPARE(r.ack, Ack::WriteProtected);
            r = drive.respond(write(s, ProcessParameterData { 800, 0, 0, 0x0299, 0 }), kStart + 40);
            QCOMPARE(r.ack, Ack::AddressInvalid);
            r = drive.respond(write(s,
                                    ProcessParameterData {
                                        800, 0, 0, quint16(0x8000 | kAccelerationTime), 99999 }),
                              kStart + 50);
            QCOMPARE(r.ack, Ack::DataInvalid);
            r = drive.respond(write(s, ProcessParameterData { 900, 0, 0, 0, 0 }), kStart + 60);
            QCOMPARE(r.ack, Ack::Ok);
            QCOMPARE(drive.value(kCommandSpeed, 0), 900);
        }
    }
};

QTEST_GUILESS_MAIN(TestSimLive)
#include "tst_simlive.moc"
