#include "EditorSampleDrive.h"

#include "parameters/ParameterFormat.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

namespace {

ParameterFormat formatOf(quint16 address)
{
    static const DriveDescription description = drive();
    return ParameterFormat(*description.find(address));
}

} // namespace

// How the table and the editors read and take values: one format for both.
class TestParameterFormat : public QObject
{
    Q_OBJECT
private slots:
    void showsPlaintextOrScaledNumber()
    {
        QCOMPARE(formatOf(kState).text(66), QStringLiteral("Fcon"));
        QCOMPARE(formatOf(kState).text(5), QStringLiteral("5"));
        QCOMPARE(formatOf(kFrequency).text(-4180), QStringLiteral("-52.25 Hz"));
        QCOMPARE(formatOf(kFrequency).text(-4180, false), QStringLiteral("-52.25"));
        QCOMPARE(formatOf(kControl).text(6), QStringLiteral("reverse | released"));
        QCOMPARE(formatOf(kErrorMask).text(0xFF), QStringLiteral("00FFh"));
        QVERIFY(formatOf(kControl).isBitField());
        QVERIFY(!formatOf(kSource).isBitField());
        QVERIFY(formatOf(kErrorMask).isHexadecimal());
    }

    void takesExactNumbersWithOrWithoutUnit()
    {
        const ParameterFormat hz = formatOf(kMaxFrequency);
        QCOMPARE(hz.parse(QStringLiteral("50")), 5000);
        QCOMPARE(hz.parse(QStringLiteral(" 50.5 Hz")), 5050);
        QCOMPARE(hz.parse(QStringLiteral("50,50")), 5050);
        QCOMPARE(hz.parse(QStringLiteral("+0.01")), 1);
        QCOMPARE(hz.parse(QStringLiteral("0")), 0);
        // 1/80 Hz steps with two decimals: 12.34 shows as typed (raw 987 = 12.3375).
        const ParameterFormat fine = formatOf(kFrequency);
        QCOMPARE(fine.parse(QStringLiteral("12.34")), 987);
        QCOMPARE(fine.text(987), QStringLiteral("12.34 Hz"));
    }

    void refusesWhatWouldBeRoundedAway()
    {
        QString error;
        const ParameterFormat hz = formatOf(kMaxFrequency);
        QVERIFY(!hz.parse(QStringLiteral("50.005"), &error));
        QCOMPARE(error,
                 QStringLiteral("50.005 cannot be set exactly: the nearest value this "
                                "parameter can hold is 50.01 Hz"));
        QVERIFY(!hz.parse(QStringLiteral("12.3375 Hz"), &error));
        QVERIFY(error.contains(QStringLiteral("cannot be set exactly")));
    }

    void refusesValuesOutsideTheLimitsUnlessAskedNotTo()
    {
        QString error;
        const ParameterFormat hz = formatOf(kMaxFrequency);
        QVERIFY(!hz.parse(QStringLiteral("400.01"), &error));
        QCOMPARE(error, QStringLiteral("400.01 Hz is outside the limits 0.00 .. 400.00 Hz"));
        QCOMPARE(hz.parse(QStringLiteral("400.01"), nullptr, ParameterFormat::Limits::Ignore),
                 40001);
        QVERIFY(!hz.isWithinLimits(-1));
        QVERIFY(hz.limitsProblem(40000).isEmpty());
    }

    void takesPlaintextsAndSaysWhichExist()
    {
        QString error;
        const ParameterFormat source = formatOf(kSource);
        QCOMPARE(source.parse(QStringLiteral("BUS")), 2);
        QCOMPARE(source.parse(QStringLiteral("1")), 1);
        QVERIFY(!source.parse(QStringLiteral("limited"), &error));
        QCOMPARE(error, QStringLiteral("3 is outside the limits 0 .. 2"));
        QVERIFY(!source.parse(QStringLiteral("serial"), &error));
        QVERIFY(error.contains(QStringLiteral("digital, analog, bus, limited")));
        QCOMPARE(formatOf(kControl).parse(QStringLiteral("reverse | released")), 6);
    }

    void takesHexadecimalAsTyped()
    {
        const ParameterFormat hex = formatOf(kErrorMask);
        QCOMPARE(hex.parse(QStringLiteral("0x1A0")), 0x1A0);
        QCOMPARE(hex.parse(QStringLiteral("1a0h")), 0x1A0);
        QString error;
        QVERIFY(!hex.parse(QStringLiteral("xyz"), &error));
        QCOMPARE(error, QStringLiteral("'xyz' is not a hexadecimal number"));
    }

    void rawFormatKeepsTheLimitsOnly()
    {
        const ParameterFormat raw = formatOf(kMaxFrequency).rawFormat();
        QVERIFY(raw.isRaw());
        QCOMPARE(raw.text(5000), QStringLiteral("5000"));
        QCOMPARE(raw.parse(QStringLiteral("12345")), 12345);
        QString error;
        QVERIFY(!raw.parse(QStringLiteral("1.5"), &error));
        QCOMPARE(error, QStringLiteral("'1.5' is not a whole number"));
        QVERIFY(!raw.parse(QStringLiteral("40001"), &error));
        QCOMPARE(error, QStringLiteral("40001 is outside the limits 0 .. 40000"));
        QCOMPARE(formatOf(kState).rawFormat().text(66), QStringLiteral("66"));
    }

    void anInvalidScalingIsNeverDividedBy()
    {
        ParameterDescription broken = parameter(0x0310, QStringLiteral("broken"), 0, kWritable);
        broken.scaling.divisor = 0;
        broken.maximum = 100;
        const ParameterFormat format(broken);
        QCOMPARE(format.text(12), QStringLiteral("12 (no scaling: divisor 0)"));
        QString error;
        QVERIFY(!format.parse(QStringLiteral("12"), &error));
        QVERIFY(error.contains(QStringLiteral("divisor 0")));
        QCOMPARE(format.rawFormat().parse(QStringLiteral("12")), 12);
    }
};

QTEST_GUILESS_MAIN(TestParameterFormat)
#include "tst_parameterformat.moc"
