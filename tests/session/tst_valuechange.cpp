#include "session/ValueChange.h"

#include <QTest>

#include <deque>

using namespace DriveDesk;

namespace {

constexpr quint16 kMinSpeedForward = 0x030A; // op.10, 8 sets

// A sink whose requests wait until the test answers them, in any order: a drive that finishes
// a read before a write sent ahead of it, or whose answer to a write gets lost.
class ScriptedSink : public RequestSink
{
public:
    struct Waiting
    {
        Telegram request;
        std::function<void(const Reply &)> done;
    };

    QList<Telegram> sent;
    std::deque<Waiting> waiting;

    void submit(const Telegram &request, std::function<void(const Reply &)> done) override
    {
        sent << request;
        waiting.push_back({request, std::move(done)});
    }
    void cancelPending() override {}
    bool supports(Service, Access) const override { return true; }

    // Answers the waiting request at `index` (0: the oldest).
    void answer(std::size_t index, Reply::Status status, std::optional<qint32> value = {},
                Ack ack = Ack::Ok)
    {
        Waiting next = std::move(waiting.at(index));
        waiting.erase(waiting.begin() + std::ptrdiff_t(index));
        Reply reply;
        reply.request = next.request;
        reply.status = status;
        reply.attempts = 1;
        if (status == Reply::Status::Ok || status == Reply::Status::Refused) {
            reply.response = next.request.response(ack);
            if (value) {
                auto *data = reply.response.as<ParameterValue>();
                data->value = *value;
            }
        }
        next.done(reply);
    }

    // The index of the waiting read of `set` (service 0, one set), -1 if there is none.
    int readOf(int set) const
    {
        for (std::size_t i = 0; i < waiting.size(); ++i) {
            const Telegram &request = waiting.at(i).request;
            const auto *value = request.as<ParameterValue>();
            if (!request.isWrite() && value && value->set == quint8(1u << set))
                return int(i);
        }
        return -1;
    }
};

ValueChange change(quint8 sets, qint32 raw)
{
    return ValueChange{kMinSpeedForward, true, {WriteStep{sets, raw, false}}, {}, true};
}

} // namespace

// One change written and read back: over HSP5 the read-backs go right behind the write, and
// each counts only where the write was answered OK and the read shows what it wrote.
class TestValueChange : public QObject
{
    Q_OBJECT
private slots:
    void theReadBacksFollowTheWriteWithoutWaitingForItsAnswer()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Hsp5, change(0x05, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        QCOMPARE(sink.sent.size(), 3); // the write, then sets 0 and 2 read
        QVERIFY(sink.sent.at(0).isWrite());
        QCOMPARE(sink.readOf(0), 1);
        QCOMPARE(sink.readOf(2), 2);
        sink.answer(0, Reply::Status::Ok);
        QVERIFY(!outcome); // the reads are still on their way
        sink.answer(0, Reply::Status::Ok, 100);
        sink.answer(0, Reply::Status::Ok, 100);
        QVERIFY(outcome);
        QCOMPARE(sink.sent.size(), 3); // nothing asked again
        QVERIFY(outcome->ok());
        QCOMPARE(outcome->acknowledgedMask, quint8(0x05));
        QCOMPARE(outcome->readBack[0], std::optional<qint32>(100));
        QCOMPARE(outcome->readBack[2], std::optional<qint32>(100));
    }

    // The drive may finish a read before the write ahead of it, or the write needed another
    // attempt after the read went out: the old value it shows is no read-back of the write.
    void aReadThatShowsTheOldValueIsAskedAgainAfterTheWritesAnswer()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Hsp5, change(0x05, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        QCOMPARE(sink.sent.size(), 3);
        sink.answer(std::size_t(sink.readOf(0)), Reply::Status::Ok, 50); // before the write
        sink.answer(std::size_t(sink.readOf(2)), Reply::Status::Ok, 100);
        QCOMPARE(sink.sent.size(), 3); // the write is not answered yet: nothing to decide
        sink.answer(0, Reply::Status::Ok);
        QVERIFY(!outcome);
        QCOMPARE(sink.sent.size(), 4);
        QCOMPARE(sink.readOf(0), 0); // set 0 read again, set 2 not
        sink.answer(0, Reply::Status::Ok, 100);
        QVERIFY(outcome);
        QCOMPARE(outcome->readBack[0], std::optional<qint32>(100));
        QCOMPARE(outcome->readBack[2], std::optional<qint32>(100));
        QVERIFY(outcome->readBackError.isEmpty());
    }

