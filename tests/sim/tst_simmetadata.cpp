#include "SimRequests.h"
#include "sim/SevenSegment.h"

#include <QTest>

using namespace DriveDesk;
using namespace SimRequests;

namespace {

constexpr quint16 kState = 0x0200; // ru.00
constexpr quint16 kActualFrequency = 0x0203; // ru.03
constexpr quint16 kEnergySaving = 0x0506; // uF.06, bit field

QByteArray nameOf(SimulatedDrive &drive, quint16 address, quint8 language)
{
    const Telegram r
        = drive.respond(read(Service::ParameterName, NameData { address, language, {} }), 0);
    return r.ack == Ack::Ok ? r.as<NameData>()->text : QByteArray();
}

// Every parameter address as a scan finds it: groups by service 10, numbers by service 6.
QList<quint16> scanAddresses(SimulatedDrive &drive, int *groups = nullptr)
{
    QList<quint16> found;
    int groupCount = 0;
    for (int page = 0; page < 0x80; ++page) {
        const Telegram g = drive.respond(
            read(Service::GroupProperties, GroupPropertiesData { quint16(page << 8) }), 0);
        if (g.ack != Ack::Ok)
            continue;
        ++groupCount;
        const auto *group = g.as<GroupPropertiesData>();
        int inGroup = 0;
        for (int number = 0; number <= group->highestNumber; ++number) {
            const auto address = quint16(page << 8 | number);
            const Telegram n
                = drive.respond(read(Service::ParameterName, NameData { address, 0, {} }), 0);
            if (n.ack == Ack::Ok) {
                found << address;
                ++inGroup;
            }
        }
        if (inGroup != group->countMinusOne + 1)
            qWarning("group page %02x: %d parameters, service 10 says %d", page, inGroup,
                     group->countMinusOne + 1);
        if (inGroup != group->countMinusOne + 1)
            return {};
    }
    if (groups)
        *groups = groupCount;
    return found;
}

} // namespace

// Metadata services 2-13: the F5 group map, names in two languages, limits, properties,
// scaling, plaintexts with the bit-field parameter and the 7-segment texts.
class TestSimMetadata : public QObject
{
    Q_OBJECT
private slots:
    void groupsFollowTheF5Map_data()
    {
        QTest::addColumn<int>("page");
        QTest::addColumn<QByteArray>("id");
        const QList<std::pair<int, const char *>> map
            = { { 0x00, "Sy" }, { 0x02, "ru" }, { 0x03, "op" }, { 0x04, "Pn" },
                { 0x05, "uF" }, { 0x06, "dr" }, { 0x07, "cn" }, { 0x08, "ud" },
                { 0x09, "Fr" }, { 0x0A, "An" }, { 0x0B, "di" }, { 0x0C, "do" },
                { 0x0D, "LE" }, { 0x0E, "In" }, { 0x0F, "CS" }, { 0x10, "Ec" } };
        for (const auto &[page, id] : map)
            QTest::newRow(id) << page << QByteArray(id);
    }

    void groupsFollowTheF5Map()
    {
        QFETCH(int, page);
        QFETCH(QByteArray, id);
        SimulatedDrive drive;
        // The low byte of the address is ignored.
        const Telegram r = drive.respond(
            read(Service::GroupProperties, GroupPropertiesData { quint16(page << 8 | 0x55) }), 0);
        QCOMPARE(r.ack, Ack::Ok);
        const auto *g = r.as<GroupPropertiesData>();
        QCOMPARE(QByteArray(g->id.data(), 2), id);
        QVERIFY(g->shortcut >= 'a' && g->shortcut <= 'z');
        QVERIFY(g->properties & (1u << 4)); // visible in COMBIVIS
        QVERIFY(g->highestNumber >= g->countMinusOne);
    }

    void scanFindsAtLeast12GroupsAnd200Parameters()
    {
        SimulatedDrive drive;
        int groups = 0;
        const QList<quint16> addresses = scanAddresses(drive, &groups);
        QVERIFY(groups >= 12);
        QCOMPARE(groups, drive.groupCount());
        QVERIFY2(addresses.size() >= 200, qPrintable(QString::number(addresses.size())));
        QCOMPARE(addresses.size(), drive.parameterCount());

        // Every group has its own display index.
        QList<int> indices;
        for (int page = 0; page < 0x80; ++page) {
            const Telegram g = drive.respond(
                read(Service::GroupProperties, GroupPropertiesData { quint16(page << 8) }), 0);
            if (g.ack == Ack::Ok)
                indices << g.as<GroupPropertiesData>()->index;
        }
        std::sort(indices.begin(), indices.end());
        for (int i = 0; i < indices.size(); ++i)
            QCOMPARE(indices.at(i), i);
    }

