#include "client/ReplyCheck.h"

#include <QTest>

using namespace DriveDesk;

namespace {

Telegram sent(Service service, Access access, ServiceData data, quint8 invokeId)
{
    Telegram telegram = Telegram::request(service, access, std::move(data));
    telegram.operatorInvoke = invokeId;
    return telegram;
}

// A DIN66019II short answer as the operator's decoder gives it.
Telegram shortAnswer(quint8 invokeId, Ack ack, Access access)
{
    Telegram telegram;
    telegram.service = Service::Unspecified;
    telegram.direction = Direction::Response;
    telegram.access = access;
    telegram.operatorInvoke = invokeId;
    telegram.ack = ack;
    return telegram;
}

} // namespace

// Every answer is checked against the request it would answer before it is accepted.
class TestReplyCheck : public QObject
{
    Q_OBJECT
private slots:
    void hsp5AnswerMatchesItsRequest()
    {
        const Telegram request = sent(Service::ParameterValue, Access::Read,
                                      ParameterValue{0x2000, 0x20, 0}, 1);
        Telegram answer = request.response();
        answer.data = ParameterValue{0, 0, 0x46}; // HSP5 answers carry the value only
        QCOMPARE(replyMismatch(Protocol::Hsp5, request, answer), QString());

        const Telegram complete = completeAnswer(request, answer);
        QCOMPARE(*complete.as<ParameterValue>(), (ParameterValue{0x2000, 0x20, 0x46}));
    }

    void hsp5AnswerOfAnotherCycleIsRejected()
    {
        const Telegram request = sent(Service::ParameterValue, Access::Read,
                                      ParameterValue{0x2000, 1, 0}, 3);
        Telegram answer = request.response();
        answer.operatorInvoke = 4;
        const QString why = replyMismatch(Protocol::Hsp5, request, answer);
        QVERIFY2(why.contains(QStringLiteral("invoke id 4, expected 3")), qPrintable(why));
    }

    void hsp5AnswerOfAnotherServiceOrAccessIsRejected()
    {
        const Telegram request = sent(Service::ParameterValue, Access::Read,
                                      ParameterValue{0x2000, 1, 0}, 3);
        Telegram other = request.response();
        other.service = Service::ParameterValueStandard;
        const QString why = replyMismatch(Protocol::Hsp5, request, other);
        QVERIFY2(why.contains(QStringLiteral("service 1")), qPrintable(why));

        Telegram written = request.response();
        written.access = Access::Write;
        QVERIFY(replyMismatch(Protocol::Hsp5, request, written).contains(QStringLiteral("write")));
    }

    void aRequestIsNoAnswer()
    {
        const Telegram request = sent(Service::Limits, Access::Read, ParameterLimits{0x0300}, 2);
        QVERIFY(!replyMismatch(Protocol::Hsp5, request, request).isEmpty());
    }

    void payloadOfTheWrongTypeIsRejected()
    {
        const Telegram request = sent(Service::Limits, Access::Read, ParameterLimits{0x0300}, 2);
        Telegram answer = request.response();
        answer.data = DefaultValue{0, 5};
        QVERIFY(!replyMismatch(Protocol::Hsp5, request, answer).isEmpty());
    }

    void dinShortAcknowledgeAnswersAWrite()
    {
        const Telegram request = sent(Service::ParameterValue, Access::Write,
                                      ParameterValue{0x0300, 1, -2}, 14);
        const Telegram answer = shortAnswer(14, Ack::Ok, Access::Write);
        QCOMPARE(replyMismatch(Protocol::Din66019II, request, answer), QString());
        const Telegram complete = completeAnswer(request, answer);
        QCOMPARE(complete.service, Service::ParameterValue);
        QCOMPARE(*complete.as<ParameterValue>(), (ParameterValue{0x0300, 1, -2}));
    }

    void dinShortAcknowledgeNeverAnswersAValueRead()
    {
        const Telegram request = sent(Service::ParameterValue, Access::Read,
                                      ParameterValue{0x0200, 2, 0}, 1);
        const QString why = replyMismatch(Protocol::Din66019II, request,
                                          shortAnswer(1, Ack::Ok, Access::Write));
        QVERIFY2(why.contains(QStringLiteral("bare acknowledge")), qPrintable(why));
        // ... but does answer the default check, a read.
        const Telegram check = sent(Service::CheckDefault, Access::Read,
                                    DefaultCheckData{0x0200, 1}, 5);
        QCOMPARE(replyMismatch(Protocol::Din66019II, check, shortAnswer(5, Ack::Ok, Access::Write)),
                 QString());
    }

