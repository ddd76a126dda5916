#include "BusTestSupport.h"
#include "bus/SimulatedBus.h"
#include "sim/SimulatedDrive.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::BusTest;

namespace {

SimulationOptions quietOptions(QList<int> addresses = {1})
{
    SimulationOptions options;
    options.driveAddresses = addresses;
    options.replyLatencyUs = 1000;
    return options;
}

// Sends bytes at time t and returns everything the drives send back, whenever due.
QByteArray exchange(SimulatedBus &bus, const QByteArray &bytes, qint64 t = 0)
{
    bus.receive(bytes, t);
    return bus.takeDue(kForever);
}

QByteArray send(SimulatedBus &bus, const Operator &op, const Telegram &request, qint64 t = 0)
{
    return exchange(bus, op.encode(request), t);
}

// The telegrams that come back for a request sent at time t.
QList<Telegram> ask(SimulatedBus &bus, Operator &op, const Telegram &request, qint64 t = 0)
{
    return op.telegrams(exchange(bus, op.encode(request), t));
}

} // namespace

// The simulated drives on a byte stream: protocol rules, timing and injected faults.
class TestSimulatedBus : public QObject
{
    Q_OBJECT
private slots:
    void hsp5RequestIsAnswered()
    {
        SimulatedBus bus(Protocol::Hsp5, quietOptions());
        Operator op(Protocol::Hsp5);
        const QList<Telegram> replies = ask(bus, op, readValue(kStateAddress, 1));
        QCOMPARE(replies.size(), 1);
        QVERIFY(replies[0].isResponse());
        QCOMPARE(replies[0].operatorInvoke, quint8(1));
        QCOMPARE(replies[0].service, Service::ParameterValue);
        QCOMPARE(replies[0].ack, Ack::Ok);
        QCOMPARE(bus.counters().requests, 1);
        QCOMPARE(bus.counters().replies, 1);
    }

