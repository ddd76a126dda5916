#include "../client/ClientTestSupport.h"

#include "state/EditText.h"
#include "session/PasswordLevelJob.h"
#include "session/Polling.h"
#include "session/ValueChange.h"
#include "state/ValueEdits.h"
#include "session/ValueReads.h"

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

constexpr quint16 kActualFrequency = 0x0203; // ru.03, read-only
constexpr quint16 kNoSuchParameter = 0x7F7F;
constexpr quint16 kDemoPeriod = 0x0305; // op.05, one value

ParameterDescription described(quint16 address, bool setProgrammable)
{
    ParameterDescription parameter;
    parameter.address = address;
    parameter.maximum = 10000;
    parameter.properties1 = setProgrammable ? 1u << 11 : 0u;
    parameter.scaling = DisplayScalingData{address, 1, 1, 0, 0}; // raw, no unit
    return parameter;
}

ValueRead oneValue(quint16 address)
{
    return ValueRead{address, 0, false};
}

template<typename T>
QList<T> resultsOf(const QFuture<T> &future)
{
    return waitFinished(future) ? future.results() : QList<T>{};
}

} // namespace

// core/session's jobs and polling against the simulated drive through a real client: what the
// window and the command line both rely on.
class TestSessionJobs : public QObject
{
    Q_OBJECT
private slots:
    void pollingReadsRoundAfterRoundUntilTheConnectionGoes()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        Polling polling(session.client.get());
        polling.setReads([] { return QList<ValueRead>{oneValue(kActualFrequency), oneValue(kRatedCurrent)}; });
        polling.setIntervalMs(Polling::kMinimumIntervalMs);
        QSignalSpy readings(&polling, &Polling::reading);
        QSignalSpy rounds(&polling, &Polling::roundFinished);
        QSignalSpy stopped(&polling, &Polling::stopped);

        polling.setEnabled(true);
        QTRY_VERIFY_WITH_TIMEOUT(rounds.size() >= 3, kWaitMs);
        QCOMPARE(polling.roundsCompleted(), int(rounds.size()));
        QVERIFY(readings.size() >= 6);
        const auto last = readings.constLast().at(0).value<ValueReading>();
        QCOMPARE(last.read.address, kRatedCurrent);
        QCOMPARE(last.value, 105);
        const auto round = rounds.constLast().at(0).value<Polling::Round>();
        QCOMPARE(round.reads, 2);
        QVERIFY(round.failures.isEmpty());

