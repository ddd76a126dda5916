#include "Hsp5TestSupport.h"

#include "protocol/hsp5/Hsp5Decoder.h"

#include <QDir>
#include <QFile>
#include <QTest>

using namespace DriveDesk;
using namespace Hsp5TestSupport;
using Hsp5SeedVectors::hex;

// The HSP5 stream decoder: any split of the stream, telegrams glued together, garbage, broken
// telegrams, inverter-started requests, and the fuzz corpus replayed.
class TestHsp5Decoder : public QObject
{
    Q_OBJECT
private slots:
    void anySplitGivesTheSameTelegrams_data()
    {
        QTest::addColumn<Role>("role");
        QTest::newRow("operator") << Role::Operator;
        QTest::newRow("drive") << Role::Drive;
    }

    void anySplitGivesTheSameTelegrams()
    {
        QFETCH(Role, role);
        QByteArray stream;
        QList<Decoded> expected;
        for (const auto &v : Hsp5SeedVectors::all()) {
            if (receiver(v.telegram) == role) {
                stream += v.bytes; // glued together, no gaps
                expected.append(v.telegram);
            }
        }
        QVERIFY(expected.size() > 30);
        const Run whole = decode(role, stream);
        QVERIFY2(whole.items == expected, qPrintable(show(whole.items)));
        QVERIFY(decode(role, byteByByte(stream)).items == expected);
        for (qsizetype cut = 1; cut < stream.size(); ++cut) {
            const Run run = decode(role, {stream.first(cut), stream.sliced(cut)});
            QVERIFY2(run.items == expected, qPrintable(QStringLiteral("cut at %1").arg(cut)));
            QCOMPARE(run.left, 0);
        }
    }

    void garbageBeforeBetweenAndAfterIsOneErrorEach()
    {
        const QByteArray a = hex("10 80 00 00 00 46 00 D6");
        const QByteArray b = hex("20 C0 00 E0");
        const QByteArray stream = hex("FF 00 77") + a + hex("00 00 88 00") + b + hex("FF EE");
        const Run run = decode(Role::Operator, stream);
        QCOMPARE(run.items.size(), 4);
        QCOMPARE(errorAt(run, 0)->kind, DecodeError::Kind::UnexpectedByte);
        QCOMPARE(errorAt(run, 0)->bytes, hex("FF 00 77"));
        const QString detail = errorAt(run, 0)->detail;
        QVERIFY2(detail.contains(QStringLiteral("FFh starts no telegram")), qPrintable(detail));
        QVERIFY(std::holds_alternative<Telegram>(run.items[1]));
        QCOMPARE(errorAt(run, 2)->bytes, hex("00 00 88 00"));
        QCOMPARE(std::get<Telegram>(run.items[3]).operatorInvoke, quint8(2));
        // Trailing garbage waits for the next telegram to end its run.
        QCOMPARE(run.left, 2);
        QCOMPARE(bytesOf(run.items), stream.first(stream.size() - 2));

        const auto decoder = Hsp5Codec(Hsp5Services::WithExtensions).makeDecoder(Role::Operator);
        decoder->feed(stream);
        while (decoder->next()) { }
        decoder->feed(a);
        const auto tail = decoder->next();
        QVERIFY(tail && std::holds_alternative<DecodeError>(*tail));
        QCOMPARE(std::get<DecodeError>(*tail).bytes, hex("FF EE"));
        QVERIFY(decoder->next() && decoder->buffered() == 0);
    }

    void wrongBccIsOneErrorAndTheNextTelegramSurvives()
    {
        const QByteArray good = hex("10 80 00 00 00 46 00 D6");
        const QByteArray broken = hex("20 80 00 00 00 46 00 3F"); // expected E6h
        const QByteArray next = hex("30 C0 00 F0");
        const QByteArray stream = good + broken + next;
        const Run run = decode(Role::Operator, stream);
        QCOMPARE(run.items.size(), 4);
        QVERIFY(std::holds_alternative<Telegram>(run.items[0]));
        const DecodeError *bcc = errorAt(run, 1);
        QVERIFY(bcc);
        QCOMPARE(bcc->kind, DecodeError::Kind::ChecksumMismatch);
        QCOMPARE(bcc->operatorInvoke, quint8(2));
        QCOMPARE(bcc->answer(), Ack::BccError);
        QVERIFY2(bcc->detail.contains(QStringLiteral("BCC 3Fh, expected E6h")),
                 qPrintable(bcc->detail));
        // The rest of the broken telegram is one error, not one per byte.
        QCOMPARE(errorAt(run, 2)->kind, DecodeError::Kind::UnexpectedByte);
        QCOMPARE(bcc->bytes + errorAt(run, 2)->bytes, broken);
        QCOMPARE(std::get<Telegram>(run.items[3]).operatorInvoke, quint8(3));
        QCOMPARE(bytesOf(run.items), stream);
        for (qsizetype cut = 1; cut < stream.size(); ++cut)
            QVERIFY(decode(Role::Operator, {stream.first(cut), stream.sliced(cut)}).items
                    == run.items);
        QVERIFY(decode(Role::Operator, byteByByte(stream)).items == run.items);
    }

