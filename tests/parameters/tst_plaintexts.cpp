#include "parameters/Plaintexts.h"

#include <QTest>

using namespace DriveDesk;

namespace {

PlaintextDefinition definition(quint32 mask, const char *description,
                               std::initializer_list<std::pair<qint32, const char *>> entries)
{
    PlaintextDefinition result { mask, QString::fromUtf8(description), {} };
    for (const auto &[value, text] : entries)
        result.entries.append({ value, 0, QString::fromUtf8(text) });
    return result;
}

// Seed 002 chapter 3.2: 5 texts in 3 definitions (1, 3 and 1 texts). The seed gives no masks
// or values; these are a bit-field parameter of that shape.
Plaintexts seedExample()
{
    return Plaintexts({
        definition(0x0001, "Controller release", { { 0x1, "released" } }),
        definition(0x0006, "Direction",
                   { { 0x0, "stop" }, { 0x2, "forward" }, { 0x4, "reverse" } }),
        definition(0x0008, "Brake", { { 0x8, "brake open" } }),
    });
}

} // namespace

// Plaintexts: raw value to text and back through the definitions' masks.
class TestPlaintexts : public QObject
{
    Q_OBJECT
private slots:
    void seedExampleHasFiveTextsInThreeDefinitions()
    {
        const Plaintexts texts = seedExample();
        QCOMPARE(texts.definitions().size(), 3);
        QCOMPARE(texts.allowedTexts().size(), 5);
        QCOMPARE(texts.definitions().at(0).entries.size(), 1);
        QCOMPARE(texts.definitions().at(1).entries.size(), 3);
        QCOMPARE(texts.definitions().at(2).entries.size(), 1);
    }

    void severalDefinitionsGiveOneTextEach()
    {
        const Plaintexts texts = seedExample();
        QCOMPARE(texts.text(0x0), QStringLiteral("stop"));
        QCOMPARE(texts.text(0x1), QStringLiteral("released | stop"));
        QCOMPARE(texts.text(0x3), QStringLiteral("released | forward"));
        QCOMPARE(texts.text(0xD), QStringLiteral("released | reverse | brake open"));
        QVERIFY(texts.hasText(0xD));
    }

    void missingTextsAndStrayBitsAreNamed()
    {
        const Plaintexts texts = seedExample();
        QCOMPARE(texts.text(0x7), QStringLiteral("released | 0006h (no plaintext in 'Direction')"));
        QVERIFY(!texts.hasText(0x7));
        QCOMPARE(texts.text(0x13), QStringLiteral("released | forward | other bits 0010h"));
        QVERIFY(!texts.hasText(0x13));
    }

    void severalDefinitionsComposeByOr()
    {
        const Plaintexts texts = seedExample();
        QCOMPARE(texts.value(QStringLiteral("released | forward | brake open")), 0xB);
        QCOMPARE(texts.value(QStringLiteral("forward")), 0x2);
        QCOMPARE(texts.value(QStringLiteral("Brake Open|REVERSE")), 0xC); // any order, any case
        QCOMPARE(texts.value(QStringLiteral("released")), 0x1);
        // Bits outside every mask stay as they are; the named fields are set, the others 0.
        QCOMPARE(texts.value(QStringLiteral("forward"), nullptr, 0x119), 0x112);
        for (qint32 raw = 0; raw < 16; ++raw) {
            if (!texts.hasText(raw))
                continue;
            QCOMPARE(texts.value(texts.text(raw)), raw);
        }
    }

    void oneFieldIsChosenKeepingEveryOtherBit()
    {
        const Plaintexts texts = seedExample();
        // Direction to reverse: released, brake and the stray bit 10h stay.
        QCOMPARE(texts.withField(0x1B, 1, 0x4), 0x1D);
        QCOMPARE(texts.withField(0x1D, 0, 0x0), 0x1C);
        // Only the field's own bits are taken from the value given.
        QCOMPARE(texts.withField(0x0, 2, -1), 0x8);
        QCOMPARE(texts.withField(qint32(0x80000000), 1, 0x2), qint32(0x80000002));
        const Plaintexts whole({ definition(0, "Mode", { { 3, "three" } }),
                                 definition(0x10, "Flag", { { 0x10, "on" } }) });
        QCOMPARE(whole.withField(0x1234, 0, 3), 3); // a mask of 0 covers every bit
    }

    void unknownTextsListWhatIsAllowed()
    {
        const Plaintexts texts = seedExample();
        QString error;
        QVERIFY(!texts.value(QStringLiteral("fast"), &error));
        QCOMPARE(error,
                 QStringLiteral("'fast' is not a plaintext of this parameter; allowed: "
                                "Controller release: released; Direction: stop, forward, "
                                "reverse; Brake: brake open"));
        QVERIFY(!texts.value(QStringLiteral("forward | reverse"), &error));
        QCOMPARE(error, QStringLiteral("'forward' and 'reverse' are texts of the same definition"));
        QVERIFY(!texts.value(QStringLiteral("forward || brake open"), &error));
        QVERIFY2(error.contains(QStringLiteral("empty text")), qPrintable(error));
        QVERIFY(!texts.value(QStringLiteral("  "), &error));
        QVERIFY2(error.startsWith(QStringLiteral("no text given")), qPrintable(error));
    }

    void textsSharedByDefinitionsAreReadInOrder()
    {
        const Plaintexts texts({
            definition(0x1, "Input 1", { { 0, "off" }, { 1, "on" } }),
            definition(0x2, "Input 2", { { 0, "off" }, { 2, "on" } }),
        });
        QCOMPARE(texts.text(0x2), QStringLiteral("off | on"));
        QCOMPARE(texts.value(QStringLiteral("off | on")), 0x2);
        QCOMPARE(texts.value(QStringLiteral("on | off")), 0x1);
        QString error;
        QVERIFY(!texts.value(QStringLiteral("on"), &error));
        QVERIFY2(error.contains(QStringLiteral("several definitions")), qPrintable(error));
    }