    // No answer to the write: even a read behind it that shows the new value does not make it
    // written (a later attempt, or none, may be what the drive took). A read after the write's
    // end settles it: no answer is not a refusal.
    void aReadBehindAWriteWithoutAnswerDoesNotCount()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Hsp5, change(0x01, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        QCOMPARE(sink.sent.size(), 2);
        sink.answer(1, Reply::Status::Ok, 100);
        sink.answer(0, Reply::Status::Timeout);
        QVERIFY(!outcome);
        QCOMPARE(sink.sent.size(), 3);
        QCOMPARE(sink.readOf(0), 0); // read again once the write has ended
        sink.answer(0, Reply::Status::Ok, 100);
        QVERIFY(outcome);
        QCOMPARE(outcome->acknowledgedMask, quint8(0x01));
        QCOMPARE(outcome->confirmedByReadingMask, quint8(0x01));
        QCOMPARE(outcome->unansweredMask, quint8(0));
        QCOMPARE(outcome->refusedMask, quint8(0));
        QCOMPARE(outcome->readBack[0], std::optional<qint32>(100));
        QVERIFY(outcome->ok());
    }

    void aWriteWithoutAnswerWhoseSetHoldsAnotherValueWasNotWritten()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Din66019II, change(0x04, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        sink.answer(0, Reply::Status::Timeout);
        QCOMPARE(sink.readOf(2), 0);
        sink.answer(0, Reply::Status::Ok, 50);
        QVERIFY(outcome);
        QCOMPARE(outcome->acknowledgedMask, quint8(0));
        QCOMPARE(outcome->refusedMask, quint8(0x04));
        QCOMPARE(outcome->unansweredMask, quint8(0)); // settled: the drive holds 50
        QCOMPARE(outcome->readBack[2], std::optional<qint32>(50));
        QVERIFY(!outcome->ok());
    }

    void aWriteWithoutAnswerWhoseSetCannotBeReadStaysUnknown()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Din66019II, change(0x04, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        sink.answer(0, Reply::Status::Timeout);
        sink.answer(0, Reply::Status::Timeout);
        QVERIFY(outcome);
        QCOMPARE(outcome->unansweredMask, quint8(0x04));
        QVERIFY(outcome->anyUnknown());
        QVERIFY(!outcome->readBack[2]);
        QVERIFY(!outcome->readBackError.isEmpty());
    }

    // Service 1: the active set has no bit of its own in the masks.
    void anActiveSetWriteWithoutAnswerIsSettledByReadingIt()
    {
        for (const qint32 held : {100, 50}) {
            ScriptedSink sink;
            std::optional<WriteOutcome> outcome;
            sendValueChange(sink, Protocol::Din66019II, change(0x00, 100),
                            [&outcome](const WriteOutcome &o) { outcome = o; });
            sink.answer(0, Reply::Status::Timeout);
            QCOMPARE(sink.waiting.size(), std::size_t(1));
            QVERIFY(!sink.waiting.front().request.isWrite());
            sink.answer(0, Reply::Status::Ok, held);
            QVERIFY(outcome);
            QVERIFY(!outcome->anyUnknown());
            QCOMPARE(outcome->activeSetAcknowledged, held == 100);
            QCOMPARE(outcome->activeSetConfirmedByReading, held == 100);
            QCOMPARE(outcome->ok(), held == 100);
            QCOMPARE(outcome->readBack[0], std::optional<qint32>(held));
        }
    }

