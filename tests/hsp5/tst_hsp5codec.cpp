#include "Hsp5TestSupport.h"

#include "protocol/hsp5/Hsp5Layout.h"

#include <QTest>

#include <limits>

using namespace DriveDesk;
using namespace Hsp5TestSupport;
using Hsp5SeedVectors::hex;

namespace {

const QList<Service> kServices{
    Service::ParameterValue, Service::ParameterValueStandard, Service::Limits,
    Service::DefaultValue, Service::Properties, Service::DisplayScaling, Service::ParameterName,
    Service::PlaintextIndices, Service::DisplayPlaintext, Service::CombivisPlaintext,
    Service::GroupProperties, Service::GroupName, Service::PlaintextDefinition, Service::Fieldbus,
    Service::SubindexValue, Service::ProcessData1, Service::ProcessData2, Service::Scope,
    Service::ProcessData4, Service::ProcessData5, Service::ScopeRecord, Service::CheckDefault,
    Service::CheckDefaultStandard, Service::ProcessDataDuplex1, Service::ProcessDataDuplex2,
    Service::ProcessDataDuplex3, Service::ProcessDataDuplex4, Service::ProcessDataDuplex5,
    Service::ProcessDataDuplex6};

// Values for the round trips: ordinary, the negative extremes, all bits set and the longest texts.
struct Values
{
    qint32 v32;
    qint16 v16;
    quint16 u16;
    quint8 u8;
    QByteArray text;
    QByteArray data;
};

Values values(int variant)
{
    switch (variant) {
    case 0:
        return {0x12345678, 0x1234, 0x2101, 0x28, "Speed", QByteArray("\x01\x02\x00\x03", 4)};
    case 1:
        return {std::numeric_limits<qint32>::min(), std::numeric_limits<qint16>::min(), 0, 0,
                {}, {}};
    default:
        return {-1, -1, 0xFFFF, 0xFF, QByteArray(24, '\xFC'), QByteArray(64, '\xA5')};
    }
}

// A payload with exactly the fields that travel in this telegram (seed 000 sections 2.1-2.39
// and docs/protocol-hsp5.md), so that decoding gives it back unchanged.
ServiceData onWire(Service s, Access a, Direction d, const Values &v)
{
    const bool duplex = int(s) >= 48;
    const bool request = d == Direction::Request;
    const bool writeRequest = request && (a == Access::Write || duplex);
    const bool readResponse = !request && (a == Access::Read || duplex);
    const bool keyed = request && !duplex;               // what the request addresses
    const bool carried = readResponse || writeRequest;  // values travel here
    const auto key = [&](auto x) { return keyed ? x : decltype(x){}; };
    const auto data = [&](auto x) { return carried ? x : decltype(x){}; };
    const std::array<quint8, 5> segments{v.u8, 0x3F, 0x06, 0x5B, 0x80};
    switch (s) {
    case Service::ParameterValue:
    case Service::ParameterValueStandard:
    case Service::SubindexValue:
        return ParameterValue{key(v.u16), key(v.u8), data(v.v32)};
    case Service::Limits:
        return ParameterLimits{key(v.u16), data(v.v32), data(~v.v32)};
    case Service::DefaultValue:
        return DefaultValue{key(v.u16), data(v.v32)};
    case Service::Properties:
        return PropertiesData{key(v.u16), data(quint32(v.v32)), data(~quint32(v.v32))};
    case Service::DisplayScaling:
        return DisplayScalingData{key(v.u16), data(v.v16), data(qint16(~v.v16)),
                                  data(qint16(v.v16 ^ 0x5555)), data(quint16(v.v16))};
    case Service::ParameterName:
    case Service::GroupName:
        return NameData{key(v.u16), key(v.u8), data(v.text)};
    case Service::PlaintextIndices:
        return PlaintextIndicesData{key(v.u16), data(quint16(v.v16)), data(quint16(1)),
                                    data(quint16(~v.v16)), data(quint16(0xFFFF))};
    case Service::DisplayPlaintext:
        return DisplayPlaintextData{key(v.u16), key(quint16(v.u16 ^ 0xFF)), key(v.u8),
                                    data(v.v32), data(quint8(v.u8 ^ 3)), data(segments)};
    case Service::CombivisPlaintext:
        return CombivisPlaintextData{key(v.u16), key(v.u8), key(quint8(v.u8 ^ 1)), key(v.u8),
                                     data(v.v32), data(quint8(v.u8 ^ 3)), data(v.text)};
    case Service::GroupProperties:
        return GroupPropertiesData{key(v.u16), data(v.u8),
                                   data(std::array<char, 2>{'r', char(v.u8)}), data('u'),
                                   data(quint16(v.v16)), data(v.u8), data(quint8(~v.u8))};
    case Service::PlaintextDefinition:
        return PlaintextDefinitionData{key(v.u16), key(v.u8), key(v.u8), data(quint32(v.v32)),
                                       data(v.u8), data(v.text)};
    case Service::Fieldbus:
        return FieldbusData{key(v.u8), key(v.u16), key(v.u8), data(v.data)};
    case Service::ProcessData1:
    case Service::ProcessData4:
    case Service::ProcessDataDuplex1:
    case Service::ProcessDataDuplex4:
        return ProcessData32{{data(v.v32), data(~v.v32)}};
    case Service::ProcessData2:
    case Service::ProcessData5:
    case Service::ProcessDataDuplex2:
    case Service::ProcessDataDuplex5:
        return ProcessData16{{data(v.v16), data(qint16(~v.v16)), data(qint16(1)), data(v.v16)}};
    case Service::Scope:
        return ScopeData{data(quint16(v.v16)), {data(v.v32), data(~v.v32)},
                         {data(v.v16), data(qint16(~v.v16))}};
    case Service::ScopeRecord:
        return ScopeRecordData{key(v.u8), key(v.u16), data(quint16(v.v16)),
                               {data(v.v32), data(~v.v32), data(1), data(v.v32)}};
    case Service::ProcessDataDuplex3:
    case Service::ProcessDataDuplex6:
        return ProcessParameterData{data(v.v32), data(v.v16), data(qint16(~v.v16)),
                                    writeRequest ? v.u16 : quint16(0), data(~v.v32)};
    case Service::CheckDefault:
    case Service::CheckDefaultStandard:
        return DefaultCheckData{key(v.u16), key(v.u8)};
    default:
        return std::monostate{};
    }
}

Telegram sample(Service s, Access a, Direction d, int variant, bool fromInverter)
{
    Telegram t = Telegram::request(s, a, onWire(s, a, d, values(variant)));
    t.direction = d;
    const quint8 invoke = quint8(variant * 7 + 1); // 1, 8, 15
    (fromInverter ? t.inverterInvoke : t.operatorInvoke) = invoke;
    if (d == Direction::Response)
        t.ack = variant == 2 ? Ack::Free : Ack(variant * 3);
    return t;
}

} // namespace