    void everyParameterHasEnglishAndGermanNames()
    {
        SimulatedDrive drive;
        int differ = 0;
        for (quint16 address : scanAddresses(drive)) {
            const QByteArray english = nameOf(drive, address, 0);
            const QByteArray german = nameOf(drive, address, 1);
            QVERIFY2(!english.isEmpty() && !german.isEmpty(),
                     qPrintable(QString::number(address, 16)));
            QVERIFY(english.size() <= 24 && german.size() <= 24);
            for (char c : english + german)
                QVERIFY2(c >= 0x20 && c <= 0x7E, german.constData());
            if (english != german)
                ++differ;
        }
        QVERIFY(differ > 150);
        QCOMPARE(nameOf(drive, kActualFrequency, 0), QByteArray("Actual frequency"));
        QCOMPARE(nameOf(drive, kActualFrequency, 1), QByteArray("Istfrequenzanzeige"));
        QCOMPARE(nameOf(drive, 0x0E1D, 0), QByteArray("E.OH error counter"));
    }

    void namesInOtherLanguagesAreRefused()
    {
        SimulatedDrive drive;
        Telegram r
            = drive.respond(read(Service::ParameterName, NameData { kActualFrequency, 2, {} }), 0);
        QCOMPARE(r.ack, Ack::LanguageInvalid);
        QVERIFY(r.as<NameData>()->text.isEmpty());
        r = drive.respond(read(Service::GroupName, NameData { 0x0200, 2, {} }), 0);
        QCOMPARE(r.ack, Ack::LanguageInvalid);
        QVERIFY(r.as<NameData>()->text.isEmpty());
        r = drive.respond(read(Service::ParameterName, NameData { 0x0299, 0, {} }), 0);
        QCOMPARE(r.ack, Ack::AddressInvalid);
        QVERIFY(r.as<NameData>()->text.isEmpty());
    }

    void groupNamesInBothLanguages()
    {
        SimulatedDrive drive;
        Telegram r = drive.respond(read(Service::GroupName, NameData { 0x0203, 0, {} }), 0);
        QCOMPARE(r.as<NameData>()->text, QByteArray("Run parameters"));
        r = drive.respond(read(Service::GroupName, NameData { 0x0203, 1, {} }), 0);
        QCOMPARE(r.as<NameData>()->text, QByteArray("Betriebsanzeigen"));
        r = drive.respond(read(Service::GroupName, NameData { 0x7000, 0, {} }), 0);
        QCOMPARE(r.ack, Ack::AddressInvalid);
    }