    // A garbled answer whose checksum passed: a value outside the parameter's limits cannot be
    // what the drive holds. It is read again, and never shown as the drive's.
    void anImpossibleReadBackIsReadAgainAndNeverBelieved()
    {
        for (const bool clearsUp : {true, false}) {
            ScriptedSink sink;
            std::optional<WriteOutcome> outcome;
            ValueChange written = change(0x04, 4);
            written.implausible = [](qint32 value) {
                return value >= 0 && value <= 8 ? QString() : QStringLiteral("outside 0 .. 8");
            };
            sendValueChange(sink, Protocol::Din66019II, written,
                            [&outcome](const WriteOutcome &o) { outcome = o; });
            sink.answer(0, Reply::Status::Ok);
            sink.answer(0, Reply::Status::Ok, 276);
            QVERIFY(!outcome);
            sink.answer(0, Reply::Status::Ok, clearsUp ? 4 : 276);
            if (!clearsUp) {
                QVERIFY(!outcome);
                sink.answer(0, Reply::Status::Ok, 276);
            }
            QVERIFY(outcome);
            QCOMPARE(sink.sent.size(), clearsUp ? 3 : 4);
            QCOMPARE(outcome->acknowledgedMask, quint8(0x04));
            if (clearsUp) {
                QCOMPARE(outcome->readBack[2], std::optional<qint32>(4));
                QVERIFY(outcome->readBackError.isEmpty());
            } else {
                QVERIFY(!outcome->readBack[2]);
                QVERIFY2(outcome->readBackError.contains(QLatin1String("outside 0 .. 8")),
                         qPrintable(outcome->readBackError));
            }
        }
    }

    // The link went after the drive acknowledged: not read back, and nothing more is asked.
    void aReadLostWithTheLinkLeavesTheSetUnread()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Hsp5, change(0x01, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        sink.answer(0, Reply::Status::Ok);
        sink.answer(0, Reply::Status::LinkLost);
        QVERIFY(outcome);
        QCOMPARE(sink.sent.size(), 2);
        QCOMPARE(outcome->acknowledgedMask, quint8(0x01));
        QVERIFY(!outcome->readBack[0]);
        QVERIFY(!outcome->readBackError.isEmpty());
        QVERIFY(outcome->connectionFailed);
    }

    void aRefusedWriteIsNotReadBack()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Hsp5, change(0x01, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        sink.answer(0, Reply::Status::Refused, {}, Ack::WriteProtected);
        sink.answer(0, Reply::Status::Ok, 100);
        QVERIFY(outcome);
        QCOMPARE(outcome->refusedMask, quint8(0x01));
        QCOMPARE(outcome->unansweredMask, quint8(0));
        QVERIFY(!outcome->readBack[0]);
        QVERIFY(!outcome->ok());
    }

    // Half duplex: one request at a time on the line anyway; the read waits for the answer.
    void dinReadsBackAfterTheAnswer()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        sendValueChange(sink, Protocol::Din66019II, change(0x01, 100),
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        QCOMPARE(sink.sent.size(), 1);
        sink.answer(0, Reply::Status::Ok);
        QCOMPARE(sink.sent.size(), 2);
        sink.answer(0, Reply::Status::Ok, 100);
        QVERIFY(outcome);
        QCOMPARE(outcome->readBack[0], std::optional<qint32>(100));
    }

    // A set that a later step writes again is read once, after that step.
    void aSetWrittenTwiceIsReadAfterItsLastWrite()
    {
        ScriptedSink sink;
        std::optional<WriteOutcome> outcome;
        ValueChange twice{kMinSpeedForward, true,
                          {WriteStep{0x03, 100, false}, WriteStep{0x01, 200, false}}, {}, true};
        sendValueChange(sink, Protocol::Hsp5, twice,
                        [&outcome](const WriteOutcome &o) { outcome = o; });
        QCOMPARE(sink.sent.size(), 1); // the first step's sets are written again after it
        sink.answer(0, Reply::Status::Ok);
        QCOMPARE(sink.sent.size(), 3); // the second step and its read
        sink.answer(0, Reply::Status::Ok);
        QCOMPARE(sink.sent.size(), 3);
        sink.answer(0, Reply::Status::Ok, 200);
        QCOMPARE(sink.sent.size(), 4); // set 1, the first step's, read now
        QCOMPARE(sink.readOf(1), 0);
        sink.answer(0, Reply::Status::Ok, 100);
        QVERIFY(outcome);
        QCOMPARE(sink.sent.size(), 4);
        QCOMPARE(outcome->readBack[0], std::optional<qint32>(200));
        QCOMPARE(outcome->readBack[1], std::optional<qint32>(100));
    }
};

QTEST_GUILESS_MAIN(TestValueChange)
#include "tst_valuechange.moc"
