#include "parameters/DisplayScaling.h"
#include "parameters/DisplayUnit.h"

#include <QLocale>
#include <QTest>

#include <limits>

using namespace DriveDesk;

namespace {

constexpr quint16 kHz = 18;
constexpr quint16 kVolt = 21;
constexpr quint16 kPercent = 37;

quint16 flags(quint16 unit, int representation, int mode = 0)
{
    return quint16(unit | (mode << 6) | (representation << 8));
}

DisplayScaling scaling(qint16 divisor, qint16 multiplier, qint16 offset, quint16 flagBits)
{
    return DisplayScaling(DisplayScalingData { 0x0203, divisor, multiplier, offset, flagBits });
}

} // namespace

// Service 5: raw values to what a user reads, and back.
class TestDisplayScaling : public QObject
{
    Q_OBJECT
private slots:
    void unitTableHasTheSeedsSymbols()
    {
        QCOMPARE(displayUnitSymbol(0), QString());
        QCOMPARE(displayUnitSymbol(1), QStringLiteral("mm"));
        QCOMPARE(displayUnitSymbol(7), QStringLiteral("µs"));
        QCOMPARE(displayUnitSymbol(14), QStringLiteral("m/s²"));
        QCOMPARE(displayUnitSymbol(17), QStringLiteral("1/min"));
        QCOMPARE(displayUnitSymbol(18), QStringLiteral("Hz"));
        QCOMPARE(displayUnitSymbol(31), QStringLiteral("°C"));
        QCOMPARE(displayUnitSymbol(34), QStringLiteral("Ω"));
        QCOMPARE(displayUnitSymbol(36), QStringLiteral("INC"));
        QCOMPARE(displayUnitSymbol(37), QStringLiteral("%"));
        QCOMPARE(displayUnitSymbol(38), QStringLiteral("kWh"));
        QCOMPARE(displayUnitSymbol(40), QStringLiteral("s/h"));
        for (int code = 1; code < kDisplayUnitCount; ++code) {
            QVERIFY2(!displayUnitSymbol(code).isEmpty(), qPrintable(QString::number(code)));
            QCOMPARE(displayUnitFromSymbol(displayUnitSymbol(code)), code);
        }
        for (int code : { 41, 63, 64, -1, 1000, std::numeric_limits<int>::min() })
            QCOMPARE(displayUnitSymbol(code), QString());
    }

    void unitSymbolsAsUsersTypeThem()
    {
        QCOMPARE(displayUnitFromSymbol(QStringLiteral("us")), 7);
        QCOMPARE(displayUnitFromSymbol(QStringLiteral("rpm")), 17);
        QCOMPARE(displayUnitFromSymbol(QStringLiteral("hz")), 18);
        QCOMPARE(displayUnitFromSymbol(QStringLiteral("Ohm")), 34);
        QCOMPARE(displayUnitFromSymbol(QStringLiteral("KWh")), 38);
        QCOMPARE(displayUnitFromSymbol(QStringLiteral("degC")), 31);
        QCOMPARE(displayUnitFromSymbol(QStringLiteral("m/s2")), 14);
        QVERIFY(!displayUnitFromSymbol(QStringLiteral("x")));
        QVERIFY(!displayUnitFromSymbol(QString()));
    }

    void formatsFixedDecimalsWithUnit()
    {
        const DisplayScaling hz = scaling(100, 1, 0, flags(kHz, 2));
        QCOMPARE(hz.format(1250), QStringLiteral("12.50 Hz"));
        QCOMPARE(hz.format(1250, false), QStringLiteral("12.50"));
        QCOMPARE(hz.unitSymbol(), QStringLiteral("Hz"));
        QCOMPARE(hz.decimals(), 2);
        QCOMPARE(scaling(10, 1, 0, flags(kPercent, 1)).format(-35), QStringLiteral("-3.5 %"));
        QCOMPARE(scaling(1, 1, 0, 0).format(42), QStringLiteral("42"));
    }