    void hsp5WriteThenReadBack()
    {
        SimulatedBus bus(Protocol::Hsp5, quietOptions());
        Operator op(Protocol::Hsp5);
        QList<Telegram> replies = ask(bus, op, writeValue(kWritableAddress, 42, 2));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].ack, Ack::Ok);
        replies = ask(bus, op, readValue(kWritableAddress, 3));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].as<ParameterValue>()->value, 42);
    }

    void hsp5WrongBccIsAnsweredWithAck5()
    {
        SimulatedBus bus(Protocol::Hsp5, quietOptions());
        Operator op(Protocol::Hsp5);
        QByteArray broken = op.encode(readValue(kStateAddress, 4));
        broken.back() = char(broken.back() ^ 0x01);
        const QList<Telegram> replies = op.telegrams(exchange(bus, broken));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].operatorInvoke, quint8(4));
        QCOMPARE(replies[0].service, Service::ParameterValue);
        QCOMPARE(replies[0].ack, Ack::BccError);
        QVERIFY(bus.counters().decodeErrors >= 1);

        // The line recovers: the repeated request gets its value.
        const QList<Telegram> again = ask(bus, op, readValue(kStateAddress, 5), 100'000'000);
        QCOMPARE(again.size(), 1);
        QCOMPARE(again[0].operatorInvoke, quint8(5));
        QCOMPARE(again[0].ack, Ack::Ok);
    }

    void hsp5GarbageStaysUnanswered()
    {
        SimulatedBus bus(Protocol::Hsp5, quietOptions());
        // Byte 0 with both invoke ids zero starts no telegram.
        QCOMPARE(exchange(bus, QByteArrayLiteral("\x00\x00\x00\x00")), QByteArray());
        QCOMPARE(bus.counters().replies, 0);
    }

    void hsp5PartialTelegramIsForgottenAfterAPause()
    {
        SimulatedBus bus(Protocol::Hsp5, quietOptions());
        Operator op(Protocol::Hsp5);
        const QByteArray request = op.encode(readValue(kStateAddress, 6));
        bus.receive(request.first(3), 0); // the rest is lost on the line
        const QList<Telegram> replies = ask(bus, op, readValue(kStateAddress, 7), 50'000'000);
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].operatorInvoke, quint8(7));
        QCOMPARE(bus.counters().partialDrops, 1);
    }

    void aSilentBusTakesNothingAndAnswersNothing()
    {
        SimulatedBus bus(Protocol::Hsp5, quietOptions());
        Operator op(Protocol::Hsp5);
        bus.setSilent(true);
        QVERIFY(bus.isSilent());
        const QByteArray request = op.encode(readValue(kStateAddress, 1));
        QCOMPARE(exchange(bus, request), QByteArray());
        // Half a telegram while frozen is not the start of the next one.
        bus.receive(request.first(3), 1'000'000);
        QCOMPARE(bus.counters().requests, 0);
        QCOMPARE(bus.counters().ignoredWhileSilent, request.size() + 3);

        bus.setSilent(false);
        const QList<Telegram> replies = ask(bus, op, readValue(kStateAddress, 2), 2'000'000);
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].operatorInvoke, quint8(2));
        QCOMPARE(replies[0].ack, Ack::Ok);
    }

    void dinNoAnswerWithoutSelection()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions());
        Operator op(Protocol::Din66019II);
        QCOMPARE(send(bus, op, readValue(kStateAddress, 1)), QByteArray());
        QCOMPARE(bus.counters().unanswered, 1);
        const QList<Telegram> replies = ask(bus, op, readValue(kStateAddress, 2, 1));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].operatorInvoke, quint8(2));
        QCOMPARE(replies[0].ack, Ack::Ok);
    }

    void dinSelectionHoldsUntilNextEot()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions({1, 2}));
        Operator op(Protocol::Din66019II);
        QCOMPARE(ask(bus, op, writeValue(kWritableAddress, 11, 1, 1)).size(), 1);
        QCOMPARE(bus.selection(), 1);
        // No EOT: still drive 1.
        QList<Telegram> replies = ask(bus, op, readValue(kWritableAddress, 2));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].as<ParameterValue>()->value, 11);
        // EOT 02: drive 2, which kept its own value.
        replies = ask(bus, op, readValue(kWritableAddress, 3, 2));
        QCOMPARE(replies.size(), 1);
        QVERIFY(replies[0].as<ParameterValue>()->value != 11);
        QCOMPARE(bus.selection(), 2);
    }

    void drivesOnOneBusHaveSettingsOfTheirOwn()
    {
        constexpr quint16 kAccelerationTime = 0x031C; // op.28
        constexpr quint16 kSoftwareVersion = 0x0E06;  // In.06
        constexpr quint16 kInverterIdentifier = 0x0002; // Sy.02
        SimulationOptions options = quietOptions({2, 5, 9, 11});
        options.otherKindAddresses = {9};
        options.unidentifiedAddresses = {11};
        SimulatedBus bus(Protocol::Din66019II, options);
        Operator op(Protocol::Din66019II);
        quint8 invoke = 0;
        const auto valueAt = [&](int drive, quint16 address) -> std::optional<qint32> {
            const QList<Telegram> replies = ask(bus, op, readValue(address, ++invoke, drive));
            if (replies.size() != 1 || replies[0].ack != Ack::Ok)
                return std::nullopt;
            return replies[0].as<ParameterValue>()->value;
        };
        const std::optional<qint32> two = valueAt(2, kAccelerationTime);
        QVERIFY(two && valueAt(5, kAccelerationTime));
        QVERIFY(*two != *valueAt(5, kAccelerationTime));
        // A change to one drive is found on that one only.
        QCOMPARE(ask(bus, op, writeValue(kAccelerationTime, 1234, ++invoke, 5)).size(), 1);
        QCOMPARE(valueAt(5, kAccelerationTime), 1234);
        QCOMPARE(valueAt(2, kAccelerationTime), two);
        // Drive 9 runs other software; drive 11 cannot say what it is.
        QVERIFY(*valueAt(9, kSoftwareVersion) != *valueAt(2, kSoftwareVersion));
        QCOMPARE(bus.drive(2).parameterCount(), bus.drive(0).parameterCount() + 24);
        QVERIFY(valueAt(2, kInverterIdentifier));
        QVERIFY(!valueAt(11, kInverterIdentifier));
        QVERIFY(valueAt(11, kAccelerationTime));
    }

    void paddedDrivesOnOneBusShareTheirMetadata()
    {
        // One kind, one metadata: the metadata cache serves a scan of drive 2 to drive 5.
        SimulationOptions options = quietOptions({2, 5});
        options.parameterCount = 300;
        SimulatedBus bus(Protocol::Din66019II, options);
        for (quint16 address = 0x2000; address < 0x2000 + 94; ++address) {
            const Telegram limits = Telegram::request(Service::Limits, Access::Read,
                                                      ParameterLimits{address});
            QCOMPARE(bus.drive(1).respond(limits, 0), bus.drive(0).respond(limits, 0));
        }
    }

    void dinNegativeReadDropsSelection()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions());
        Operator op(Protocol::Din66019II);
        const QByteArray answer = send(bus, op, readValue(kMissingAddress, 1, 1));
        QVERIFY2(answer.endsWith('\x04'), answer.toHex(' ').constData()); // IID code EOT
        const QList<Telegram> replies = op.telegrams(answer);
        QCOMPARE(replies.size(), 1);
        QVERIFY(replies[0].ack != Ack::Ok);
        QCOMPARE(bus.selection(), -1);
        // Without a new selection nobody answers.
        QCOMPARE(send(bus, op, readValue(kStateAddress, 2)), QByteArray());
        QCOMPARE(ask(bus, op, readValue(kStateAddress, 3, 1)).size(), 1);
    }

    void dinNegativeWriteKeepsSelection()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions());
        Operator op(Protocol::Din66019II);
        const QList<Telegram> replies = ask(bus, op, writeValue(kMissingAddress, 1, 1, 1));
        QCOMPARE(replies.size(), 1);
        QVERIFY(replies[0].ack != Ack::Ok);
        QCOMPARE(bus.selection(), 1);
    }

    void dinWrongBccIsAnsweredWithCode5()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions());
        Operator op(Protocol::Din66019II);
        QByteArray write = op.encode(writeValue(kWritableAddress, 8, 3, 1));
        write.back() = char(write.back() ^ 0x01);
        QCOMPARE(exchange(bus, write), QByteArrayLiteral("35\x15")); // IID 3, code 5, NAK
        QCOMPARE(bus.selection(), 1);
        QByteArray read = op.encode(readValue(kWritableAddress, 4));
        read.back() = char(read.back() ^ 0x01);
        QCOMPARE(exchange(bus, read), QByteArrayLiteral("45\x04")); // IID 4, code 5, EOT
        QCOMPARE(bus.selection(), -1);
    }

    void dinSurvivesFaults()
    {
        SimulationOptions options = quietOptions({1, 2});
        options.corruptByteRate = 0.005;
        options.dropByteRate = 0.005;
        options.busyRate = 0.1;
        options.seed = 3;
        SimulatedBus bus(Protocol::Din66019II, options);
        Operator op(Protocol::Din66019II);
        int good = 0;
        for (int i = 0; i < 2000; ++i) {
            const qint64 t = i * 100'000'000LL;
            bus.receive(op.encode(readValue(kStateAddress, quint8(i % 15 + 1), 1 + i % 2)), t);
            for (const Decoded &item : op.decode(bus.takeDue(t + 50'000'000))) {
                const auto *reply = std::get_if<Telegram>(&item);
                good += reply && reply->ack == Ack::Ok ? 1 : 0;
            }
        }
        const BusCounters &c = bus.counters();
        QCOMPARE(c.encodeFailures, 0);
        QVERIFY2(c.busyReplies > 150 && c.busyReplies < 250,
                 qPrintable(QString::number(c.busyReplies)));
        QVERIFY2(good > 1400, qPrintable(QString::number(good)));
    }

    void dinOnlyTheSelectedDriveAnswers()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions({1, 2, 3}));
        Operator op(Protocol::Din66019II);
        QCOMPARE(bus.driveCount(), 3);
        for (int address : {1, 2, 3}) {
            const QList<Telegram> replies = ask(bus, op, readValue(kStateAddress, 1, address));
            QCOMPARE(replies.size(), 1);
        }
        QCOMPARE(send(bus, op, readValue(kStateAddress, 1, 7)), QByteArray());
        QCOMPARE(bus.counters().replies, 3);
    }

    void dinBroadcastAndGroupWritesAreCarriedOutUnanswered()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions({1, 2, 17}));
        Operator op(Protocol::Din66019II);
        QCOMPARE(send(bus, op, writeValue(kWritableAddress, 77, 1, 0xFF)), QByteArray());
        QCOMPARE(send(bus, op, readValue(kWritableAddress, 2)), QByteArray()); // no reads
        for (int address : {1, 2, 17}) {
            const QList<Telegram> replies = ask(bus, op, readValue(kWritableAddress, 3, address));
            QCOMPARE(replies.size(), 1);
            QCOMPARE(replies[0].as<ParameterValue>()->value, 77);
        }
        // Group F0: addresses 0..15 only.
        QCOMPARE(send(bus, op, writeValue(kWritableAddress, 55, 4, 0xF0)), QByteArray());
        const QList<int> expected{55, 55, 77};
        const QList<int> addresses{1, 2, 17};
        for (int i = 0; i < addresses.size(); ++i) {
            const QList<Telegram> replies
                = ask(bus, op, readValue(kWritableAddress, 5, addresses[i]));
            QCOMPARE(replies.size(), 1);
            QCOMPARE(replies[0].as<ParameterValue>()->value, expected[i]);
        }
    }

    void dinStatusInterrogationCollectsBroadcastResult()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions({1, 2}));
        Operator op(Protocol::Din66019II);
        Telegram status = Telegram::request(Service::StatusInterrogation, Access::Read, {});
        status.driveAddress = 1;

        QCOMPARE(send(bus, op, writeValue(kWritableAddress, 5, 1, 0xFF)), QByteArray());
        QCOMPARE(send(bus, op, status), QByteArrayLiteral("\x06")); // ACK

        QCOMPARE(send(bus, op, writeValue(kMissingAddress, 5, 2, 0xFF)), QByteArray());
        status.driveAddress = 2;
        const QByteArray negative = send(bus, op, status);
        QCOMPARE(negative.size(), 2); // code NAK
        QCOMPARE(negative.at(1), '\x15');
        QVERIFY(negative.at(0) != '0');
        QCOMPARE(bus.selection(), 2);
    }

    void legacyDin66019TelegramsFollowTheSameRules()
    {
        SimulatedBus bus(Protocol::Din66019, quietOptions({1, 2}));
        Operator op(Protocol::Din66019);
        Telegram write = Telegram::request(Service::Legacy, Access::Write,
                                           ParameterValue{kWritableAddress, 0, 241});
        write.driveAddress = 1;
        QCOMPARE(send(bus, op, write), QByteArrayLiteral("\x06"));
        Telegram read = Telegram::request(Service::Legacy, Access::Read,
                                          ParameterValue{kWritableAddress, 0, 0});
        const QList<Telegram> replies = ask(bus, op, read);
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].as<ParameterValue>()->value, 241);
        read.driveAddress = 9;
        QCOMPARE(send(bus, op, read), QByteArray());
    }

    void busyRateAnswersAck6()
    {
        SimulationOptions options = quietOptions();
        options.busyRate = 1.0;
        SimulatedBus bus(Protocol::Hsp5, options);
        Operator op(Protocol::Hsp5);
        const QList<Telegram> replies = ask(bus, op, writeValue(kWritableAddress, 9, 1));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].ack, Ack::Busy);
        QCOMPARE(bus.counters().busyReplies, 1);
    }

    void faultCountersFollowTheRates()
    {
        SimulationOptions options = quietOptions();
        options.corruptByteRate = 0.01;
        options.dropByteRate = 0.01;
        options.delayRate = 0.1;
        options.busyRate = 0.1;
        options.seed = 7;
        SimulatedBus bus(Protocol::Hsp5, options);
        Operator op(Protocol::Hsp5);
        constexpr int kRequests = 4000;
        qint64 t = 0;
        for (int i = 0; i < kRequests; ++i) {
            bus.receive(op.encode(readValue(kStateAddress, quint8(i % 15 + 1))), t);
            t += 200'000'000; // far apart: every pause resets a partial telegram
            bus.takeDue(t);
        }
        const BusCounters &c = bus.counters();
        const double bytes = double(c.bytesToDrive + c.bytesFromDrive);
        const auto near = [](double actual, double expected) {
            return actual > expected * 0.75 && actual < expected * 1.25;
        };
        // Bytes are dropped first; only those that stay can be corrupted.
        QVERIFY2(near(c.droppedBytes, bytes * 0.01), qPrintable(QString::number(c.droppedBytes)));
        QVERIFY2(near(c.corruptedBytes, bytes * 0.99 * 0.01),
                 qPrintable(QString::number(c.corruptedBytes)));
        QVERIFY2(near(c.delayedReplies, c.requests * 0.1),
                 qPrintable(QString::number(c.delayedReplies)));
        QVERIFY2(near(c.busyReplies, c.requests * 0.1), qPrintable(QString::number(c.busyReplies)));
        // Most requests still got through and were answered.
        QVERIFY(c.requests > kRequests * 0.8);
    }

    void sameSeedSameFaults()
    {
        SimulationOptions options = quietOptions();
        options.corruptByteRate = 0.05;
        options.busyRate = 0.2;
        Operator op(Protocol::Hsp5);
        QByteArray first;
        QByteArray second;
        for (QByteArray *out : {&first, &second}) {
            SimulatedBus bus(Protocol::Hsp5, options);
            for (int i = 0; i < 50; ++i)
                *out += send(bus, op, readValue(kStateAddress, quint8(i % 15 + 1)),
                             i * 100'000'000LL);
        }
        QCOMPARE(first, second);
    }

    void unsolicitedRequestsComeFirstAndAreConsumed()
    {
        SimulationOptions options = quietOptions();
        options.unsolicitedRate = 1.0;
        SimulatedBus bus(Protocol::Hsp5, options);
        Operator op(Protocol::Hsp5);
        for (int i = 0; i < 20; ++i) {
            const quint8 invoke = quint8(i % 15 + 1);
            const qint64 t = i * 10'000'000LL;
            const QList<Telegram> items = ask(bus, op, readValue(kStateAddress, invoke), t);
            QCOMPARE(items.size(), 2);
            const Telegram &unsolicited = items[0];
            QVERIFY(!unsolicited.isResponse());
            QCOMPARE(unsolicited.operatorInvoke, quint8(0));
            QCOMPARE(unsolicited.inverterInvoke, quint8(i % 15 + 1));
            QCOMPARE(unsolicited.service, Service::Limits);
            QVERIFY(unsolicited.isWrite());
            QCOMPARE(items[1].operatorInvoke, invoke);
            QVERIFY(items[1].isResponse());
            // The operator does not serve it and says so; the drive takes that answer quietly.
            const Telegram refusal = unsolicited.response(Ack::ServiceNotAvailable);
            QCOMPARE(send(bus, op, refusal, t + 5'000'000), QByteArray());
        }
        QCOMPARE(bus.counters().unsolicitedRequests, 20);
        QCOMPARE(bus.counters().unsolicitedAnswers, 20);
        QCOMPARE(bus.counters().unexpected, 0);
    }

    void pacingSchedulesHsp5FullDuplex()
    {
        SimulationOptions options = quietOptions();
        options.paced = true;
        options.baudRate = 38400;
        options.replyLatencyUs = 1000;
        SimulatedBus bus(Protocol::Hsp5, options);
        Operator op(Protocol::Hsp5);
        // 11 bits a character at 38400 baud: 286458.3 ns.
        QCOMPARE(bus.lineTimeNs(6), 1'718'750);
        QCOMPARE(bus.lineTimeNs(8), 2'291'667);
        const QByteArray request = op.encode(readValue(kStateAddress, 1)); // 6 bytes
        QCOMPARE(request.size(), 6);
        bus.receive(request, 0);
        bus.receive(op.encode(readValue(kStateAddress, 2)), 0); // queued behind the first
        QCOMPARE(bus.scheduled().size(), std::size_t(2));
        const BusTransmission first = bus.scheduled()[0];
        const BusTransmission second = bus.scheduled()[1];
        QCOMPARE(first.bytes.size(), 8);
        QCOMPARE(first.startNs, 1'718'750 + 1'000'000);
        QCOMPARE(first.dueNs, 1'718'750 + 1'000'000 + 2'291'667);
        // Second request in at 3437500, ready at 4437500, but the line is busy until the
        // first reply is out: the second follows it back to back.
        QCOMPARE(second.startNs, first.dueNs);
        QCOMPARE(second.dueNs, 2'718'750 + bus.lineTimeNs(16));
        QCOMPARE(bus.nextDueNs(), first.dueNs);
        QCOMPARE(bus.takeDue(first.dueNs - 1), QByteArray());
        QCOMPARE(bus.takeDue(first.dueNs).size(), 8);
    }

    void pacingSharesTheDinLine()
    {
        SimulationOptions options = quietOptions();
        options.paced = true;
        options.baudRate = 9600;
        options.replyLatencyUs = 500;
        SimulatedBus bus(Protocol::Din66019II, options);
        Operator op(Protocol::Din66019II);
        // 10 bits a character at 9600 baud: 1041666.7 ns.
        const QByteArray request = op.encode(readValue(kStateAddress, 1, 1));
        bus.receive(request, 0);
        QCOMPARE(bus.scheduled().size(), std::size_t(1));
        const BusTransmission reply = bus.scheduled()[0];
        const qint64 requestEnd = bus.lineTimeNs(request.size());
        QCOMPARE(reply.startNs, requestEnd + 500'000);
        QCOMPARE(reply.dueNs, requestEnd + 500'000 + bus.lineTimeNs(reply.bytes.size()));
        // A request sent while the reply is on the line waits for it (one shared line).
        const QByteArray next = op.encode(readValue(kStateAddress, 2));
        bus.receive(next, reply.startNs + 1000);
        QCOMPARE(bus.scheduled().size(), std::size_t(2));
        QCOMPARE(bus.scheduled()[1].startNs, reply.dueNs + bus.lineTimeNs(next.size()) + 500'000);
    }

    void pacingDoesNotAccumulateRounding()
    {
        SimulationOptions options = quietOptions();
        options.paced = true;
        options.baudRate = 38400;
        options.replyLatencyUs = 0;
        SimulatedBus bus(Protocol::Hsp5, options);
        Operator op(Protocol::Hsp5);
        // 300 requests handed over one byte at a time, all at t = 0: back to back on the line.
        const QByteArray request = op.encode(readValue(kStateAddress, 1));
        for (int i = 0; i < 300; ++i) {
            for (char byte : request)
                bus.receive(QByteArray(1, byte), 0);
        }
        const qint64 requestsEnd = bus.lineTimeNs(300 * 6);
        QCOMPARE(requestsEnd, 515'625'000); // 1800 * 11 / 38400 s exactly
        // The last reply: 300 replies back to back from the end of the first request.
        QCOMPARE(bus.scheduled().back().dueNs, bus.lineTimeNs(6) + bus.lineTimeNs(300 * 8));
    }

    void latencyWithoutPacing()
    {
        SimulationOptions options = quietOptions();
        options.replyLatencyUs = 2500;
        options.delayRate = 1.0;
        options.delayMs = 40;
        SimulatedBus bus(Protocol::Hsp5, options);
        Operator op(Protocol::Hsp5);
        bus.receive(op.encode(readValue(kStateAddress, 1)), 1'000'000);
        QCOMPARE(bus.nextDueNs(), 1'000'000 + 2'500'000 + 40'000'000);
        QCOMPARE(bus.counters().delayedReplies, 1);
    }

    void resetLineKeepsDriveState()
    {
        SimulatedBus bus(Protocol::Din66019II, quietOptions());
        Operator op(Protocol::Din66019II);
        QCOMPARE(ask(bus, op, writeValue(kWritableAddress, 31, 1, 1)).size(), 1);
        bus.receive(op.encode(readValue(kStateAddress, 2)), 0);
        bus.resetLine();
        QVERIFY(bus.scheduled().empty());
        QCOMPARE(bus.selection(), -1);
        const QList<Telegram> replies = ask(bus, op, readValue(kWritableAddress, 3, 1));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].as<ParameterValue>()->value, 31);
    }

    void countsBytesEachWay()
    {
        SimulatedBus bus(Protocol::Hsp5, quietOptions());
        Operator op(Protocol::Hsp5);
        send(bus, op, readValue(kStateAddress, 1));
        QCOMPARE(bus.counters().bytesToDrive, 6);
        QCOMPARE(bus.counters().bytesFromDrive, 8);
    }
};

QTEST_GUILESS_MAIN(TestSimulatedBus)
#include "tst_simulatedbus.moc"