        session.client->disconnectFromDrive();
        QTRY_COMPARE_WITH_TIMEOUT(stopped.size(), 1, kWaitMs);
        QCOMPARE(stopped.constFirst().at(0).toBool(), false);
        QVERIFY(!polling.isEnabled());
    }

    void aRoundOnItsWaySkipsTheNext()
    {
        // DIN66019II, one request at a time, 30 ms each: a round of five takes longer than the
        // 50 ms between rounds.
        SimulationOptions options;
        options.replyLatencyUs = 30000;
        Session session(simulated(Protocol::Din66019II, options));
        QVERIFY(session.connected());
        Polling polling(session.client.get());
        polling.setReads([] { return QList<ValueRead>(5, oneValue(kRatedCurrent)); });
        polling.setIntervalMs(Polling::kMinimumIntervalMs);
        QSignalSpy rounds(&polling, &Polling::roundFinished);
        polling.setEnabled(true);
        QTRY_VERIFY_WITH_TIMEOUT(rounds.size() >= 2, kWaitMs);
        polling.setEnabled(false);
        QVERIFY2(polling.roundsSkipped() > 0, qPrintable(QString::number(polling.roundsSkipped())));
    }

    void aRefusedReadIsReportedAndTheRoundGoesOn()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        Polling polling(session.client.get());
        polling.setReads([] { return QList<ValueRead>{oneValue(kNoSuchParameter), oneValue(kRatedCurrent)}; });
        QSignalSpy readings(&polling, &Polling::reading);
        QSignalSpy rounds(&polling, &Polling::roundFinished);
        polling.setEnabled(true);
        QTRY_COMPARE_WITH_TIMEOUT(rounds.size(), 1, kWaitMs);
        polling.setEnabled(false);
        const auto round = rounds.constFirst().at(0).value<Polling::Round>();
        QCOMPARE(round.failures.size(), 1);
        QCOMPARE(round.failures.constFirst().read.address, kNoSuchParameter);
        QVERIFY2(round.failures.constFirst().reason.contains(QStringLiteral("address")),
                 qPrintable(round.failures.constFirst().reason));
        QCOMPARE(readings.size(), 1);
        QCOMPARE(readings.constFirst().at(0).value<ValueReading>().value, 105);
    }

    void nothingToReadIsSaid()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        Polling polling(session.client.get());
        QSignalSpy nothing(&polling, &Polling::nothingToRead);
        polling.setEnabled(true);
        QCOMPARE(nothing.size(), 1);
        QCOMPARE(polling.roundsCompleted(), 0);
    }

    void aWriteIsReadBackAndARefusalSaysWhy()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        ValueChange change;
        change.address = kMaxSpeedForward;
        change.steps = {WriteStep{0x04, 2500, false}};
        const QList<WriteOutcome> written = resultsOf(
            session.client->run(std::make_shared<WriteValueJob>(Protocol::Hsp5, change)));
        QCOMPARE(written.size(), 1);
        QVERIFY2(written.constFirst().ok(), qPrintable(written.constFirst().error));
        QCOMPARE(written.constFirst().acknowledgedMask, quint8(0x04));
        QCOMPARE(written.constFirst().readBack[2], 2500);
        QCOMPARE(written.constFirst().readBack[1], std::nullopt);

        change.address = kActualFrequency;
        change.setProgrammable = false;
        change.steps = {WriteStep{0x01, 10, false}};
        const QList<WriteOutcome> refused = resultsOf(
            session.client->run(std::make_shared<WriteValueJob>(Protocol::Hsp5, change)));
        QCOMPARE(refused.size(), 1);
        QVERIFY(!refused.constFirst().anyAcknowledged());
        QVERIFY(!refused.constFirst().connectionFailed);
        QVERIFY2(refused.constFirst().error.contains(QStringLiteral("write protected")),
                 qPrintable(refused.constFirst().error));
    }

    // The one edit path of the window and the command line: queued per parameter, a later edit
    // supersedes the earlier one's cells, the outcome said in words.
    void editsOfOneParameterQueueAndTheLaterOneSupersedes()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        ValueEdits edits(session.client.get());
        QSignalSpy pending(&edits, &ValueEdits::pending);
        QSignalSpy edited(&edits, &ValueEdits::edited);
        QList<EditOutcome> outcomes;
        const ParameterDescription speed = described(kMaxSpeedForward, true);
        edits.write(speed, 0x02, 1000, [&](const EditOutcome &outcome) { outcomes << outcome; });
        edits.write(speed, 0x02, 2000, [&](const EditOutcome &outcome) { outcomes << outcome; });
        QCOMPARE(pending.size(), 2); // at once, each edit once
        QCOMPARE(pending.at(1).at(2).toInt(), 2000);
        QCOMPARE(edits.runningCount(), 2);
        QTRY_COMPARE_WITH_TIMEOUT(outcomes.size(), 2, kWaitMs);
        QCOMPARE(edited.size(), 2);
        QCOMPARE(edits.runningCount(), 0);
        QVERIFY(outcomes.at(0).superseded);
        QVERIFY(!outcomes.at(1).superseded);
        QVERIFY(outcomes.at(1).complete());
        QCOMPARE(outcomes.at(1).readBack[1], 2000);
        QCOMPARE(EditText(QStringLiteral("op.11"), &speed).outcome(outcomes.at(1)),
                 QStringLiteral("op.11 = 2000 written (set 1)"));
    }

    void aParameterWithoutSetsIsWrittenAsSetZeroAndARefusalIsSaid()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        ValueEdits edits(session.client.get());
        QSignalSpy pending(&edits, &ValueEdits::pending);
        std::optional<EditOutcome> outcome;
        const ParameterDescription period = described(kDemoPeriod, false);
        edits.write(period, 0xFF, 300, [&](const EditOutcome &done) { outcome = done; });
        QCOMPARE(pending.constFirst().at(1).value<quint8>(), quint8(0x01));
        QTRY_VERIFY_WITH_TIMEOUT(outcome, kWaitMs);
        QCOMPARE(outcome->acknowledgedMask, quint8(0x01));
        QCOMPARE(outcome->readBack[0], 300);
        QCOMPARE(EditText(QStringLiteral("op.05"), &period).outcome(*outcome),
                 QStringLiteral("op.05 = 300 written"));

        outcome.reset();
        const ParameterDescription actual = described(kActualFrequency, false);
        edits.write(actual, 0x01, 10, [&](const EditOutcome &done) { outcome = done; });
        QTRY_VERIFY_WITH_TIMEOUT(outcome, kWaitMs);
        QVERIFY(!outcome->anyAcknowledged());
        const QString said = EditText(QStringLiteral("ru.03"), &actual).outcome(*outcome);
        QVERIFY2(said.startsWith(QStringLiteral("ru.03 = 10 not written: "))
                     && said.contains(QStringLiteral("write protected")),
                 qPrintable(said));
    }

    void thePasswordLevelIsReadAndAPasswordChangesIt()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        const auto levelAfter = [&](std::optional<qint32> password) {
            const QList<PasswordLevelOutcome> outcomes = resultsOf(
                session.client->run(std::make_shared<PasswordLevelJob>(Protocol::Hsp5, password)));
            return outcomes.value(0);
        };
        PasswordLevelOutcome outcome = levelAfter(std::nullopt);
        QCOMPARE(outcome.level, PasswordLevel::Application);
        QCOMPARE(outcome.readValue, -4);

        outcome = levelAfter(1234);
        QVERIFY(!outcome.passwordAccepted);
        QVERIFY2(outcome.error.contains(QStringLiteral("password invalid")), qPrintable(outcome.error));
        QCOMPARE(outcome.readValue, std::nullopt);
        QCOMPARE(levelAfter(std::nullopt).level, PasswordLevel::Application);

        outcome = levelAfter(500);
        QVERIFY(outcome.passwordAccepted);
        QCOMPARE(outcome.level, PasswordLevel::DriveMode);
    }

    // A batch waits for the edits of its parameters given before it, and one stopped before
    // its turn came ends without writing anything; the next is written and read back.
    void aBatchStoppedBeforeItBeganWritesNothing()
    {
        Session session(simulated(Protocol::Hsp5, fast()));
        QVERIFY(session.connected());
        ValueEdits edits(session.client.get());
        const ParameterDescription speed = described(kMaxSpeedForward, true);
        const QList<ValueEdits::BatchItem> items { { speed, { WriteStep { 0x08, 1234, false } } } };
        QList<QString> ended;
        edits.write(speed, 0x01, 2000, [&](const EditOutcome &) { ended << QStringLiteral("edit"); });
        QList<EditOutcome> stopped;
        const quint64 batch = edits.applyAll(
            items, [&](qsizetype, const EditOutcome &) { ended << QStringLiteral("written"); },
            [&](const QList<EditOutcome> &outcomes) {
                ended << QStringLiteral("batch");
                stopped = outcomes;
            });
        QCOMPARE(edits.runningCount(), 2);
        edits.stopBatch(batch, QStringLiteral("stopped"));
        QTRY_COMPARE_WITH_TIMEOUT(edits.runningCount(), 0, kWaitMs);
        QCOMPARE(ended, (QList<QString> { QStringLiteral("edit"), QStringLiteral("batch") }));
        QCOMPARE(stopped.size(), 1);
        QCOMPARE(stopped.constFirst().notSentMask, quint8(0x08));
        QCOMPARE(stopped.constFirst().error, QStringLiteral("stopped"));
        QCOMPARE(valueOf(session.call(session.client->readValue(kMaxSpeedForward, 0x08))),
                 kMaxSpeedDefault);

        std::optional<QList<EditOutcome>> copied;
        edits.applyAll(items, {}, [&](const QList<EditOutcome> &outcomes) { copied = outcomes; });
        QTRY_VERIFY_WITH_TIMEOUT(copied, kWaitMs);
        QCOMPARE(copied->size(), 1);
        QVERIFY(copied->constFirst().complete());
        QCOMPARE(copied->constFirst().readBack[3], 1234);
    }
};

QTEST_GUILESS_MAIN(TestSessionJobs)
#include "tst_sessionjobs.moc"