    void limitsDefaultPropertiesAndScaling()
    {
        SimulatedDrive drive;
        // op.28 acceleration time: set-programmable, 0.00..300.00 s.
        Telegram r = drive.respond(read(Service::Limits, ParameterLimits { 0x031C }), 0);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(r.as<ParameterLimits>()->lower, 0);
        QCOMPARE(r.as<ParameterLimits>()->upper, 30000);
        r = drive.respond(read(Service::DefaultValue, DefaultValue { 0x031C }), 0);
        QCOMPARE(r.as<DefaultValue>()->value, 500);
        r = drive.respond(read(Service::Properties, PropertiesData { 0x031C }), 0);
        const quint32 p1 = r.as<PropertiesData>()->properties1;
        QVERIFY(p1 & (1u << 11)); // set-programmable
        QCOMPARE(p1 & 0x7, 3u); // read: Application
        QCOMPARE((p1 >> 3) & 0x7, 3u); // write: Application
        QCOMPARE((p1 >> 6) & 0x3, 1u); // word
        QVERIFY((p1 >> 24) & 0xF); // writable
        r = drive.respond(read(Service::DisplayScaling, DisplayScalingData { 0x031C }), 0);
        QCOMPARE(r.as<DisplayScalingData>()->divisor, qint16(100));
        QCOMPARE(r.as<DisplayScalingData>()->flags & 0x3F, 9); // s
        QCOMPARE((r.as<DisplayScalingData>()->flags >> 8) & 0xF, 2); // F2

        // uF.07 keeps the facts: 0.0..130.0 %, default 70.0 %.
        r = drive.respond(read(Service::Limits, ParameterLimits { 0x0507 }), 0);
        QCOMPARE(r.as<ParameterLimits>()->upper, 1300);
        r = drive.respond(read(Service::DefaultValue, DefaultValue { 0x0507 }), 0);
        QCOMPARE(r.as<DefaultValue>()->value, 700);

        // ru.03: read-only, 0.0125 Hz per bit, signed.
        r = drive.respond(read(Service::Properties, PropertiesData { kActualFrequency }), 0);
        QCOMPARE((r.as<PropertiesData>()->properties1 >> 24) & 0xF, 0u);
        QVERIFY(r.as<PropertiesData>()->properties1 & (1u << 10));
        QVERIFY(r.as<PropertiesData>()->properties2 & (1u << 9)); // changed by the inverter
        QVERIFY(r.as<PropertiesData>()->properties2 & (1u << 17)); // read only for downloads
        r = drive.respond(read(Service::DisplayScaling, DisplayScalingData { kActualFrequency }),
                          0);
        QCOMPARE(r.as<DisplayScalingData>()->divisor, qint16(80));
        QCOMPARE(r.as<DisplayScalingData>()->multiplier, qint16(1));
        QCOMPARE(r.as<DisplayScalingData>()->flags & 0x3F, 18); // Hz

        // ru.20 heat sink temperature: raw + offset -40 = degC.
        r = drive.respond(read(Service::DisplayScaling, DisplayScalingData { 0x0214 }), 0);
        QCOMPARE(r.as<DisplayScalingData>()->offset, qint16(-40));
        QCOMPARE(r.as<DisplayScalingData>()->flags & 0x3F, 31);

        // Sy.16: hexadecimal display, -1..7FFFh, system parameter, not a process data channel.
        r = drive.respond(read(Service::DisplayScaling, DisplayScalingData { 0x0010 }), 0);
        QCOMPARE((r.as<DisplayScalingData>()->flags >> 8) & 0xF, 6);
        r = drive.respond(read(Service::Limits, ParameterLimits { 0x0010 }), 0);
        QCOMPARE(r.as<ParameterLimits>()->lower, -1);
        QCOMPARE(r.as<ParameterLimits>()->upper, 0x7FFF);
        r = drive.respond(read(Service::Properties, PropertiesData { 0x0010 }), 0);
        QVERIFY(r.as<PropertiesData>()->properties1 & (1u << 30));
        QVERIFY(r.as<PropertiesData>()->properties1 & (1u << 28));

        // Password levels in the properties: ud.01 at every level, In.40 Security/Supervisor.
        r = drive.respond(read(Service::Properties, PropertiesData { 0x0801 }), 0);
        QCOMPARE(r.as<PropertiesData>()->properties1 & 0x3F, 0u);
        r = drive.respond(read(Service::Properties, PropertiesData { 0x0E28 }), 0);
        QCOMPARE(r.as<PropertiesData>()->properties1 & 0x3F, 6u | 7u << 3);

        // PP offset (ud.29) is a long.
        r = drive.respond(read(Service::Properties, PropertiesData { 0x081D }), 0);
        QCOMPARE((r.as<PropertiesData>()->properties1 >> 6) & 0x3, 2u);
    }

    void stateTextsOfRu00()
    {
        SimulatedDrive drive;
        Telegram r
            = drive.respond(read(Service::PlaintextIndices, PlaintextIndicesData { kState }), 0);
        QCOMPARE(r.ack, Ack::Ok);
        const PlaintextIndicesData indices = *r.as<PlaintextIndicesData>();
        QVERIFY(indices.combivisIndex > 0);
        QCOMPARE(indices.combivisCount, quint16(1));
        QCOMPARE(indices.displayIndex, indices.combivisIndex);
        QVERIFY(indices.displayCount > 80);

        QHash<qint32, QByteArray> english;
        QHash<qint32, QByteArray> german;
        for (quint8 sub = 0; sub < indices.displayCount; ++sub) {
            for (quint8 language : { 0, 1 }) {
                r = drive.respond(read(Service::CombivisPlaintext,
                                       CombivisPlaintextData {
                                           indices.combivisIndex, 0, sub, language, 0, 0, {} }),
                                  0);
                QCOMPARE(r.ack, Ack::Ok);
                QVERIFY(r.as<CombivisPlaintextData>()->text.size() <= 24);
                (language ? german : english)
                    .insert(r.as<CombivisPlaintextData>()->value,
                            r.as<CombivisPlaintextData>()->text);
            }
        }
        QCOMPARE(english.value(0), QByteArray("noP (no operation)"));
        QCOMPARE(german.value(0), QByteArray("noP (kein Betrieb)"));
        QCOMPARE(english.value(66), QByteArray("Fcon (forward constant)"));
        QCOMPARE(english.value(64), QByteArray("Facc forward accel."));
        QCOMPARE(english.value(8), QByteArray("E.OH heat sink overtemp"));
        QCOMPARE(german.value(8), QByteArray("E.OH Kuehlkoerper heiss"));
        QVERIFY(english.contains(79)); // StOP

        // The display texts: a 7-segment pattern per value.
        bool sawFcon = false;
        for (quint16 sub = 0; sub < indices.displayCount; ++sub) {
            r = drive.respond(read(Service::DisplayPlaintext,
                                   DisplayPlaintextData { indices.displayIndex, sub, 0, 0, 0, {} }),
                              0);
            QCOMPARE(r.ack, Ack::Ok);
            const auto *d = r.as<DisplayPlaintextData>();
            QVERIFY(d->segments != Sim::SegmentPattern {});
            if (d->value == 66) {
                QCOMPARE(d->segments, *Sim::sevenSegmentPattern(QStringLiteral("Fcon")));
                sawFcon = true;
            }
            if (d->value == 1) {
                QCOMPARE(d->segments, *Sim::sevenSegmentPattern(QStringLiteral("E.OP")));
                QCOMPARE(d->type, quint8(0x02)); // an error replaces the display
            }
        }
        QVERIFY(sawFcon);
        r = drive.respond(
            read(Service::DisplayPlaintext,
                 DisplayPlaintextData { indices.displayIndex, indices.displayCount, 0, 0, 0, {} }),
            0);
        QCOMPARE(r.ack, Ack::DataInvalid);
        r = drive.respond(read(Service::DisplayPlaintext,
                               DisplayPlaintextData { indices.displayIndex, 0, 3, 0, 0, {} }),
                          0);
        QCOMPARE(r.ack, Ack::LanguageInvalid);
    }

