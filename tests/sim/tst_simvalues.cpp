#include "SimRequests.h"

#include <QTest>

using namespace DriveDesk;
using namespace SimRequests;

namespace {

constexpr quint16 kAccelerationTime = 0x031C; // op.28, set-programmable, 0..30000, default 500
constexpr quint16 kCommandSpeed = 0x0303; // op.03, one value for all sets
constexpr quint16 kActualFrequency = 0x0203; // ru.03, read-only
constexpr quint16 kErrorDiagnosis = 0x0E19; // In.25, read-only, set-programmable
constexpr quint16 kErrorCounter = 0x0E1A; // In.26, written at Security level
constexpr quint16 kCalibration = 0x0E28; // In.40, read at Security, written at Supervisor
constexpr quint16 kPassword = 0x0801; // ud.01
constexpr quint16 kActiveSet = 0x0902; // Fr.02
constexpr quint16 kSetPointer = 0x0909; // Fr.09

} // namespace

// Parameter values: set masks, standard and subindex set addressing, read-only, limits,
// defaults and password levels, service by service.
class TestSimValues : public QObject
{
    Q_OBJECT
private slots:
    void setMaskReadsAndWritesSelectedSets()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 1000, 0x02), 0).ack, Ack::Ok);
        Telegram r = drive.respond(readValue(kAccelerationTime, 0x01), 0);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(valueOf(r), 500);
        QCOMPARE(valueOf(drive.respond(readValue(kAccelerationTime, 0x02), 0)), 1000);
        QCOMPARE(drive.value(kAccelerationTime, 1), 1000);

        // Several sets whose values differ: no single value to give.
        r = drive.respond(readValue(kAccelerationTime, 0x03), 0);
        QCOMPARE(r.ack, Ack::DataInvalid);

        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 700, 0xFF), 0).ack, Ack::Ok);
        for (int set = 0; set < 8; ++set)
            QCOMPARE(drive.value(kAccelerationTime, set), 700);
        r = drive.respond(readValue(kAccelerationTime, 0xFF), 0);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(valueOf(r), 700);
    }

    void setMaskZeroIsRefused()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(readValue(kAccelerationTime, 0), 0).ack, Ack::SetInvalid);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 600, 0), 0).ack, Ack::SetInvalid);
        QCOMPARE(drive.value(kAccelerationTime, 0), 500);
    }

    void parameterThatIsNotSetProgrammableHoldsOneValue()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(writeValue(kCommandSpeed, 1234, 0x04), 0).ack, Ack::Ok);
        QCOMPARE(valueOf(drive.respond(readValue(kCommandSpeed, 0x01), 0)), 1234);
        QCOMPARE(valueOf(drive.respond(readValue(kCommandSpeed, 0xFF), 0)), 1234);
        QCOMPARE(drive.value(kCommandSpeed, 7), 1234);
    }

    void standardSetAddressingUsesActiveSetAndSetPointer()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(writeValue(kActiveSet, 2), 0).ack, Ack::Ok);
        QCOMPARE(drive.respond(writeValue(kSetPointer, 5), 0).ack, Ack::Ok);

        const Service standard = Service::ParameterValueStandard;
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 801, 0, standard), 0).ack, Ack::Ok);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 805, 1, standard), 0).ack, Ack::Ok);
        QCOMPARE(drive.value(kAccelerationTime, 2), 801);
        QCOMPARE(drive.value(kAccelerationTime, 5), 805);
        QCOMPARE(drive.value(kAccelerationTime, 0), 500);
        QCOMPARE(valueOf(drive.respond(readValue(kAccelerationTime, 0, standard), 0)), 801);
        QCOMPARE(valueOf(drive.respond(readValue(kAccelerationTime, 1, standard), 0)), 805);

        QCOMPARE(drive.respond(readValue(kAccelerationTime, 2, standard), 0).ack, Ack::SetInvalid);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 900, 2, standard), 0).ack,
                 Ack::SetInvalid);
        // The set byte of service 1 is not a mask: 3 is invalid too.
        QCOMPARE(drive.respond(readValue(kAccelerationTime, 3, standard), 0).ack, Ack::SetInvalid);
    }

    void activeSetAndSetPointerStayInZeroToSeven()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(writeValue(kActiveSet, 8), 0).ack, Ack::DataInvalid);
        QCOMPARE(drive.respond(writeValue(kSetPointer, -1), 0).ack, Ack::DataInvalid);
    }

    void subindexAddressesTheSet()
    {
        SimulatedDrive drive;
        const Service subindex = Service::SubindexValue;
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 1500, 3, subindex), 0).ack, Ack::Ok);
        QCOMPARE(drive.value(kAccelerationTime, 3), 1500);
        QCOMPARE(valueOf(drive.respond(readValue(kAccelerationTime, 3, subindex), 0)), 1500);
        QCOMPARE(valueOf(drive.respond(readValue(kAccelerationTime, 0, subindex), 0)), 500);
        QCOMPARE(drive.respond(readValue(kAccelerationTime, 8, subindex), 0).ack, Ack::SetInvalid);
    }

    void legacyServiceGoesThroughSetPointerWith16Bits()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(writeValue(kSetPointer, 4), 0).ack, Ack::Ok);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 1200, 0, Service::Legacy), 0).ack,
                 Ack::Ok);
        QCOMPARE(drive.value(kAccelerationTime, 4), 1200);
        QCOMPARE(valueOf(drive.respond(readValue(kAccelerationTime, 0, Service::Legacy), 0)), 1200);
        // ud.30 holds 2147483647: the 16-bit line carries its low word.
        QCOMPARE(valueOf(drive.respond(readValue(0x081E, 0, Service::Legacy), 0)), -1);
    }

    void readOnlyParametersRefuseWrites()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(writeValue(kActualFrequency, 100), 0).ack, Ack::WriteProtected);
        QCOMPARE(drive.respond(writeValue(kErrorDiagnosis, 0), 0).ack, Ack::WriteProtected);
        QCOMPARE(drive.respond(readValue(kActualFrequency), 0).ack, Ack::Ok);
    }

    void writesOutsideTheLimitsAreRefused()
    {
        SimulatedDrive drive;
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 30001), 0).ack, Ack::DataInvalid);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, -1), 0).ack, Ack::DataInvalid);
        QCOMPARE(drive.value(kAccelerationTime, 0), 500);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 30000), 0).ack, Ack::Ok);
    }

    void unknownAddressesAreInvalid()
    {
        SimulatedDrive drive;
        for (quint16 address : { quint16(0x0250), quint16(0x7F00), quint16(0xFFFF) }) {
            QCOMPARE(drive.respond(readValue(address), 0).ack, Ack::AddressInvalid);
            QCOMPARE(drive.respond(writeValue(address, 1), 0).ack, Ack::AddressInvalid);
            QCOMPARE(
                drive.respond(read(Service::CheckDefault, DefaultCheckData { address, 1 }), 0).ack,
                Ack::AddressInvalid);
            QCOMPARE(drive.respond(readValue(address, 0, Service::ParameterValueStandard), 0).ack,
                     Ack::AddressInvalid);
        }
    }

    void setProgrammableReadOnlyParameterDiffersBetweenSets()
    {
        SimulatedDrive drive;
        // In.25: newest error in set 0, oldest in set 7.
        QCOMPARE(valueOf(drive.respond(readValue(kErrorDiagnosis, 0x01), 0)), 0x2005);
        QCOMPARE(valueOf(drive.respond(readValue(kErrorDiagnosis, 0x02), 0)), 0x4012);
        QCOMPARE(drive.respond(readValue(kErrorDiagnosis, 0xFF), 0).ack, Ack::DataInvalid);
        QCOMPARE(valueOf(drive.respond(readValue(kErrorDiagnosis, 0xF0), 0)), 0);
    }

    void defaultsAreCheckedAndSet()
    {
        SimulatedDrive drive;
        const auto check = [&](quint8 mask) {
            return drive
                .respond(read(Service::CheckDefault, DefaultCheckData { kAccelerationTime, mask }),
                         0)
                .ack;
        };
        QCOMPARE(check(0xFF), Ack::Ok);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 900, 0x08), 0).ack, Ack::Ok);
        QCOMPARE(check(0xFF), Ack::DataInvalid);
        QCOMPARE(check(0x01), Ack::Ok);
        QCOMPARE(check(0x08), Ack::DataInvalid);
        QCOMPARE(check(0), Ack::SetInvalid);

        QCOMPARE(
            drive
                .respond(write(Service::CheckDefault, DefaultCheckData { kAccelerationTime, 0x08 }),
                         0)
                .ack,
            Ack::Ok);
        QCOMPARE(drive.value(kAccelerationTime, 3), 500);
        QCOMPARE(check(0xFF), Ack::Ok);

        // Standard set addressing: the active set, then the set pointer.
        QCOMPARE(drive.respond(writeValue(kSetPointer, 6), 0).ack, Ack::Ok);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 901, 0x40), 0).ack, Ack::Ok);
        const auto checkStandard = [&](quint8 set) {
            return drive
                .respond(read(Service::CheckDefaultStandard,
                              DefaultCheckData { kAccelerationTime, set }),
                         0)
                .ack;
        };
        QCOMPARE(checkStandard(0), Ack::Ok);
        QCOMPARE(checkStandard(1), Ack::DataInvalid);
        QCOMPARE(checkStandard(2), Ack::SetInvalid);
        QCOMPARE(drive
                     .respond(write(Service::CheckDefaultStandard,
                                    DefaultCheckData { kAccelerationTime, 1 }),
                              0)
                     .ack,
                 Ack::Ok);
        QCOMPARE(drive.value(kAccelerationTime, 6), 500);

        // Read-only parameters cannot be set to their default.
        QCOMPARE(
            drive
                .respond(write(Service::CheckDefault, DefaultCheckData { kErrorDiagnosis, 0xFF }),
                         0)
                .ack,
            Ack::WriteProtected);
    }

    void passwordLevelsGuardParameters()
    {
        SimulatedDrive drive;
        QCOMPARE(valueOf(drive.respond(readValue(kPassword), 0)), -4); // Application
        QCOMPARE(drive.passwordLevel(), 3);

        // Above Application: In.40 is read at Security, written at Supervisor; In.26 written at
        // Security.
        QCOMPARE(drive.respond(readValue(kCalibration), 0).ack, Ack::AddressOrPasswordInvalid);
        QCOMPARE(drive.respond(writeValue(kErrorCounter, 0), 0).ack, Ack::AddressOrPasswordInvalid);
        QCOMPARE(valueOf(drive.respond(readValue(kErrorCounter), 0)), 3);

        // A wrong password changes nothing; a number outside the limits is invalid data.
        QCOMPARE(drive.respond(writeValue(kPassword, 1234), 0).ack, Ack::PasswordInvalid);
        QCOMPARE(drive.respond(writeValue(kPassword, -4), 0).ack, Ack::PasswordInvalid);
        QCOMPARE(drive.respond(writeValue(kPassword, 10000), 0).ack, Ack::DataInvalid);
        QCOMPARE(valueOf(drive.respond(readValue(kPassword), 0)), -4);

        QCOMPARE(drive.respond(writeValue(kPassword, 6060), 0).ack, Ack::Ok);
        QCOMPARE(valueOf(drive.respond(readValue(kPassword), 0)), -7); // Security
        QCOMPARE(valueOf(drive.respond(readValue(kCalibration), 0)), 0x5A5A);
        QCOMPARE(drive.respond(writeValue(kCalibration, 1), 0).ack, Ack::AddressOrPasswordInvalid);
        QCOMPARE(drive.respond(writeValue(kErrorCounter, 0), 0).ack, Ack::Ok);

        QCOMPARE(drive.respond(writeValue(kPassword, 7070), 0).ack, Ack::Ok);
        QCOMPARE(valueOf(drive.respond(readValue(kPassword), 0)), -8); // Supervisor
        QCOMPARE(drive.respond(writeValue(kCalibration, 1), 0).ack, Ack::Ok);

        // Down to CP read-only: only the password parameter is left.
        QCOMPARE(drive.respond(writeValue(kPassword, 100), 0).ack, Ack::Ok);
        QCOMPARE(valueOf(drive.respond(readValue(kPassword), 0)), -1);
        QCOMPARE(drive.respond(readValue(kAccelerationTime), 0).ack, Ack::AddressOrPasswordInvalid);
        QCOMPARE(drive.respond(writeValue(kAccelerationTime, 600), 0).ack,
                 Ack::AddressOrPasswordInvalid);
        QCOMPARE(drive.value(kAccelerationTime, 0), 500);
        // Setting ud.01 to its default would raise the level without a password.
        QCOMPARE(
            drive.respond(write(Service::CheckDefault, DefaultCheckData { kPassword, 1 }), 0).ack,
            Ack::PasswordInvalid);

        QCOMPARE(drive.respond(writeValue(kPassword, 440), 0).ack, Ack::Ok);
        QCOMPARE(drive.respond(readValue(kAccelerationTime), 0).ack, Ack::Ok);
    }

    void driveAddressAndControlWordLong()
    {
        SimulatedDrive drive({ 7, 0, 1 });
        QCOMPARE(drive.address(), 7);
        QCOMPARE(valueOf(drive.respond(readValue(0x0006), 0)), 7); // Sy.06

        // Sy.43 is Sy.41 (high word) and Sy.50 (low word).
        QCOMPARE(drive.respond(writeValue(0x002B, 0x00120034), 0).ack, Ack::Ok);
        QCOMPARE(drive.value(0x0029, 0), 0x12);
        QCOMPARE(drive.value(0x0032, 0), 0x34);
        QCOMPARE(drive.respond(writeValue(0x0032, 0x99), 0).ack, Ack::Ok);
        QCOMPARE(valueOf(drive.respond(readValue(0x002B), 0)), 0x00120099);
    }

    void malformedAndUnknownRequestsAreAnsweredNotCrashed()
    {
        SimulatedDrive drive;
        Telegram wrongPayload = read(Service::ParameterValue, NameData { 0x0203, 0, {} });
        Telegram r = drive.respond(wrongPayload, 0);
        QCOMPARE(r.direction, Direction::Response);
        QCOMPARE(r.ack, Ack::FramingError);
        QVERIFY(r.as<ParameterValue>());

        r = drive.respond(read(Service::Unspecified, std::monostate {}), 0);
        QCOMPARE(r.ack, Ack::ServiceNotAvailable);
        r = drive.respond(read(Service::StatusInterrogation, std::monostate {}), 0);
        QCOMPARE(r.ack, Ack::ServiceNotAvailable);

        Telegram aResponse = readValue(kAccelerationTime).response(Ack::Ok);
        QCOMPARE(drive.respond(aResponse, 0).ack, Ack::ServiceNotAvailable);

        for (int service = -3; service <= 53; ++service) {
            for (Access access : { Access::Read, Access::Write }) {
                const auto s = Service(service);
                Telegram request = Telegram::request(s, access, emptyDataFor(s));
                request.operatorInvoke = 5;
                const Telegram answer = drive.respond(request, service);
                QCOMPARE(answer.direction, Direction::Response);
                QCOMPARE(answer.service, s);
                QCOMPARE(answer.operatorInvoke, quint8(5));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestSimValues)
#include "tst_simvalues.moc"