    void decimalSeparatorFollowsTheLanguageShown()
    {
        // The window sets the default locale to its language; typing takes either separator.
        const DisplayScaling hz = scaling(100, 1, 0, flags(kHz, 2));
        const DisplayScaling variable = scaling(1000, 1, 0, flags(kHz, 5));
        QLocale::setDefault(QLocale(QLocale::German));
        QCOMPARE(hz.format(500), QStringLiteral("5,00 Hz"));
        QCOMPARE(hz.format(-750, false), QStringLiteral("-7,50"));
        QCOMPARE(variable.format(12500), QStringLiteral("12,5 Hz"));
        QCOMPARE(variable.format(12000), QStringLiteral("12 Hz"));
        QCOMPARE(hz.parse(QStringLiteral("7,5")), 750);
        QCOMPARE(hz.parse(QStringLiteral("7.5 Hz")), 750);
        QLocale::setDefault(QLocale::c());
        QCOMPARE(hz.format(500), QStringLiteral("5.00 Hz"));
        QCOMPARE(hz.parse(QStringLiteral("7,5")), 750);
    }

    void roundsHalfAwayFromZeroWithoutNegativeZero()
    {
        const DisplayScaling f1 = scaling(100, 1, 0, flags(0, 1));
        QCOMPARE(f1.format(125), QStringLiteral("1.3"));
        QCOMPARE(f1.format(-125), QStringLiteral("-1.3"));
        QCOMPARE(f1.format(124), QStringLiteral("1.2"));
        QCOMPARE(f1.format(-4), QStringLiteral("0.0"));
        QCOMPARE(f1.format(5), QStringLiteral("0.1"));
    }

    void offsetAndMultiplierApply()
    {
        // (raw + offset) * multiplier / divisor
        const DisplayScaling s = scaling(8, 5, -100, flags(kVolt, 1));
        QCOMPARE(s.format(260), QStringLiteral("100.0 V")); // (260 - 100) * 5 / 8
        QCOMPARE(scaling(-2, 1, 0, 0).format(10), QStringLiteral("-5"));
    }

    void variableDecimalsTrimTrailingZeros()
    {
        const DisplayScaling s = scaling(1000, 1, 0, flags(kHz, 5));
        QCOMPARE(s.decimals(), 4);
        QCOMPARE(s.format(12500), QStringLiteral("12.5 Hz"));
        QCOMPARE(s.format(12000), QStringLiteral("12 Hz"));
        QCOMPARE(s.format(12345), QStringLiteral("12.345 Hz"));
        QCOMPARE(scaling(10000, 1, 0, flags(0, 5)).format(-1), QStringLiteral("-0.0001"));
        QCOMPARE(scaling(20000, 1, 0, flags(0, 5)).format(1), QStringLiteral("0.0001"));
        QCOMPARE(scaling(30000, 1, 0, flags(0, 5)).format(1), QStringLiteral("0"));
    }

    void fixedPointIsWhatFormatShows()
    {
        QCOMPARE(scaling(100, 1, 0, flags(0, 1)).toFixedPoint(-125), -13); // "-1.3"
        QCOMPARE(scaling(8, 5, -100, flags(kVolt, 1)).toFixedPoint(260), 1000); // "100.0 V"
        QCOMPARE(scaling(1000, 1, 0, flags(kHz, 5)).toFixedPoint(12500), 125000); // "12.5 Hz"
        QCOMPARE(scaling(1, 1000, 0, flags(kHz, 0, 1)).toFixedPoint(-8), -125);
        QCOMPARE(scaling(1, 1000, 0, flags(kHz, 0, 1)).toFixedPoint(0), std::nullopt);
        QCOMPARE(scaling(0, 0, 0, flags(0, 6)).toFixedPoint(255), std::nullopt); // hexadecimal
        QCOMPARE(scaling(0, 1, 0, flags(kHz, 2)).toFixedPoint(5), std::nullopt); // divisor 0
        QCOMPARE(scaling(1, 1, 0, flags(0, 0, 2)).toFixedPoint(5), std::nullopt); // mode 2
    }