    void bitFieldParameterHasSeveralDefinitions()
    {
        SimulatedDrive drive;
        Telegram r = drive.respond(
            read(Service::PlaintextIndices, PlaintextIndicesData { kEnergySaving }), 0);
        const PlaintextIndicesData indices = *r.as<PlaintextIndicesData>();
        QCOMPARE(indices.combivisCount, quint16(3));
        QCOMPARE(indices.displayCount, quint16(0)); // the keypad shows the number
        const quint16 index = indices.combivisIndex;

        struct Expected
        {
            quint32 mask;
            quint8 count;
            const char *english;
            const char *german;
        };
        const Expected expected[] = { { 0x0F, 8, "Function", "Funktion" },
                                      { 0x70, 5, "Ramp time", "Rampenzeit" },
                                      { 0x80, 2, "Display", "Anzeige" } };
        for (quint8 definition = 0; definition < 3; ++definition) {
            for (quint8 language : { 0, 1 }) {
                r = drive.respond(
                    read(Service::PlaintextDefinition,
                         PlaintextDefinitionData { index, definition, language, 0, 0, {} }),
                    0);
                QCOMPARE(r.ack, Ack::Ok);
                QCOMPARE(r.as<PlaintextDefinitionData>()->mask, expected[definition].mask);
                QCOMPARE(r.as<PlaintextDefinitionData>()->count, expected[definition].count);
                QCOMPARE(r.as<PlaintextDefinitionData>()->text,
                         QByteArray(language ? expected[definition].german
                                             : expected[definition].english));
            }
        }
        // Values stand in place within their mask.
        r = drive.respond(
            read(Service::CombivisPlaintext, CombivisPlaintextData { index, 1, 2, 0, 0, 0, {} }),
            0);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(r.as<CombivisPlaintextData>()->value, 0x20);
        QCOMPARE(r.as<CombivisPlaintextData>()->text, QByteArray("ramp time / 4"));
        r = drive.respond(
            read(Service::CombivisPlaintext, CombivisPlaintextData { index, 0, 2, 1, 0, 0, {} }),
            0);
        QCOMPARE(r.as<CombivisPlaintextData>()->value, 2);
        QCOMPARE(r.as<CombivisPlaintextData>()->text, QByteArray("bei Istwert = Sollwert"));

        // Beyond the definitions and texts: data invalid.
        r = drive.respond(
            read(Service::PlaintextDefinition, PlaintextDefinitionData { index, 3, 0, 0, 0, {} }),
            0);
        QCOMPARE(r.ack, Ack::DataInvalid);
        QVERIFY(r.as<PlaintextDefinitionData>()->text.isEmpty());
        r = drive.respond(
            read(Service::CombivisPlaintext, CombivisPlaintextData { index, 3, 0, 0, 0, 0, {} }),
            0);
        QCOMPARE(r.ack, Ack::DataInvalid);
        r = drive.respond(
            read(Service::CombivisPlaintext, CombivisPlaintextData { index, 0, 8, 0, 0, 0, {} }),
            0);
        QCOMPARE(r.ack, Ack::DataInvalid);
        r = drive.respond(
            read(Service::CombivisPlaintext, CombivisPlaintextData { index, 0, 0, 2, 0, 0, {} }),
            0);
        QCOMPARE(r.ack, Ack::LanguageInvalid);
        QVERIFY(r.as<CombivisPlaintextData>()->text.isEmpty());
        r = drive.respond(
            read(Service::PlaintextDefinition, PlaintextDefinitionData { index, 0, 2, 0, 0, {} }),
            0);
        QCOMPARE(r.ack, Ack::LanguageInvalid);

        // The value itself combines the fields: function 2, ramp time / 4.
        QCOMPARE(drive.respond(writeValue(kEnergySaving, 0x22), 0).ack, Ack::Ok);
    }