// The HSP5 codec: seed 000's telegrams byte for byte, the length table, round trips of every
// service, and what it refuses to encode.
class TestHsp5Codec : public QObject
{
    Q_OBJECT
private slots:
    void bccIsXorOfAllBytes()
    {
        QCOMPARE(hsp5Bcc(hex("10 00 20 00 20")), quint8(0x10));
        QCOMPARE(hsp5Bcc(hex("10 80 00 00 00 46 00")), quint8(0xD6));
        QCOMPARE(hsp5Bcc(QByteArray()), quint8(0));
    }

    void codecBasics()
    {
        const Hsp5Codec codec(Hsp5Services::WithExtensions);
        QCOMPARE(codec.protocol(), Protocol::Hsp5);
        QCOMPARE(codec.bitsPerCharacter(), 11);
    }

    void workedExampleOfProtocolNotes()
    {
        const Hsp5Codec codec(Hsp5Services::WithExtensions);
        Telegram request = Telegram::request(Service::ParameterValue, Access::Read,
                                             ParameterValue{0x2000, 0x20, 0});
        request.operatorInvoke = 1;
        QCOMPARE(codec.encode(request), hex("10 00 20 00 20 10"));

        Telegram response = request.response(Ack::Ok);
        response.data = ParameterValue{0, 0, 0x46};
        QCOMPARE(codec.encode(response), hex("10 80 00 00 00 46 00 D6"));

        const Run run = decode(Role::Operator, hex("10 80 00 00 00 46 00 D6"));
        QCOMPARE(run.items.size(), 1);
        const auto *decoded = std::get_if<Telegram>(&run.items.first());
        QVERIFY(decoded);
        QCOMPARE(decoded->operatorInvoke, quint8(1));
        QCOMPARE(decoded->as<ParameterValue>()->value, 0x46);
        QCOMPARE(decoded->ack, Ack::Ok);
    }