    void hexadecimalShowsTheRawBits()
    {
        const DisplayScaling hex = scaling(0, 0, 0, flags(0, 6));
        QVERIFY(hex.isValid()); // hexadecimal does not divide
        QCOMPARE(hex.format(255), QStringLiteral("00FFh"));
        QCOMPARE(hex.format(0), QStringLiteral("0000h"));
        QCOMPARE(hex.format(0x12345), QStringLiteral("00012345h"));
        QCOMPARE(hex.format(-1), QStringLiteral("FFFFFFFFh"));
        QCOMPARE(hex.decimals(), 0);
    }

    void reciprocalMode()
    {
        const DisplayScaling s = scaling(1, 1000, 0, flags(kHz, 0, 1));
        QCOMPARE(s.format(4), QStringLiteral("250 Hz"));
        QCOMPARE(s.format(-8), QStringLiteral("-125 Hz"));
        QCOMPARE(s.format(0), QStringLiteral("0 (no scaling: value + offset is 0)"));
        const DisplayScaling third = scaling(1, 1, 0, flags(0, 3, 1));
        QCOMPARE(third.format(3), QStringLiteral("0.333"));
        QCOMPARE(third.parse(QStringLiteral("0.333")), 3);
        QCOMPARE(third.parse(QStringLiteral("0.25")), 4);
        QCOMPARE(third.parse(QStringLiteral("1000")), 1); // nearest shown value, never 0
        QCOMPARE(third.parse(QStringLiteral("-1000")), -1);
        QString error;
        QVERIFY(!third.parse(QStringLiteral("0"), &error));
        QCOMPARE(error, QStringLiteral("no raw value gives 0 in this scaling"));
        // with an offset, raw -offset is the pole
        QCOMPARE(scaling(1, 10, -4, flags(0, 0, 1)).format(4),
                 QStringLiteral("4 (no scaling: value + offset is 0)"));
    }

    void divisorZeroNeverDivides()
    {
        const DisplayScaling s = scaling(0, 1, 0, flags(kHz, 2));
        QVERIFY(!s.isValid());
        QCOMPARE(s.invalidReason(), QStringLiteral("divisor 0"));
        QCOMPARE(s.format(1234), QStringLiteral("1234 (no scaling: divisor 0)"));
        QCOMPARE(s.format(std::numeric_limits<qint32>::min()),
                 QStringLiteral("-2147483648 (no scaling: divisor 0)"));
        QVERIFY(!s.toDisplay(5));
        QString error;
        QVERIFY(!s.parse(QStringLiteral("12.5"), &error));
        QVERIFY2(error.contains(QStringLiteral("divisor 0")), qPrintable(error));
        // mode 1 divides by (value + offset) * divisor: zero everywhere
        const DisplayScaling reciprocal = scaling(0, 1, 0, flags(0, 0, 1));
        QCOMPARE(reciprocal.format(7), QStringLiteral("7 (no scaling: divisor 0)"));
        QVERIFY(!reciprocal.parse(QStringLiteral("1"), &error));
    }

    void freeCalculationModeIsInvalid()
    {
        const DisplayScaling s = scaling(1, 1, 0, flags(0, 0, 2));
        QCOMPARE(s.format(5), QStringLiteral("5 (no scaling: calculation mode 2)"));
        QString error;
        QVERIFY(!s.parse(QStringLiteral("5"), &error));
        QVERIFY2(error.contains(QStringLiteral("calculation mode 2")), qPrintable(error));
    }

    void unknownCodesDoNotCrash()
    {
        const DisplayScaling s = scaling(1, 1, 0, quint16(50 | (9 << 8) | 0xF000));
        QCOMPARE(s.unitSymbol(), QString());
        QCOMPARE(s.decimals(), 0);
        QCOMPARE(s.format(12), QStringLiteral("12"));
        QCOMPARE(DisplayScaling().format(-7), QStringLiteral("-7")); // identity
    }