    void dinRefusalMustCarryTheInvokeId()
    {
        const Telegram request = sent(Service::ParameterValue, Access::Read,
                                      ParameterValue{0x0200, 2, 0}, 1);
        QCOMPARE(replyMismatch(Protocol::Din66019II, request,
                               shortAnswer(1, Ack::AddressInvalid, Access::Read)),
                 QString());
        QVERIFY(!replyMismatch(Protocol::Din66019II, request,
                               shortAnswer(2, Ack::AddressInvalid, Access::Read))
                     .isEmpty());
    }

    void dinDataAnswerToAWriteIsRejected()
    {
        const Telegram request = sent(Service::ParameterValue, Access::Write,
                                      ParameterValue{0x0300, 1, 7}, 6);
        Telegram answer = request.response();
        answer.access = Access::Read;
        QVERIFY(!replyMismatch(Protocol::Din66019II, request, answer).isEmpty());
    }

    void legacyAnswerCarriesItsAddress()
    {
        const Telegram request = sent(Service::Legacy, Access::Read,
                                      ParameterValue{0x2001, 0, 0}, 0);
        Telegram answer = request.response();
        answer.data = ParameterValue{0x2001, 0, 5};
        QCOMPARE(replyMismatch(Protocol::Din66019, request, answer), QString());
        answer.data = ParameterValue{0x2011, 0, 5};
        const QString why = replyMismatch(Protocol::Din66019, request, answer);
        QVERIFY2(why.contains(QStringLiteral("2011h")), qPrintable(why));
        // Legacy short answers name no invoke id: they are taken by order.
        QCOMPARE(replyMismatch(Protocol::Din66019, request,
                               shortAnswer(0, Ack::DataInvalid, Access::Read)),
                 QString());
    }

    void namesKeepAddressAndLanguageOfTheRequest()
    {
        const Telegram request = sent(Service::ParameterName, Access::Read,
                                      NameData{0x2000, 1, {}}, 11);
        Telegram answer = request.response();
        answer.data = NameData{0, 0, QByteArrayLiteral("Status")};
        QCOMPARE(replyMismatch(Protocol::Din66019II, request, answer), QString());
        const Telegram complete = completeAnswer(request, answer);
        QCOMPARE(*complete.as<NameData>(), (NameData{0x2000, 1, QByteArrayLiteral("Status")}));
    }

    void whatCannotBeTrueIsNamed()
    {
        const auto answer = [](ServiceData data) {
            return Telegram::request(Service::Unspecified, Access::Read, std::move(data))
                .response();
        };
        QCOMPARE(implausibleAnswer(answer(NameData{0x0314, 0, "Fixed speed 1"})), QString());
        QVERIFY(implausibleAnswer(answer(NameData{0x0314, 0, "Fixed\x05speed 1"}))
                    .contains(QStringLiteral("05h")));
        // What follows the terminating NUL is padding, not text.
        QCOMPARE(implausibleAnswer(answer(NameData{0x0314, 0, QByteArray("Hz\0\x01", 4)})),
                 QString());
        QCOMPARE(implausibleAnswer(answer(ParameterLimits{0x030B, 0, 4000})), QString());
        QVERIFY(!implausibleAnswer(answer(ParameterLimits{0x030B, 4000, 0})).isEmpty());
        QCOMPARE(implausibleAnswer(answer(DisplayScalingData{0x030B, 1, 1, 0, 0})), QString());
        QVERIFY(implausibleAnswer(answer(DisplayScalingData{0x030B, 0, 1, 0, 0}))
                    .contains(QStringLiteral("divisor 0")));

        ParameterDescription onOff;
        onOff.minimum = 0;
        onOff.maximum = 1;
        QCOMPARE(implausibleValue(onOff, 1), QString());
        QVERIFY(implausibleValue(onOff, 500).contains(QStringLiteral("500")));
    }
};

QTEST_GUILESS_MAIN(TestReplyCheck)
#include "tst_replycheck.moc"