    void wrongBccOfTheWorkedExampleNamesBothValues()
    {
        const Run run = decode(Role::Operator, hex("10 80 00 00 00 46 00 3F"));
        QVERIFY(errorAt(run, 0));
        QCOMPARE(errorAt(run, 0)->kind, DecodeError::Kind::ChecksumMismatch);
        QVERIFY(errorAt(run, 0)->detail.startsWith(QStringLiteral("BCC 3Fh, expected D6h")));
        QCOMPARE(errorAt(run, 0)->operatorInvoke, quint8(1));
    }

    void aBrokenRequestIsAnsweredWithItsInvokeId()
    {
        // The drive side: a request with a wrong BCC gives ack 5 for INV-ID-OP 4.
        const Run run = decode(Role::Drive, hex("40 00 20 00 20 11") + hex("50 00 20 00 20 50"));
        QCOMPARE(errorAt(run, 0)->kind, DecodeError::Kind::ChecksumMismatch);
        QCOMPARE(errorAt(run, 0)->operatorInvoke, quint8(4));
        QCOMPARE(std::get<Telegram>(run.items.last()).operatorInvoke, quint8(5));
    }

    void unknownServicesAreTypedErrors_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("named");
        QTest::newRow("15") << hex("10 0F 00 1F") << QStringLiteral("service 15");
        QTest::newRow("54") << hex("10 36 01 27") << QStringLiteral("service 54");
        QTest::newRow("63 write") << hex("10 7F 6F") << QStringLiteral("service 63");
        QTest::newRow("21 write") << hex("10 55 00 45") << QStringLiteral("service 21");
    }

    void unknownServicesAreTypedErrors()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, named);
        const QByteArray next = hex("20 00 20 00 20 20");
        const Run run = decode(Role::Drive, bytes + next);
        const DecodeError *error = errorAt(run, 0);
        QVERIFY(error);
        QCOMPARE(error->kind, DecodeError::Kind::UnknownService);
        QCOMPARE(error->operatorInvoke, quint8(1));
        QCOMPARE(error->answer(), Ack::ServiceNotAvailable);
        QVERIFY2(error->detail.contains(named), qPrintable(error->detail));
        QCOMPARE(run.items.size(), 3); // the error, the rest of the bytes, the next request
        QCOMPARE(std::get<Telegram>(run.items.last()).operatorInvoke, quint8(2));
        QCOMPARE(bytesOf(run.items), bytes + next);
    }

    void impossibleLengthsAndAcknowledgesAreFramingErrors_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("named");
        QTest::newRow("text 25") << hex("10 86 19") + QByteArray(25, 'x') + hex("00 00")
                                 << QStringLiteral("text length 25 exceeds 24");
        QTest::newRow("data 65") << hex("10 8D 41") + QByteArray(65, 'x') + hex("00 00")
                                 << QStringLiteral("data length 65 exceeds 64");
        QTest::newRow("ack 16") << hex("10 C0 10 C0") << QStringLiteral("acknowledge 16");
    }

    void impossibleLengthsAndAcknowledgesAreFramingErrors()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, named);
        const Run run = decode(Role::Operator, bytes + hex("10 C0 00 D0"));
        QVERIFY(errorAt(run, 0));
        QCOMPARE(errorAt(run, 0)->kind, DecodeError::Kind::Framing);
        QVERIFY2(errorAt(run, 0)->detail.contains(named), qPrintable(errorAt(run, 0)->detail));
        QVERIFY(std::holds_alternative<Telegram>(run.items.last()));
        QCOMPARE(bytesOf(run.items), bytes + hex("10 C0 00 D0"));
    }

    void outOfStepFailuresFoldIntoTheGarbageRun()
    {
        // Once garbage came, a broken telegram is just more of it: one error, then the telegram.
        const QByteArray stream = hex("FF") + hex("20 80 00 00 00 46 00 3F") + hex("10 0F")
                                  + hex("30 C0 00 F0");
        const Run run = decode(Role::Operator, stream);
        QCOMPARE(run.items.size(), 2);
        QCOMPARE(errorAt(run, 0)->kind, DecodeError::Kind::UnexpectedByte);
        QCOMPARE(errorAt(run, 0)->bytes, stream.first(stream.size() - 4));
    }

    void endlessGarbageIsReportedInBoundedRuns()
    {
        const QByteArray garbage(200, '\xFF');
        const Run run = decode(Role::Operator, garbage);
        QCOMPARE(run.items.size(), 3); // 64 + 64 + 64, 8 still waiting
        QCOMPARE(run.left, 8);
        QCOMPARE(errorAt(run, 0)->bytes.size(), Hsp5Decoder::kMaxSkippedRun);
    }

    void inverterRequestsAreNeverTakenForResponses()
    {
        const QByteArray inverterWrite = hex("01 42 21 01 12 34 56 78 23 45 67 89 E3");
        const QByteArray operatorAnswer = hex("01 C2 00 C3");
        const QByteArray reply = hex("10 80 00 00 00 46 00 D6");
        const Run atOperator = decode(Role::Operator, inverterWrite + operatorAnswer + reply);
        QCOMPARE(atOperator.items.size(), 3);
        const auto &request = std::get<Telegram>(atOperator.items[0]);
        QCOMPARE(request.direction, Direction::Request);
        QCOMPARE(request.inverterInvoke, quint8(1));
        QCOMPARE(request.operatorInvoke, quint8(0));
        // The operator's own answer coming back (an echo) is no response for the operator.
        QCOMPARE(errorAt(atOperator, 1)->kind, DecodeError::Kind::UnexpectedByte);
        QCOMPARE(errorAt(atOperator, 1)->bytes, operatorAnswer);

        const QByteArray operatorRead = hex("10 00 20 00 20 10");
        const Run atDrive = decode(Role::Drive, operatorAnswer + inverterWrite + operatorRead);
        const auto &answer = std::get<Telegram>(atDrive.items[0]);
        QCOMPARE(answer.direction, Direction::Response);
        QCOMPARE(answer.inverterInvoke, quint8(1));
        QCOMPARE(errorAt(atDrive, 1)->kind, DecodeError::Kind::UnexpectedByte);
        QCOMPARE(errorAt(atDrive, 1)->bytes, inverterWrite);
        QCOMPARE(std::get<Telegram>(atDrive.items[2]).operatorInvoke, quint8(1));
    }

    void resetDropsPartialInput()
    {
        const auto decoder = Hsp5Codec(Hsp5Services::WithExtensions).makeDecoder(Role::Operator);
        decoder->feed(hex("10 80 00 00"));
        QVERIFY(!decoder->next());
        QCOMPARE(decoder->buffered(), 4);
        decoder->reset();
        QCOMPARE(decoder->buffered(), 0);
        decoder->feed(hex("10 80 00 00 00 46 00 D6"));
        const auto item = decoder->next();
        QVERIFY(item && std::holds_alternative<Telegram>(*item));
    }

    void corpusReplay()
    {
        const QDir dir(QStringLiteral(DRIVEDESK_TEST_DATA "/fuzz/hsp5"));
        const QStringList files = dir.entryList(QDir::Files);
        QVERIFY2(files.size() > 10, qPrintable(dir.path()));
        const Hsp5Codec codec(Hsp5Services::WithExtensions);
        for (const QString &name : files) {
            QFile file(dir.filePath(name));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QByteArray input = file.readAll();
            for (Role role : {Role::Operator, Role::Drive}) {
                const Run run = decode(role, input);
                // Every byte is accounted for once; every telegram re-encodes to its own bytes.
                QVERIFY2(bytesOf(run.items) == input.first(input.size() - run.left),
                         qPrintable(name));
                for (const Decoded &item : run.items) {
                    if (const auto *t = std::get_if<Telegram>(&item))
                        QVERIFY2(decode(role, codec.encode(*t)).items == QList<Decoded>{*t},
                                 qPrintable(name));
                }
                const qsizetype cut = input.size() / 2;
                QVERIFY2(decode(role, {input.first(cut), input.sliced(cut)}).items == run.items,
                         qPrintable(name));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestHsp5Decoder)
#include "tst_hsp5decoder.moc"
