#include "client/ClientTiming.h"
#include "client/Reply.h"
#include "Translations.h"

#include <QTest>
#include <QTranslator>

using namespace DriveDesk;

// What a user reads about a request: one sentence per outcome, with the drive's reason.
class TestReply : public QObject
{
    Q_OBJECT
private slots:
    // English as the programs show it: with its catalogue, which holds the plural forms.
    void initTestCase() { QVERIFY(installTranslations(QStringLiteral("en"))); }

    void refusalNamesTheDrivesReason()
    {
        Reply reply;
        reply.status = Reply::Status::Refused;
        reply.response.ack = Ack::WriteProtected;
        reply.attempts = 1;
        QCOMPARE(reply.message(), QStringLiteral("drive refused: parameter write protected"));
        QTranslator german; // removes itself from the application when it goes
        QVERIFY(german.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
        QVERIFY(QCoreApplication::installTranslator(&german));
        QCOMPARE(reply.message(), QStringLiteral("Umrichter lehnt ab: Parameter schreibgeschützt"));
    }

    void busyToTheEndSaysHowOftenItWasTried()
    {
        Reply reply;
        reply.status = Reply::Status::Refused;
        reply.response.ack = Ack::Busy;
        reply.attempts = 4;
        QCOMPARE(reply.message(),
                 QStringLiteral("drive refused: inverter busy (after 4 attempts)"));
        QTranslator german;
        QVERIFY(german.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
        QVERIFY(QCoreApplication::installTranslator(&german));
        QCOMPARE(reply.message(),
                 QStringLiteral("Umrichter lehnt ab: Umrichter beschäftigt (nach 4 Versuchen)"));
    }

    void timeoutSaysAttemptsAndWhatWentWrong()
    {
        Reply reply;
        reply.status = Reply::Status::Timeout;
        reply.attempts = 4;
        reply.detail = QStringLiteral("3 timeouts, 1 answer with a wrong BCC; timeout 91 ms");
        QCOMPARE(reply.message(), QStringLiteral("no valid answer from the drive after 4 attempts "
                                                 "(3 timeouts, 1 answer with a wrong BCC; "
                                                 "timeout 91 ms)"));
        QTranslator german;
        QVERIFY(german.load(QStringLiteral(":/i18n/drivedesk_de.qm")));
        QVERIFY(QCoreApplication::installTranslator(&german));
        QVERIFY(reply.message().startsWith(
            QStringLiteral("keine gültige Antwort vom Umrichter nach 4 Versuchen (")));
    }

    void everyStatusHasANameAndASentence()
    {
        for (int status = int(Reply::Status::Ok); status <= int(Reply::Status::NoReply); ++status) {
            Reply reply;
            reply.status = Reply::Status(status);
            QVERIFY(!statusName(reply.status).startsWith(QStringLiteral("status ")));
            QVERIFY(!reply.message().isEmpty());
        }
        Reply lost;
        lost.status = Reply::Status::LinkLost;
        lost.detail = QStringLiteral("tcp 127.0.0.1:5020: the device server closed the connection");
        QCOMPARE(lost.message(), QStringLiteral("the connection to the drive was lost (tcp "
                                                "127.0.0.1:5020: the device server closed the "
                                                "connection)"));
    }

    void okHasNoComplaint()
    {
        Reply reply;
        reply.status = Reply::Status::Ok;
        QCOMPARE(reply.message(), QStringLiteral("OK"));
        QVERIFY(reply.ok());
    }

    void timeoutFollowsTheLine()
    {
        ConnectionSettings slow;
        slow.kind = ConnectionSettings::Kind::Serial;
        slow.protocol = Protocol::Din66019II;
        slow.baudRate = 9600;
        ConnectionSettings quick = slow;
        quick.baudRate = 115200;
        QVERIFY(answerTimeoutMs(slow, {}) > answerTimeoutMs(quick, {}));
        ConnectionSettings tcp = quick;
        tcp.kind = ConnectionSettings::Kind::Tcp;
        QVERIFY(answerTimeoutMs(tcp, {}) > answerTimeoutMs(quick, {}));

        ClientOptions fixed;
        fixed.timeoutMs = 250;
        QCOMPARE(answerTimeoutMs(slow, fixed), 250);
        QVERIFY(probeTimeoutMs(slow, {}, 26) < answerTimeoutMs(slow, {}));
    }
};

QTEST_GUILESS_MAIN(TestReply)
#include "tst_reply.moc"