    void oneDefinitionIsAnEnumeration()
    {
        const DisplayScaling scaling(DisplayScalingData { 0, 1, 1, 0, 0 });
        const Plaintexts texts(
            { definition(0xFFFFFFFF, "state", { { 0, "noP" }, { 66, "Fcon" } }) }, scaling);
        QCOMPARE(texts.text(66), QStringLiteral("Fcon"));
        QCOMPARE(texts.text(0), QStringLiteral("noP"));
        QCOMPARE(texts.text(5), QStringLiteral("5 (no plaintext)"));
        QVERIFY(!texts.hasText(5));
        QCOMPARE(texts.value(QStringLiteral("fcon")), 66);
        QCOMPARE(texts.value(QStringLiteral(" noP ")), 0);
        QString error;
        QVERIFY(!texts.value(QStringLiteral("Fco"), &error));
        QCOMPARE(error,
                 QStringLiteral("'Fco' is not a plaintext of this parameter; allowed: noP, Fcon"));
    }

    void unmatchedValueShowsTheScaledNumber()
    {
        const DisplayScaling hz(DisplayScalingData { 0, 100, 1, 0, quint16(18 | (2 << 8)) });
        const Plaintexts texts({ definition(0, "", { { 0, "off" } }) }, hz);
        QCOMPARE(texts.text(1250), QStringLiteral("12.50 Hz (no plaintext)"));
        QCOMPARE(texts.text(0), QStringLiteral("off"));
    }

    void shownIsWhatEveryViewDisplays()
    {
        const DisplayScaling hz(DisplayScalingData { 0, 100, 1, 0, quint16(18 | (2 << 8)) });
        const Plaintexts enumeration({ definition(0, "", { { 0, "off" } }) }, hz);
        QVERIFY(!enumeration.isBitField());
        QCOMPARE(enumeration.shown(0), QStringLiteral("off"));
        QCOMPARE(enumeration.shown(1250), QStringLiteral("12.50 Hz"));
        QCOMPARE(enumeration.shown(1250, false), QStringLiteral("12.50"));
        const Plaintexts bitField = seedExample();
        QVERIFY(bitField.isBitField());
        QCOMPARE(bitField.shown(0x7), QStringLiteral("released | 0006h (no plaintext in 'Direction')"));
        QCOMPARE(Plaintexts({}, hz).shown(1250), QStringLiteral("12.50 Hz"));
    }

    void maskZeroCoversEveryBit()
    {
        const Plaintexts texts({ definition(0, "", { { 7, "seven" } }) });
        QCOMPARE(Plaintexts::effectiveMask(texts.definitions().first()), 0xFFFFFFFFu);
        QCOMPARE(texts.text(7), QStringLiteral("seven"));
        QVERIFY(!texts.hasText(0x107));
    }

    void entryValuesAreInPlace()
    {
        // A field in bits 4-7: entries carry their bits in place, other bits are kept.
        const Plaintexts texts({ definition(0x00F0, "mode", { { 0x10, "a" }, { 0x20, "b" } }) });
        QCOMPARE(texts.text(0x0125), QStringLiteral("b"));
        QCOMPARE(texts.value(QStringLiteral("b"), nullptr, 0x0105), 0x0125);
        // A signed word: the drive sign-extends both the value and its text's value.
        const Plaintexts word({ definition(0xFFFF, "", { { -1, "off" }, { 5, "on" } }) });
        QCOMPARE(word.text(-1), QStringLiteral("off"));
        QCOMPARE(word.text(0xFFFF), QStringLiteral("off"));
        QCOMPARE(word.value(QStringLiteral("off"), nullptr, 5), -1);
        QCOMPARE(word.value(QStringLiteral("on"), nullptr, 0), 5);
    }

    void extremesAndNegativeValues()
    {
        const Plaintexts texts({ definition(0xFFFFFFFF, "",
                                            { { std::numeric_limits<qint32>::min(), "lowest" },
                                              { std::numeric_limits<qint32>::max(), "highest" },
                                              { -1, "minus one" } }) });
        QCOMPARE(texts.text(std::numeric_limits<qint32>::min()), QStringLiteral("lowest"));
        QCOMPARE(texts.text(std::numeric_limits<qint32>::max()), QStringLiteral("highest"));
        QCOMPARE(texts.value(QStringLiteral("minus one")), -1);
        QCOMPARE(texts.value(QStringLiteral("lowest")), std::numeric_limits<qint32>::min());
        const Plaintexts high(
            { definition(0x80000000, "sign", { { qint32(0x80000000), "negative" } }),
              definition(0x1, "odd", { { 1, "odd" } }) });
        QCOMPARE(high.text(-1), QStringLiteral("negative | odd | other bits 7FFFFFFEh"));
        QCOMPARE(high.value(QStringLiteral("negative | odd")), qint32(0x80000001));
    }

    void noPlaintextsShowsNumbersOnly()
    {
        const Plaintexts none;
        QVERIFY(none.isEmpty());
        QCOMPARE(none.text(42), QStringLiteral("42"));
        QString error;
        QVERIFY(!none.value(QStringLiteral("42"), &error));
        QCOMPARE(error, QStringLiteral("this parameter has no plaintexts"));
        const Plaintexts emptyDefinitions({ definition(0xFF, "x", {}) });
        QVERIFY(emptyDefinitions.isEmpty());
        QCOMPARE(emptyDefinitions.text(3), QStringLiteral("3"));
    }
};

QTEST_GUILESS_MAIN(TestPlaintexts)
#include "tst_plaintexts.moc"