    void extremesDoNotOverflow()
    {
        const qint32 max = std::numeric_limits<qint32>::max();
        const qint32 min = std::numeric_limits<qint32>::min();
        QCOMPARE(scaling(1, 32767, 0, flags(0, 4)).format(max),
                 QStringLiteral("70366596661249.0000"));
        QCOMPARE(scaling(1, -32768, -32768, flags(0, 4)).format(min),
                 QStringLiteral("70369817919488.0000"));
        QCOMPARE(scaling(-3, 32767, 32767, flags(0, 2)).format(max),
                 QStringLiteral("-23455890112512.67"));
        QCOMPARE(scaling(-32768, 32767, 0, flags(0, 4, 1)).format(min), QStringLiteral("0.0000"));
        QCOMPARE(scaling(1, 1, 32767, 0).format(max), QStringLiteral("2147516414"));
        const DisplayScaling identity = scaling(1, 1, 0, 0);
        QCOMPARE(identity.parse(QStringLiteral("2147483647")), max);
        QCOMPARE(identity.parse(QStringLiteral("-2147483648")), min);
        QString error;
        QVERIFY(!identity.parse(QStringLiteral("2147483648"), &error));
        QVERIFY2(error.contains(QStringLiteral("out of range")), qPrintable(error));
        QVERIFY(!identity.parse(QStringLiteral("123456789012345678901234"), &error));
        QVERIFY2(error.contains(QStringLiteral("too many digits")), qPrintable(error));
        QVERIFY(
            !scaling(1, 1, 0, flags(0, 0, 1)).parse(QStringLiteral("0.0000000000000001"), &error));
    }

    void parsesWithOrWithoutUnitAndEitherSeparator()
    {
        const DisplayScaling hz = scaling(100, 1, 0, flags(kHz, 2));
        QCOMPARE(hz.parse(QStringLiteral("12.50 Hz")), 1250);
        QCOMPARE(hz.parse(QStringLiteral("12,5")), 1250);
        QCOMPARE(hz.parse(QStringLiteral("12.5Hz")), 1250);
        QCOMPARE(hz.parse(QStringLiteral(" 12.5 hz ")), 1250);
        QCOMPARE(hz.parse(QStringLiteral("+3")), 300);
        QCOMPARE(hz.parse(QStringLiteral(".5")), 50);
        QCOMPARE(hz.parse(QStringLiteral("-0.004")), 0);
        QCOMPARE(hz.parse(QStringLiteral("0.005")), 1); // nearest raw, half away from zero
        QCOMPARE(hz.parse(QStringLiteral("-0.005")), -1);
        QCOMPARE(scaling(8, 5, -100, flags(kVolt, 1)).parse(QStringLiteral("100 V")), 260);
        QCOMPARE(scaling(1, 1, 0, flags(17, 0)).parse(QStringLiteral("1500 rpm")), 1500);
        QCOMPARE(scaling(1, 1, 0, flags(17, 0)).parse(QStringLiteral("1500 1/min")), 1500);
    }

    void parseErrorsNameTheFault()
    {
        const DisplayScaling hz = scaling(100, 1, 0, flags(kHz, 2));
        QString error;
        QVERIFY(!hz.parse(QStringLiteral("12,3x"), &error));
        QCOMPARE(error, QStringLiteral("'12,3x' is not a number"));
        QVERIFY(!hz.parse(QStringLiteral("12 V"), &error));
        QCOMPARE(error, QStringLiteral("unit 'V' does not match 'Hz'"));
        QVERIFY(!hz.parse(QStringLiteral("   "), &error));
        QCOMPARE(error, QStringLiteral("no value given"));
        QVERIFY(!hz.parse(QStringLiteral("1.2.3"), &error));
        QCOMPARE(error, QStringLiteral("'1.2.3' is not a number"));
        QVERIFY(!hz.parse(QStringLiteral("abc"), &error));
        QCOMPARE(error, QStringLiteral("'abc' is not a number"));
        QVERIFY(!scaling(1, 1, 0, 0).parse(QStringLiteral("5 Hz"), &error));
        QCOMPARE(error, QStringLiteral("unit 'Hz' does not match: this value has no unit"));
        QVERIFY(!scaling(1, 0, 0, 0).parse(QStringLiteral("0"), &error));
        QVERIFY2(error.contains(QStringLiteral("multiplier 0")), qPrintable(error));
        QVERIFY(!scaling(1, 0, 0, 0).parse(QStringLiteral("3"), &error));
        QCOMPARE(error, QStringLiteral("no raw value gives 3 in this scaling"));
    }