    void seedExamples_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<Telegram>("telegram");
        for (const auto &v : Hsp5SeedVectors::all())
            QTest::newRow(v.section) << v.bytes << v.telegram;
    }

    void seedExamples()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(Telegram, telegram);
        QString error;
        QCOMPARE(Hsp5Codec(Hsp5Services::WithExtensions).encode(telegram, &error).toHex(' '), bytes.toHex(' '));
        QVERIFY(error.isEmpty());
        const Run run = decode(receiver(telegram), bytes);
        QVERIFY2(run.items == QList<Decoded>{telegram}, qPrintable(show(run.items)));
        QCOMPARE(run.left, 0);
    }

    void lengthsOfTheSeedTable_data()
    {
        QTest::addColumn<Service>("service");
        QTest::addColumn<QList<int>>("lengths"); // read request/response, write request/response
        QTest::addColumn<bool>("variable");      // read response and write request carry a text
        const auto row = [](const char *name, Service s, QList<int> lengths,
                            bool variable = false) {
            QTest::newRow(name) << s << lengths << variable;
        };
        row("0", Service::ParameterValue, {6, 8, 10, 4});
        row("1", Service::ParameterValueStandard, {6, 8, 10, 4});
        row("2", Service::Limits, {5, 12, 13, 4});
        row("3", Service::DefaultValue, {5, 8, 9, 4});
        row("4", Service::Properties, {5, 12, 13, 4});
        row("5", Service::DisplayScaling, {5, 12, 13, 4});
        row("6", Service::ParameterName, {6, 5, 7, 4}, true);
        row("7", Service::PlaintextIndices, {5, 12, 13, 4});
        row("8", Service::DisplayPlaintext, {8, 14, 18, 4});
        row("9", Service::CombivisPlaintext, {8, 10, 14, 4}, true);
        row("10", Service::GroupProperties, {5, 12, 13, 4});
        row("11", Service::GroupName, {6, 5, 7, 4}, true);
        row("12", Service::PlaintextDefinition, {7, 10, 13, 4}, true);
        row("16", Service::ProcessData1, {3, 12, 11, 4});
        row("17", Service::ProcessData2, {3, 12, 11, 4});
        row("18", Service::Scope, {3, 18, 17, 4});
        row("32", Service::CheckDefault, {6, 4, 6, 4});
        row("33", Service::CheckDefaultStandard, {6, 4, 6, 4});
        row("48", Service::ProcessDataDuplex1, {11, 12, 11, 12});
        row("49", Service::ProcessDataDuplex2, {11, 12, 11, 12});
        row("50", Service::ProcessDataDuplex3, {17, 16, 17, 16});
        // DriveDesk's extensions (docs/protocol-hsp5.md).
        row("13 extension", Service::Fieldbus, {7, 5, 8, 4}, true);
        row("14 extension", Service::SubindexValue, {6, 8, 10, 4});
        row("19 extension", Service::ProcessData4, {3, 12, 11, 4});
        row("20 extension", Service::ProcessData5, {3, 12, 11, 4});
        row("21 extension", Service::ScopeRecord, {6, 22, 0, 0});
        row("51 extension", Service::ProcessDataDuplex4, {11, 12, 11, 12});
        row("52 extension", Service::ProcessDataDuplex5, {11, 12, 11, 12});
        row("53 extension", Service::ProcessDataDuplex6, {17, 16, 17, 16});
    }

    void lengthsOfTheSeedTable()
    {
        QFETCH(Service, service);
        QFETCH(QList<int>, lengths);
        QFETCH(bool, variable);
        const bool extension = QByteArray(QTest::currentDataTag()).endsWith("extension");
        const Hsp5Services services
            = extension ? Hsp5Services::WithExtensions : Hsp5Services::Seed;
        const Hsp5Codec codec(services);
        // A drive that knows only seed 000 cannot frame an extension: the default codec never
        // sends one.
        QCOMPARE(Hsp5Codec().supports(service, Access::Read), !extension);
        const int longest = service == Service::Fieldbus ? 64 : 24;
        int column = 0;
        for (Access a : {Access::Read, Access::Write}) {
            for (Direction d : {Direction::Request, Direction::Response}) {
                const int expected = lengths[column++];
                QCOMPARE(codec.supports(service, a), expected != 0);
                if (expected == 0) {
                    QVERIFY(!hsp5Layout(service, a, d, services));
                    continue;
                }
                const bool carriesText = variable
                                         && (a == Access::Read) == (d == Direction::Response);
                // Variant 1 has empty texts, variant 2 the longest.
                QCOMPARE(codec.encode(sample(service, a, d, 1, false)).size(), expected);
                QCOMPARE(codec.encode(sample(service, a, d, 2, false)).size(),
                         expected + (carriesText ? longest : 0));
                QCOMPARE(hsp5Layout(service, a, d, services)->isVariable(), carriesText);
                QCOMPARE(hsp5Layout(service, a, d).has_value(), !extension);
            }
        }
    }

    void roundTripEveryService()
    {
        const Hsp5Codec codec(Hsp5Services::WithExtensions);
        for (Service s : kServices) {
            for (Access a : {Access::Read, Access::Write}) {
                if (!codec.supports(s, a))
                    continue;
                for (Direction d : {Direction::Request, Direction::Response}) {
                    for (int variant = 0; variant < 3; ++variant) {
                        for (bool fromInverter : {false, true}) {
                            const Telegram t = sample(s, a, d, variant, fromInverter);
                            QString error;
                            const QByteArray bytes = codec.encode(t, &error);
                            QVERIFY2(!bytes.isEmpty(), qPrintable(error));
                            const Run run = decode(receiver(t), bytes);
                            QVERIFY2(run.items == QList<Decoded>{t},
                                     qPrintable(describe(t) + QStringLiteral(" -> ")
                                                + show(run.items)));
                        }
                    }
                }
            }
        }
    }

    void encodeRejectsWhatHsp5CannotSay_data()
    {
        QTest::addColumn<Telegram>("telegram");
        QTest::addColumn<QString>("named");
        const auto op = [](Service s, Access a, ServiceData d = {}) {
            return Hsp5SeedVectors::op(s, a, Direction::Request, std::move(d));
        };
        for (Service s : {Service::Legacy, Service::StatusInterrogation, Service::Unspecified}) {
            QTest::newRow(qPrintable(serviceName(s))) << op(s, Access::Read, ParameterValue{})
                                                      << QStringLiteral("HSP5 has no");
        }
        QTest::newRow("21 write") << op(Service::ScopeRecord, Access::Write)
                                  << QStringLiteral("service 21");
        QTest::newRow("text 25")
            << op(Service::ParameterName, Access::Write, NameData{1, 0, QByteArray(25, 'a')})
            << QStringLiteral("text of 25 bytes");
        QTest::newRow("data 65")
            << op(Service::Fieldbus, Access::Write, FieldbusData{0, 1, 0, QByteArray(65, 'a')})
            << QStringLiteral("data of 65 bytes");
        QTest::newRow("payload") << op(Service::Limits, Access::Read, ParameterValue{})
                                 << QStringLiteral("payload");
        Telegram noInvoke = op(Service::ParameterValue, Access::Read);
        noInvoke.operatorInvoke = 0;
        QTest::newRow("no invoke id") << noInvoke << QStringLiteral("exactly one");
        Telegram bothInvoke = noInvoke;
        bothInvoke.operatorInvoke = bothInvoke.inverterInvoke = 3;
        QTest::newRow("both invoke ids") << bothInvoke << QStringLiteral("exactly one");
        Telegram bigInvoke = noInvoke;
        bigInvoke.operatorInvoke = 16;
        QTest::newRow("invoke 16") << bigInvoke << QStringLiteral("0..15");
        Telegram bigAck = op(Service::ParameterValue, Access::Write).response(Ack(16));
        QTest::newRow("ack 16") << bigAck << QStringLiteral("acknowledge 16");
    }

    void encodeRejectsWhatHsp5CannotSay()
    {
        QFETCH(Telegram, telegram);
        QFETCH(QString, named);
        QString error;
        QVERIFY(Hsp5Codec(Hsp5Services::WithExtensions).encode(telegram, &error).isEmpty());
        QVERIFY2(error.contains(named), qPrintable(error));
    }

    void supportsOnlyHsp5Services()
    {
        const Hsp5Codec codec(Hsp5Services::WithExtensions);
        for (Service s : {Service::Legacy, Service::StatusInterrogation, Service::Unspecified}) {
            QVERIFY(!codec.supports(s, Access::Read));
            QVERIFY(!codec.supports(s, Access::Write));
        }
        for (Service s : kServices)
            QVERIFY(codec.supports(s, Access::Read));
        QVERIFY(!codec.supports(Service::ScopeRecord, Access::Write));
        for (int number = 0; number < 64; ++number) {
            const bool seed = (number <= 12) || (number >= 16 && number <= 18) || number == 32
                              || number == 33 || (number >= 48 && number <= 50);
            const bool extension = number == 13 || number == 14 || (number >= 19 && number <= 21)
                                   || (number >= 51 && number <= 53);
            QCOMPARE(hsp5Service(number).has_value(), seed);
            QCOMPARE(hsp5Service(number, Hsp5Services::WithExtensions).has_value(),
                     seed || extension);
        }
    }

    void theSeedCodecRefusesExtensionsWithAHint()
    {
        const Hsp5Codec codec;
        QCOMPARE(codec.services(), Hsp5Services::Seed);
        QString error;
        const Telegram identify
            = Hsp5SeedVectors::op(Service::Fieldbus, Access::Read, Direction::Request,
                                  FieldbusData{1, 0, 0, {}});
        QVERIFY(codec.encode(identify, &error).isEmpty());
        QVERIFY2(error.contains(QStringLiteral("HSP5 extensions")), qPrintable(error));
        QVERIFY(!Hsp5Codec(Hsp5Services::WithExtensions).encode(identify).isEmpty());
        // A drive that knows only the seed's services cannot know where service 13 ends.
        const auto decoder = codec.makeDecoder(Role::Drive);
        decoder->feed(Hsp5Codec(Hsp5Services::WithExtensions).encode(identify));
        const auto item = decoder->next();
        QVERIFY(item);
        const auto *decodeError = std::get_if<DecodeError>(&*item);
        QVERIFY(decodeError);
        QCOMPARE(decodeError->kind, DecodeError::Kind::UnknownService);
    }

};

QTEST_GUILESS_MAIN(TestHsp5Codec)
#include "tst_hsp5codec.moc"
