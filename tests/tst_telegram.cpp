#include "protocol/Acknowledge.h"
#include "protocol/Codec.h"
#include "protocol/Telegram.h"

#include <QTest>
#include <QTranslator>

using namespace DriveDesk;

// The shared service layer: payload types, acknowledge texts, protocol names.
class TestTelegram : public QObject
{
    Q_OBJECT
private slots:
    void everyServiceHasItsPayloadType()
    {
        QVERIFY(std::holds_alternative<ParameterValue>(emptyDataFor(Service::ParameterValue)));
        QVERIFY(std::holds_alternative<ParameterValue>(emptyDataFor(Service::Legacy)));
        QVERIFY(std::holds_alternative<NameData>(emptyDataFor(Service::GroupName)));
        QVERIFY(std::holds_alternative<ProcessParameterData>(emptyDataFor(Service::ProcessDataDuplex6)));
        QVERIFY(std::holds_alternative<std::monostate>(emptyDataFor(Service::Unspecified)));
    }

    void responseKeepsInvokeIdsAndPayload()
    {
        Telegram request = Telegram::request(Service::ParameterValue, Access::Read,
                                             ParameterValue{0x2000, 0x20, 0});
        request.operatorInvoke = 7;
        request.driveAddress = 2;
        const Telegram response = request.response(Ack::DataInvalid);
        QCOMPARE(response.direction, Direction::Response);
        QCOMPARE(response.operatorInvoke, quint8(7));
        QCOMPARE(response.ack, Ack::DataInvalid);
        QCOMPARE(response.driveAddress, -1);
        QCOMPARE(response.as<ParameterValue>()->address, quint16(0x2000));
    }

    void everyAcknowledgeHasEnglishAndGermanText()
    {
        QStringList english;
        for (int code = 0; code < 16; ++code)
            english << ackText(Ack(code));
        QVERIFY(!english.contains(QString()));
        QCOMPARE(ackText(Ack::WriteProtected), QStringLiteral("parameter write protected"));

        QTranslator german; // removes itself from the application when it goes
        QVERIFY(german.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
        QVERIFY(QCoreApplication::installTranslator(&german));
        for (int code = 1; code < 16; ++code)
            QVERIFY2(ackText(Ack(code)) != english.at(code), qPrintable(english.at(code)));
        QCOMPARE(ackText(Ack::Ok), QStringLiteral("OK"));
        QCOMPARE(ackText(Ack::DataInvalid), QStringLiteral("Daten ungültig"));
    }

    void protocolNamesRoundTrip()
    {
        for (Protocol p : {Protocol::Hsp5, Protocol::Din66019II, Protocol::Din66019})
            QCOMPARE(protocolFromName(protocolName(p)), p);
        QCOMPARE(protocolFromName(QStringLiteral("DIN66019II")), Protocol::Din66019II);
        QVERIFY(!protocolFromName(QStringLiteral("modbus")));
    }

    void describeNamesServiceAndAck()
    {
        Telegram t = Telegram::request(Service::ParameterValue, Access::Read,
                                       ParameterValue{0x0203, 1, 0});
        const QString text = describe(t.response(Ack::Busy));
        QVERIFY2(text.contains(QStringLiteral("0203h")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("inverter busy")), qPrintable(text));
    }
};

QTEST_GUILESS_MAIN(TestTelegram)
#include "tst_telegram.moc"