    void unknownPlaintextIndicesAreInvalid()
    {
        SimulatedDrive drive;
        for (quint16 index : { quint16(0), quint16(9999) }) {
            QCOMPARE(drive
                         .respond(read(Service::DisplayPlaintext,
                                       DisplayPlaintextData { index, 0, 0, 0, 0, {} }),
                                  0)
                         .ack,
                     Ack::DataInvalid);
            QCOMPARE(drive
                         .respond(read(Service::CombivisPlaintext,
                                       CombivisPlaintextData { index, 0, 0, 0, 0, 0, {} }),
                                  0)
                         .ack,
                     Ack::DataInvalid);
            QCOMPARE(drive
                         .respond(read(Service::PlaintextDefinition,
                                       PlaintextDefinitionData { index, 0, 0, 0, 0, {} }),
                                  0)
                         .ack,
                     Ack::DataInvalid);
        }
        // A parameter without plaintexts says so with zero counts.
        const Telegram r
            = drive.respond(read(Service::PlaintextIndices, PlaintextIndicesData { 0x031C }), 0);
        QCOMPARE(r.ack, Ack::Ok);
        QCOMPARE(*r.as<PlaintextIndicesData>(), (PlaintextIndicesData { 0x031C, 0, 0, 0, 0 }));
    }

    void operatorCannotWriteMetadata()
    {
        SimulatedDrive drive;
        for (int service = 2; service <= 12; ++service) {
            const auto s = Service(service);
            ServiceData data = emptyDataFor(s);
            std::visit(
                [](auto &d) {
                    if constexpr (requires { d.address; })
                        d.address = 0x031C;
                },
                data);
            const Telegram r = drive.respond(write(s, data), 0);
            QVERIFY2(r.ack == Ack::ServiceNotAvailable, qPrintable(serviceName(s)));
        }
        const Telegram limits = drive.respond(read(Service::Limits, ParameterLimits { 0x031C }), 0);
        QCOMPARE(limits.as<ParameterLimits>()->upper, 30000);
    }

    void identifiesAsSimulatedDrive()
    {
        SimulatedDrive drive;
        Telegram r = drive.respond(read(Service::Fieldbus, FieldbusData { 1, 0, 0, {} }), 0);
        QCOMPARE(r.ack, Ack::Ok);
        const QByteArray text = r.as<FieldbusData>()->data;
        QVERIFY(text.startsWith("DriveDesk simulated COMBIVERT F5"));
        QVERIFY(text.size() <= 64);
        QCOMPARE(QString::fromLatin1(text), drive.identification());
        for (quint8 function : { 0, 2, 3, 4 }) {
            r = drive.respond(read(Service::Fieldbus, FieldbusData { function, 0, 0, {} }), 0);
            QCOMPARE(r.ack, Ack::ServiceNotAvailable);
        }
        QCOMPARE(drive.respond(write(Service::Fieldbus, FieldbusData { 1, 0, 0, "x" }), 0).ack,
                 Ack::ServiceNotAvailable);
    }

    void sevenSegmentPatterns()
    {
        const auto pattern = Sim::sevenSegmentPattern(QStringLiteral("E.OP"));
        QVERIFY(pattern);
        QCOMPARE(*pattern, (Sim::SegmentPattern { 0x00, 0x00, 0x79 | 0x80, 0x3F, 0x73 }));
        QCOMPARE(Sim::sevenSegmentText(*Sim::sevenSegmentPattern(QStringLiteral("noP"))),
                 QStringLiteral("noP"));
        QVERIFY(!Sim::sevenSegmentPattern(QStringLiteral("toolong")));
        QVERIFY(!Sim::sevenSegmentPattern(QStringLiteral("a+b")));
    }
};

QTEST_GUILESS_MAIN(TestSimMetadata)
#include "tst_simmetadata.moc"
