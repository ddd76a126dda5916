#include "ClientTestSupport.h"
#include "SpoilingProxy.h"

#include "bus/SimulatorServer.h"
#include "client/ClientTiming.h"

#include <QElapsedTimer>
#include <QRegularExpression>
#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

using Spoil = SpoilingProxy::Spoil;

Q_DECLARE_METATYPE(DriveDesk::Protocol)
Q_DECLARE_METATYPE(DriveDesk::ClientTest::SpoilingProxy::Spoil)

namespace {

// A link that answers only garbage is stopped within 10 s at 38400 Bd (garbageLimitMs(), over
// TCP 5.4 s at most), with room for a busy machine.
constexpr int kLimitMs = 10000;
constexpr int kReads = 12;

// Values of the simulated F5 the reads ask for, and what each holds.
struct Expected
{
    quint16 address;
    qint32 value;
};
constexpr Expected kValues[] = {
    { kMaxSpeedForward, kMaxSpeedDefault },
    { kMotorVoltage, 400 },
    { kCurrentLimit, 150 },
};

const Expected &expectedFor(int read)
{
    return kValues[read % std::size(kValues)];
}

} // namespace

// A link on which nothing valid arrives (answers cut, stale, of the wrong length, random, an
// endless stream) does not answer: the client says so after kUnansweredRequestsToStop requests
// in a row, as for a drive gone silent, and says what came instead. A line that merely repeats
// its answers is still read.
class TestClientGarbage : public QObject
{
    Q_OBJECT
private slots:
    void theBoundFollowsTheLine_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<bool>("tcp");
        QTest::addColumn<int>("limitMs");
        // docs/client.md, "A drive that stops answering".
        QTest::newRow("hsp5 38400") << Protocol::Hsp5 << false << 2396;
        QTest::newRow("din 38400") << Protocol::Din66019II << false << 2091;
        QTest::newRow("hsp5 tcp 38400") << Protocol::Hsp5 << true << 5426;
        QTest::newRow("din tcp 38400") << Protocol::Din66019II << true << 4641;
    }

    void theBoundFollowsTheLine()
    {
        QFETCH(Protocol, protocol);
        QFETCH(bool, tcp);
        QFETCH(int, limitMs);
        ConnectionSettings settings;
        settings.kind = tcp ? ConnectionSettings::Kind::Tcp : ConnectionSettings::Kind::Serial;
        settings.protocol = protocol;
        settings.baudRate = 38400;
        QCOMPARE(garbageLimitMs(settings, {}), limitMs);
        QVERIFY(limitMs < kLimitMs);
    }

    void readsEndWhenNothingValidComes_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<Spoil>("spoil");
        QTest::addColumn<QString>("cameInstead");
        const QString wrongLength = QStringLiteral("frames of the wrong length");
        const QString stale = QStringLiteral("answers to an earlier request");
        const QString checksum = QStringLiteral("frames with a wrong checksum");
        const QString unframed = QStringLiteral("bytes that never made a telegram");
        const QString foreign = QStringLiteral("answers to no request sent");
        const auto row
            = [](const char *name, Protocol protocol, Spoil spoil, const QString &cameInstead) {
                  QTest::newRow(name) << protocol << spoil << cameInstead;
              };
        for (const Protocol protocol : { Protocol::Hsp5, Protocol::Din66019II }) {
            const bool hsp5 = protocol == Protocol::Hsp5;
            const auto name = [hsp5](const char *what) {
                return QByteArray(hsp5 ? "hsp5 " : "din ").append(what);
            };
            row(name("cut in half"), protocol, Spoil::CutInHalf, wrongLength);
            row(name("stale"), protocol, Spoil::Stale, stale);
            row(name("one byte more"), protocol, Spoil::OneByteMore, wrongLength);
            row(name("one byte less"), protocol, Spoil::OneByteLess, wrongLength);
            row(name("random bytes"), protocol, Spoil::RandomBytes, unframed);
            row(name("endless random"), protocol, Spoil::EndlessRandom, unframed);
            row(name("endless stx digits"), protocol, Spoil::EndlessDigits, unframed);
            // To DIN66019II, "1 ACK" is a short answer: to a read it is none, nor to any
            // request sent.
            row(name("endless 1 ack"), protocol, Spoil::EndlessAck, hsp5 ? unframed : foreign);
        }
        // A bit stuck on a DIN66019II line: every answer's BCC is wrong. (HSP5's decoder, out of
        // step after such an answer, skips the next one whole: a mix a noisy line gives too.)
        row("din flipped bit", Protocol::Din66019II, Spoil::FlippedBit, checksum);
        row("hsp5 flipped bit", Protocol::Hsp5, Spoil::FlippedBit, checksum);
    }

    void readsEndWhenNothingValidComes()
    {
        QFETCH(Protocol, protocol);
        QFETCH(Spoil, spoil);
        QFETCH(QString, cameInstead);
        ProxiedDrive line(protocol, fast(), spoil);
        QString error;
        QVERIFY2(line.listen(&error), qPrintable(error));
        Session s(line.proxy.settings());
        QVERIFY(s.connected());
        QSignalSpy stopped(s.client.get(), &DriveClient::driveStoppedAnswering);

        // One read after the other, as a job that waits for each answer asks.
        QElapsedTimer timer;
        timer.start();
        Reply last;
        for (int i = 0; i < kReads && last.status != Reply::Status::DriveSilent; ++i) {
            last = replyOf(s.client->readValue(expectedFor(i).address, 1), 2 * kLimitMs);
            if (last.ok())
                QCOMPARE(valueOf(last), expectedFor(i).value);
        }
        const qint64 took = timer.elapsed();
        qInfo("%s: the drive stopped answering after %lld ms", QTest::currentDataTag(), took);
        QCOMPARE(last.status, Reply::Status::DriveSilent);
        QVERIFY2(took < kLimitMs, qPrintable(QStringLiteral("%1 ms").arg(took)));
        QVERIFY(last.isConnectionFailure());
        QVERIFY2(last.message().startsWith(QStringLiteral("the drive stopped answering: ")),
                 qPrintable(last.message()));
        QVERIFY2(last.message().endsWith(cameInstead), qPrintable(last.message()));

        // The worker's news crosses to this thread as a queued signal.
        QTRY_COMPARE(stopped.size(), 1);
        const QString reason = stopped.first().at(0).toString();
        QVERIFY2(reasonSays(reason, cameInstead), qPrintable(reason));
        QVERIFY(s.client->isDriveSilent());
        QCOMPARE(s.client->state(), DriveClient::State::Connected);

        // More garbage is no answer: the drive stays silent (the window's banner stays), and a
        // request goes out once, as the check whether the drive is back.
        const Reply check = s.call(s.client->readValue(kMotorVoltage, 1));
        QCOMPARE(check.status, Reply::Status::DriveSilent);
        QCOMPARE(check.attempts, 1);
        QVERIFY(s.client->isDriveSilent());
        QCOMPARE(stopped.size(), 1);
    }

    // Reads queued at once (HSP5 has several on the wire): the same end, and every read that
    // got an answer got the right one.
    void queuedReadsEndToo_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::addColumn<Spoil>("spoil");
        QTest::addColumn<QString>("cameInstead");
        for (const Protocol protocol : { Protocol::Hsp5, Protocol::Din66019II }) {
            const char *name = protocol == Protocol::Hsp5 ? "hsp5 " : "din ";
            QTest::newRow(QByteArray(name).append("cut in half").constData())
                << protocol << Spoil::CutInHalf << QStringLiteral("frames of the wrong length");
            QTest::newRow(QByteArray(name).append("endless random").constData())
                << protocol << Spoil::EndlessRandom
                << QStringLiteral("bytes that never made a telegram");
        }
    }

    void queuedReadsEndToo()
    {
        QFETCH(Protocol, protocol);
        QFETCH(Spoil, spoil);
        QFETCH(QString, cameInstead);
        ProxiedDrive line(protocol, fast(), spoil);
        QString error;
        QVERIFY2(line.listen(&error), qPrintable(error));
        Session s(line.proxy.settings());
        QVERIFY(s.connected());
        QSignalSpy stopped(s.client.get(), &DriveClient::driveStoppedAnswering);

        QElapsedTimer timer;
        timer.start();
        QList<QFuture<Reply>> reads;
        for (int i = 0; i < kReads; ++i)
            reads << s.client->readValue(expectedFor(i).address, 1);
        for (const QFuture<Reply> &read : reads)
            QVERIFY(waitFinished(read, 2 * kLimitMs));
        const qint64 took = timer.elapsed();
        qInfo("%s: every read ended after %lld ms", QTest::currentDataTag(), took);
        QVERIFY2(took < kLimitMs, qPrintable(QStringLiteral("%1 ms").arg(took)));
        int silent = 0;
        for (int i = 0; i < kReads; ++i) {
            const Reply reply = reads.at(i).result();
            if (reply.ok())
                QCOMPARE(valueOf(reply), expectedFor(i).value);
            if (reply.status == Reply::Status::DriveSilent) {
                ++silent;
                QVERIFY2(reply.message().endsWith(cameInstead), qPrintable(reply.message()));
            }
        }
        QCOMPARE(silent, kReads - (kUnansweredRequestsToStop - 1));
        QTRY_COMPARE(stopped.size(), 1);
        QVERIFY2(reasonSays(stopped.first().at(0).toString(), cameInstead),
                 qPrintable(stopped.first().at(0).toString()));
    }

    // Garbage that goes on after the stop takes nothing back; one valid answer ends the stop,
    // and the drive answers as before.
    void aValidAnswerEndsTheStop_data() { bothProtocols(); }
    void aValidAnswerEndsTheStop()
    {
        QFETCH(Protocol, protocol);
        ProxiedDrive line(protocol, fast(), Spoil::EndlessRandom);
        QString error;
        QVERIFY2(line.listen(&error), qPrintable(error));
        Session s(line.proxy.settings());
        QVERIFY(s.connected());
        QSignalSpy silence(s.client.get(), &DriveClient::driveSilentChanged);

        QList<QFuture<Reply>> reads;
        for (int i = 0; i < kReads; ++i)
            reads << s.client->readValue(expectedFor(i).address, 1);
        for (const QFuture<Reply> &read : reads)
            QVERIFY(waitFinished(read, 2 * kLimitMs));
        QCOMPARE(reads.last().result().status, Reply::Status::DriveSilent);
        QTRY_VERIFY(s.client->isDriveSilent());
        // The stream goes on: the window's banner stays, reported once and not taken back.
        QTest::qWait(500);
        QVERIFY(s.client->isDriveSilent());
        QCOMPARE(silence.size(), 1);

        line.proxy.setSpoil(Spoil::None);
        QTest::qWait(100); // what the stream still had on its way arrives first
        const Reply back = s.call(s.client->readValue(kMotorVoltage, 1));
        QVERIFY2(back.ok(), qPrintable(back.message()));
        QCOMPARE(valueOf(back), 400);
        QTRY_VERIFY(!s.client->isDriveSilent());
        QCOMPARE(silence.size(), 2);
        const Reply next = s.call(s.client->readValue(kMaxSpeedForward, 1));
        QCOMPARE(valueOf(next), kMaxSpeedDefault);
    }

    // A gateway that sends every answer twice: each second copy answers nothing open, and is
    // garbage, but every request has its answer, so nothing stops.
    void doubledAnswersAreStillRead_data() { bothProtocols(); }
    void doubledAnswersAreStillRead()
    {
        QFETCH(Protocol, protocol);
        ProxiedDrive line(protocol, fast(), Spoil::Doubled);
        QString error;
        QVERIFY2(line.listen(&error), qPrintable(error));
        Session s(line.proxy.settings());
        QVERIFY(s.connected());
        QSignalSpy stopped(s.client.get(), &DriveClient::driveStoppedAnswering);

        constexpr int kDoubledReads = 60;
        QList<QFuture<Reply>> reads;
        for (int i = 0; i < kDoubledReads; ++i)
            reads << s.client->readValue(expectedFor(i).address, 1);
        for (int i = 0; i < kDoubledReads; ++i) {
            const Reply reply = replyOf(reads.at(i));
            QVERIFY2(reply.ok(), qPrintable(describeReply(reply)));
            QCOMPARE(valueOf(reply), expectedFor(i).value);
        }
        // And one at a time, each after the one before has its answer (and its copy).
        for (int i = 0; i < 2 * int(std::size(kValues)); ++i) {
            const Reply reply = s.call(s.client->readValue(expectedFor(i).address, 1));
            QVERIFY2(reply.ok(), qPrintable(describeReply(reply)));
            QCOMPARE(valueOf(reply), expectedFor(i).value);
        }
        QVERIFY(line.proxy.answersSeen() >= kDoubledReads);
        QCOMPARE(stopped.size(), 0);
        QVERIFY(!s.client->isDriveSilent());
    }

    // A gateway that spoils one kind of answer only (every text's length byte one too many, its
    // BCC right) while the others come through: the decoder reads on into the next answer. The
    // scan cannot read a group's name; it ends, incomplete, in the time a link that answers
    // only garbage gets from the first text asked for, and says what came instead.
    void aScanWhoseTextsComeTooLongEnds()
    {
        ProxiedDrive line(Protocol::Hsp5, fast(), Spoil::TextLengthGrown);
        QString error;
        QVERIFY2(line.listen(&error), qPrintable(error));
        Session s(line.proxy.settings());
        QVERIFY(s.connected());
        QElapsedTimer timer;
        timer.start();
        // The walk through every group address before it takes what the machine gives it.
        qint64 firstText = -1;
        connect(s.client.get(), &DriveClient::traffic, this, [&](const TrafficRecord &record) {
            const bool text = record.telegram
                && (record.telegram->service == Service::GroupName
                    || record.telegram->service == Service::ParameterName);
            if (firstText < 0 && record.kind == TrafficRecord::Kind::Sent && text)
                firstText = timer.elapsed();
        });
        QTemporaryDir cache;
        ScanOptions options;
        options.metadata = MetadataSource::RefreshCache;
        options.cacheDirectory = cache.path();
        const QFuture<DriveDescription> scan = s.client->scan(options);
        QVERIFY(waitFinished(scan, 12 * kLimitMs));
        const qint64 took = timer.elapsed() - firstText;
        const DriveDescription drive = scan.result();
        qInfo("the scan ended %lld ms after the first text asked for: %s", took,
              qPrintable(drive.incompleteReason));
        QVERIFY(firstText >= 0);
        QVERIFY2(took < kLimitMs, qPrintable(QStringLiteral("%1 ms").arg(took)));
        QVERIFY2(drive.incompleteReason.endsWith(QStringLiteral("frames of the wrong length")),
                 qPrintable(drive.incompleteReason));
    }

private:
    // "16 requests in a row answered only with ...": what came, as the reason of the stop.
    static bool reasonSays(const QString &reason, const QString &cameInstead)
    {
        const QRegularExpression sentence(
            QStringLiteral("^\\d+ request\\S* in a row answered only with %1$")
                .arg(QRegularExpression::escape(cameInstead)));
        return sentence.match(reason).hasMatch();
    }

    static void bothProtocols()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }
};

QTEST_GUILESS_MAIN(TestClientGarbage)
#include "tst_clientgarbage.moc"