    void parsesHexadecimal()
    {
        const DisplayScaling hex = scaling(1, 1, 0, flags(0, 6));
        for (const char *text : { "FF", "ff", "0xFF", "0XFF", "FFh", "00FFh", "0x00ff" })
            QCOMPARE(hex.parse(QString::fromLatin1(text)), 255);
        QCOMPARE(hex.parse(QStringLiteral("FFFFFFFF")), -1);
        QCOMPARE(hex.parse(QStringLiteral("000000000001")), 1);
        QString error;
        QVERIFY(!hex.parse(QStringLiteral("1FFFFFFFF"), &error));
        QCOMPARE(error, QStringLiteral("'1FFFFFFFF' does not fit in 32 bits"));
        QVERIFY(!hex.parse(QStringLiteral("xyz"), &error));
        QCOMPARE(error, QStringLiteral("'xyz' is not a hexadecimal number"));
        QVERIFY(!hex.parse(QStringLiteral("-5"), &error));
    }

    void parseInvertsFormat_data()
    {
        QTest::addColumn<int>("divisor");
        QTest::addColumn<int>("multiplier");
        QTest::addColumn<int>("offset");
        QTest::addColumn<int>("flagBits");
        QTest::addColumn<bool>("exact"); // every raw value has its own text
        QTest::newRow("F2 Hz") << 100 << 1 << 0 << int(flags(kHz, 2)) << true;
        QTest::newRow("F1 %") << 10 << 1 << 0 << int(flags(kPercent, 1)) << true;
        QTest::newRow("integer") << 1 << 1 << 0 << 0 << true;
        QTest::newRow("0.0125 Hz") << 80 << 1 << 0 << int(flags(kHz, 2)) << false;
        QTest::newRow("coarse") << 1 << 3 << 7 << int(flags(kVolt, 0)) << true;
        QTest::newRow("negative divisor") << -100 << 3 << -50 << int(flags(0, 2)) << true;
        QTest::newRow("variable") << 1000 << 1 << 0 << int(flags(kHz, 5)) << true;
        QTest::newRow("F4 fine") << 30000 << 1 << 0 << int(flags(0, 4)) << false;
        QTest::newRow("hex") << 1 << 1 << 0 << int(flags(0, 6)) << true;
        QTest::newRow("reciprocal") << 1 << 30000 << 0 << int(flags(0, 2, 1)) << false;
    }

    void parseInvertsFormat()
    {
        QFETCH(int, divisor);
        QFETCH(int, multiplier);
        QFETCH(int, offset);
        QFETCH(int, flagBits);
        QFETCH(bool, exact);
        const DisplayScaling s
            = scaling(qint16(divisor), qint16(multiplier), qint16(offset), quint16(flagBits));
        QList<qint32> raws;
        for (qint32 raw = -1100; raw <= 1100; ++raw)
            raws << raw;
        raws << 123456789 << -98765432 << std::numeric_limits<qint32>::max() / 4;
        for (const qint32 raw : std::as_const(raws)) {
            const QString text = s.format(raw);
            if (text.contains(QStringLiteral("no scaling")))
                continue;
            QString error;
            const std::optional<qint32> back = s.parse(text, &error);
            if (!back && s.calculationMode() == 1
                && error == QStringLiteral("no raw value gives 0 in this scaling")) {
                continue; // a large raw value rounds to 0, which no raw value gives exactly
            }
            QVERIFY2(back, qPrintable(text + QStringLiteral(": ") + error));
            QCOMPARE(s.format(*back), text);
            if (exact)
                QCOMPARE(*back, raw);
        }
    }
};

QTEST_GUILESS_MAIN(TestDisplayScaling)
#include "tst_displayscaling.moc"
