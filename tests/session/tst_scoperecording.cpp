#include "../client/ClientTestSupport.h"
#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"
#include "scope/ScopeFileReader.h"
#include "scope/ScopeRecording.h"
#include "journal/Journal.h"
#include "session/EditJournal.h"
#include "session/ScopeOfflineJob.h"
#include "session/ScopeRecorder.h"
#include "state/DriveState.h"
#include "state/ScopeChannelEdits.h"
#include "state/ValueEdits.h"

#include <QFutureWatcher>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

constexpr quint16 kChannel1Source = 0x0010; // Sy.16: itself no process data
constexpr quint16 kChannel1Set = 0x0011;    // Sy.17

DriveDescription scanned(Session &s)
{
    const QFuture<DriveDescription> scan = s.client->scan();
    if (!waitFinished(scan) || scan.resultCount() == 0)
        return {};
    return scan.result();
}

// Through the edit path, as the window and the command line assign them.
ScopeChannelsOutcome assign(ValueEdits &edits, const DriveDescription &drive,
                            ScopeAssignment choices)
{
    std::optional<ScopeChannelsOutcome> outcome;
    assignScopeChannels(edits, drive, choices,
                        [&outcome](const ScopeChannelsOutcome &assigned) { outcome = assigned; });
    if (!QTest::qWaitFor([&outcome] { return outcome.has_value(); }, kWaitMs))
        return {{}, QStringLiteral("the assignment did not finish"), false};
    return *outcome;
}

ScopeChannelsOutcome assign(Session &s, const DriveDescription &drive, ScopeAssignment choices)
{
    ValueEdits edits(s.client.get());
    return assign(edits, drive, choices);
}

// Records until `done` says so or the recording ends by itself; returns how it ended.
ScopePollEnd record(ScopeRecorder &recorder, ScopeRecording &recording,
                    ScopeRecorderOptions options, const std::function<bool()> &done)
{
    QSignalSpy finished(&recorder, &ScopeRecorder::finished);
    recorder.start(&recording, options);
    if (!QTest::qWaitFor([&] { return done() || !finished.isEmpty(); }, kWaitMs))
        return {{}, QStringLiteral("the recording neither ended nor got far enough"), false};
    recorder.stop();
    if (!QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs))
        return {{}, QStringLiteral("the recording did not stop"), false};
    return finished.first().at(0).value<ScopePollEnd>();
}

bool timesAscend(const ScopeRecording &recording)
{
    for (qsizetype i = 1; i < recording.buffer.count(); ++i) {
        if (recording.buffer.samples().time(i) < recording.buffer.samples().time(i - 1))
            return false;
    }
    return true;
}

} // namespace

// The scope against the simulated F5 through a real client: channels assigned and read back,
// samples recorded in order with the drive's values, the rate limit, a lost link.
class TestScopeRecording : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        qRegisterMetaType<ScopePollEnd>();
    }

    void choosesChannelsAndRecordsTheirValues_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("HSP5") << Protocol::Hsp5;
        QTest::newRow("DIN66019II") << Protocol::Din66019II;
    }

    void choosesChannelsAndRecordsTheirValues()
    {
        QFETCH(Protocol, protocol);
        Session s(simulated(protocol, fast()));
        QVERIFY(s.connected());
        const DriveDescription drive = scanned(s);
        QVERIFY(scopeAssignmentParameters(drive).has_value());

        // A wide and a narrow channel on parameters whose values do not move.
        ScopeAssignment choices;
        choices[0] = ChannelAssignment{kMaxSpeedForward, 0x01};
        choices[2] = ChannelAssignment{kMotorVoltage, 0x01};
        choices[3] = ChannelAssignment{ChannelAssignment::kOff, 0x01};
        const ScopeChannelsOutcome outcome = assign(s, drive, choices);
        QVERIFY2(outcome.error.isEmpty(), qPrintable(outcome.error));
        QCOMPARE(outcome.assignment[0], choices[0]);
        QCOMPARE(outcome.assignment[2], choices[2]);
        QCOMPARE(outcome.assignment[3], choices[3]);
        QVERIFY(outcome.assignment[1].has_value()); // left alone, but read back all the same

        ScopeRecording recording;
        recording.channels = scopeChannels(drive, outcome.assignment);
        QCOMPARE(recording.channels[0].id, QStringLiteral("op.11"));
        QCOMPARE(recording.channels[0].unit(), QStringLiteral("1/min"));
        QCOMPARE(recording.channels[2].id, QStringLiteral("dr.04"));
        QVERIFY(!recording.channels[3].enabled);

        ScopeRecorder recorder(s.client.get());
        const ScopePollEnd end = record(recorder, recording, {},
                                        [&] { return recording.buffer.count() >= 200; });
        QVERIFY2(end.reason.isEmpty(), qPrintable(end.reason));
        QVERIFY(recording.buffer.count() >= 200);
        // Polls answered within one of the drive's milliseconds with the same values are one
        // sample, stored once and counted once in the rates.
        const ScopeRecorderStatus status = recorder.status();
        QCOMPARE(end.counts.answered, recording.buffer.count() + status.repeated);
        const SampleStore &samples = recording.buffer.samples();
        for (qsizetype i = 1; i < samples.count(); ++i)
            QVERIFY2(!(samples.at(i) == samples.at(i - 1)), qPrintable(QString::number(i)));
        const qint64 spanMs = recording.lastTime() - recording.firstTime();
        QVERIFY(spanMs > 0);
        QCOMPARE(status.averageHz, double(samples.count() - 1) * 1000.0 / double(spanMs));
        QCOMPARE(end.counts.lost + end.counts.failed, 0);
        QVERIFY(recording.started.isValid());
        QVERIFY(timesAscend(recording));
        for (qsizetype i = 0; i < recording.buffer.count(); ++i) {
            QCOMPARE(recording.buffer.samples().value(i, 0), kMaxSpeedDefault);
            QCOMPARE(recording.buffer.samples().value(i, 2), 400);
            QCOMPARE(recording.buffer.samples().value(i, 3), 0);
        }
    }

    void readsASourceFromTheSetChosen()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        const DriveDescription drive = scanned(s);
        QVERIFY(s.call(s.client->writeValue(kMaxSpeedForward, 2500, 0x04)).ok()); // set 2
        ScopeAssignment choices;
        choices[0] = ChannelAssignment{kMaxSpeedForward, 0x04};
        choices[1] = ChannelAssignment{kMaxSpeedForward, 0x01};
        const ScopeChannelsOutcome outcome = assign(s, drive, choices);
        QVERIFY2(outcome.error.isEmpty(), qPrintable(outcome.error));
        QCOMPARE(outcome.assignment[0], choices[0]);
        ScopeRecording recording;
        recording.channels = scopeChannels(drive, outcome.assignment);
        QCOMPARE(recording.channels[0].title(0), QStringLiteral("op.11 Maximum speed forward (set 2)"));
        QCOMPARE(recording.channels[1].title(1), QStringLiteral("op.11 Maximum speed forward"));
        ScopeRecorder recorder(s.client.get());
        record(recorder, recording, {}, [&] { return recording.buffer.count() >= 50; });
        QVERIFY(recording.buffer.count() >= 50);
        for (qsizetype i = 0; i < recording.buffer.count(); ++i) {
            QCOMPARE(recording.buffer.samples().value(i, 0), 2500);
            QCOMPARE(recording.buffer.samples().value(i, 1), kMaxSpeedDefault);
        }
    }

    // The assignment is an edit like any other: journaled, and shown in the drive's state as
    // the drive holds it.
    void theAssignmentIsJournaledAndShownInTheState()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        const DriveDescription drive = scanned(s);
        DriveState state;
        state.setDescription(drive);
        QTemporaryDir dir;
        Journal journal(dir.filePath(QStringLiteral("journal.sqlite")));
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        EditJournal editJournal(&journal, JournalDrive {}, QStringLiteral("scope"));
        ValueEdits edits(s.client.get(), &state);
        edits.setJournal(&editJournal);

        ScopeAssignment choices;
        choices[0] = ChannelAssignment { kMaxSpeedForward, 0x04 };
        const ScopeChannelsOutcome outcome = assign(edits, drive, choices);
        QVERIFY2(outcome.error.isEmpty(), qPrintable(outcome.error));
        QCOMPARE(outcome.assignment[0], choices[0]);
        QCOMPARE(state.value(kChannel1Source, 0), std::optional<qint32>(kMaxSpeedForward));
        QCOMPARE(state.value(kChannel1Set, 0), std::optional<qint32>(0x04));
        QCOMPARE(state.editState(kChannel1Source, 0), EditState::Written);
        QCOMPARE(state.editState(kChannel1Set, 0), EditState::Written);

        const std::optional<QList<JournalEntry>> entries = journal.entries();
        QVERIFY2(entries, qPrintable(journal.errorString()));
        QCOMPARE(entries->size(), 2);
        const QList<qint32> written { kMaxSpeedForward, 0x04 };
        const QList<quint16> addresses { kChannel1Source, kChannel1Set };
        for (qsizetype i = 0; i < entries->size(); ++i) {
            const JournalEntry &entry = entries->at(i);
            QCOMPARE(entry.parameterAddress, addresses.at(i));
            QCOMPARE(entry.written.raw, written.at(i));
            QCOMPARE(entry.readBack.raw, written.at(i));
            QCOMPARE(entry.outcome, JournalOutcome::Written);
            QCOMPARE(entry.jobId, entries->constFirst().jobId);
        }
        QCOMPARE(entries->at(0).parameterId, QStringLiteral("Sy.16"));
    }

    void refusesSourcesTheDriveDoesNotPermit()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        const DriveDescription drive = scanned(s);
        const qsizetype sentBefore = s.records().size();
        ScopeAssignment choices;
        choices[1] = ChannelAssignment{kChannel1Source, 0x01};
        const ScopeChannelsOutcome outcome = assign(s, drive, choices);
        QVERIFY2(outcome.error.contains(QStringLiteral("Sy.16")), qPrintable(outcome.error));
        QCOMPARE(s.records().size(), sentBefore); // nothing was sent
        for (const ParameterDescription *source : scopeSources(drive))
            QVERIFY(source->address != kChannel1Source && source->address != kChannel1Set);
    }

    void aDriveWithoutAssignmentIsRecordedRaw()
    {
        DriveDescription drive;
        GroupDescription group;
        group.id = QStringLiteral("ru");
        group.address = 0x0200;
        group.parameters << ParameterDescription{};
        drive.groups << group;
        QVERIFY(!scopeAssignmentParameters(drive));
        const ScopeChannels channels = scopeChannels(drive, ScopeAssignment{});
        QCOMPARE(channels.size(), 4);
        QCOMPARE(channels[1].title(1), QStringLiteral("Channel 2"));
        QVERIFY(!channels[1].source);
        QCOMPARE(channels[1].toDisplay(-1234), -1234.0);

        Session s(simulated(Protocol::Hsp5, fast()));
        ScopeAssignment choices;
        choices[0] = ChannelAssignment{kMaxSpeedForward, 1};
        const ScopeChannelsOutcome outcome = assign(s, drive, choices);
        QVERIFY(outcome.error.contains(QStringLiteral("Sy.16")));
    }

    void recordsToAFileWhileRecording()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        const DriveDescription drive = scanned(s);
        ScopeAssignment choices;
        choices[0] = ChannelAssignment{kMaxSpeedForward, 0x01};
        const ScopeChannelsOutcome outcome = assign(s, drive, choices);
        QVERIFY(outcome.error.isEmpty());
        ScopeRecording recording;
        recording.channels = scopeChannels(drive, outcome.assignment);
        recording.source = QStringLiteral("sim");
        QTemporaryDir dir;
        ScopeRecorderOptions options;
        options.filePath = dir.filePath(QStringLiteral("run.ddscope"));
        ScopeRecorder recorder(s.client.get());
        const ScopePollEnd end = record(recorder, recording, options,
                                        [&] { return recording.buffer.count() >= 500; });
        QVERIFY(end.reason.isEmpty());
        QVERIFY2(recorder.status().fileError.isEmpty(), qPrintable(recorder.status().fileError));

        ScopeRecording loaded;
        QString error;
        QVERIFY2(readScopeFile(options.filePath, loaded, &error), qPrintable(error));
        QCOMPARE(loaded.channels, recording.channels);
        QCOMPARE(loaded.buffer.count(), recording.buffer.count());
        for (qsizetype i = 0; i < recording.buffer.count(); ++i)
            QCOMPARE(loaded.buffer.samples().at(i), recording.buffer.samples().at(i));

        // A file that cannot be written is said so; the recording in memory goes on.
        ScopeRecording second;
        options.filePath = dir.filePath(QStringLiteral("missing/run.ddscope"));
        record(recorder, second, options, [&] { return second.buffer.count() >= 100; });
        QVERIFY(second.buffer.count() >= 100);
        QVERIFY2(recorder.status().fileError.contains(QStringLiteral("missing")),
                 qPrintable(recorder.status().fileError));
    }

    void lostAndFailedPollsAreCountedAndTheRecordingGoesOn()
    {
        // Replies garbled on the line (a wrong BCC) and a drive that is sometimes busy; no
        // retries, so each shows as a lost or failed poll.
        SimulationOptions faults = fast();
        faults.corruptByteRate = 0.002;
        faults.busyRate = 0.03;
        ClientOptions clientOptions;
        clientOptions.retries = 0;
        clientOptions.timeoutMs = 50;
        Session s(simulated(Protocol::Hsp5, faults), clientOptions);
        QVERIFY(s.connected());
        ScopeRecording recording;
        ScopeRecorder recorder(s.client.get());
        ScopeRecorderOptions options;
        options.polling.lostInARowLimit = 1000; // this test is about counting, not giving up
        const ScopePollEnd end = record(recorder, recording, options,
                                        [&] { return recording.buffer.count() >= 1000; });
        QVERIFY2(end.reason.isEmpty(), qPrintable(end.reason));
        QCOMPARE(end.counts.answered, recording.buffer.count() + recorder.status().repeated);
        QVERIFY2(end.counts.lost > 0, "no poll was lost");
        QVERIFY2(end.counts.failed > 0, "no poll was refused");
        QVERIFY(!end.counts.lastProblem.isEmpty());
        QCOMPARE(recorder.status().counts.lost, end.counts.lost);
        QVERIFY(timesAscend(recording));
    }

    void theRateLimitHolds()
    {
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        ScopeRecording recording;
        ScopeRecorder recorder(s.client.get());
        ScopeRecorderOptions options;
        options.polling.maxRateHz = 100;
        options.durationMs = 500;
        const ScopePollEnd end = record(recorder, recording, options, [] { return false; });
        QVERIFY2(end.reason.isEmpty(), qPrintable(end.reason));
        // The duration is the drive's: 500 ms at 100 Hz are 51 samples at most, give or take
        // the first poll's start.
        QVERIFY(recording.lastTime() - recording.firstTime() <= 500);
        QVERIFY2(recording.buffer.count() <= 53, qPrintable(QString::number(recording.buffer.count())));
        QVERIFY(recording.buffer.count() >= 10);
    }

    void everyPollFindsATickOfItsOwn()
    {
        // A drive that answers at once could take many polls in one tick of its clock, each
        // bringing the same sample. One poll per tick: the recording is the drive's every
        // millisecond, and the answers that repeat one are the odd late wake-up, not the rule.
        // HSP5, whose four polls on the way would otherwise go back to back. DIN66019II carries
        // one at a time, and on a real wire its round trip is longer than a tick (37 characters
        // at 250000 Bd: 1.5 ms); the polls the job keeps in the client's queue go out as the
        // answers come, so an unpaced simulated drive could still give it two in one tick.
        Session s(simulated(Protocol::Hsp5, fast()));
        QVERIFY(s.connected());
        ScopeRecording recording;
        ScopeRecorder recorder(s.client.get());
        ScopeRecorderOptions options;
        options.durationMs = 400;
        const ScopePollEnd end = record(recorder, recording, options, [] { return false; });
        QVERIFY2(end.reason.isEmpty(), qPrintable(end.reason));
        const ScopeRecorderStatus status = recorder.status();
        QVERIFY2(recording.buffer.count() >= 20, qPrintable(QString::number(recording.buffer.count())));
        // At most one answer in five: a build with the sanitizers runs the client several
        // times slower and its late wake-ups repeated 7 of 123; without the grid, 16,674 of
        // 17,123 answers did.
        QVERIFY2(status.repeated * 5 <= end.counts.answered,
                 qPrintable(QStringLiteral("%1 of %2 answers repeated the sample before")
                                .arg(status.repeated).arg(end.counts.answered)));
        QVERIFY(timesAscend(recording));
    }

    void recordsOverASerialPort()
    {
        // A pseudo-terminal through QSerialPort, as a USB adapter would be.
        QTemporaryDir dir;
        const QString device = dir.filePath(QStringLiteral("ttyDrive"));
        SimulatorServer server(Protocol::Din66019II, fast());
        QString error;
        QVERIFY2(server.listenPty(device, &error), qPrintable(error));
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Serial;
        settings.device = device;
        settings.protocol = Protocol::Din66019II;
        Session s(settings);
        QVERIFY(s.connected());
        ScopeRecording recording;
        ScopeRecorder recorder(s.client.get());
        const ScopePollEnd end = record(recorder, recording, {},
                                        [&] { return recording.buffer.count() >= 100; });
        QVERIFY2(end.reason.isEmpty(), qPrintable(end.reason));
        QVERIFY(recording.buffer.count() >= 100);
        QCOMPARE(end.counts.lost + end.counts.failed, 0);
        QVERIFY(timesAscend(recording));
    }

    void aLostLinkEndsTheRecordingAndKeepsItsSamples()
    {
        SimulatorServer server(Protocol::Hsp5, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        const ConnectionSettings settings = tcpTo(server);
        ClientOptions clientOptions;
        clientOptions.timeoutMs = 10000; // the lost link, not a timeout, must end it
        Session s(settings, clientOptions);
        QVERIFY(s.connected());
        ScopeRecording recording;
        ScopeRecorder recorder(s.client.get());
        const ScopePollEnd end = record(recorder, recording, {}, [&] {
            if (recording.buffer.count() >= 50)
                server.close();
            return false;
        });
        QVERIFY(end.linkLost);
        QVERIFY2(!end.reason.isEmpty(), "no reason given");
        QVERIFY(recording.buffer.count() >= 50);
        QCOMPARE(end.counts.answered, recording.buffer.count() + recorder.status().repeated);
    }

    void aSilentDriveEndsTheRecording()
    {
        SimulatorServer server(Protocol::Hsp5, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        // The client's own timeouts: a 50 ms one without retries, as this test once had, ends
        // a recording on a loaded machine before the drive froze.
        Session s(tcpTo(server));
        QVERIFY(s.connected());
        ScopeRecording recording;
        ScopeRecorder recorder(s.client.get());
        qsizetype atFreeze = -1;
        const ScopePollEnd end = record(recorder, recording, {}, [&] {
            if (atFreeze < 0 && recording.buffer.count() >= 50) {
                atFreeze = recording.buffer.count();
                server.bus().setSilent(true);
            }
            return false;
        });
        QVERIFY2(atFreeze >= 50, qPrintable(end.reason)); // it ended after the freeze, not before
        QVERIFY(end.linkLost);
        QVERIFY2(end.reason.contains(QStringLiteral("stopped answering")), qPrintable(end.reason));
        QVERIFY(end.counts.lost >= 3);
        QVERIFY(recording.buffer.count() >= atFreeze); // what was recorded stays
    }

    void readsTheOfflineRecordsOverDin66019II()
    {
        Session s(simulated(Protocol::Din66019II, fast()));
        QVERIFY(s.connected());
        const DriveDescription drive = scanned(s);
        ScopeAssignment choices;
        choices[0] = ChannelAssignment{kMaxSpeedForward, 0x01};
        choices[2] = ChannelAssignment{kMotorVoltage, 0x01};
        QVERIFY(assign(s, drive, choices).error.isEmpty());
        QTest::qWait(800); // the drive keeps its last 64 records, one each 10 ms

        QFutureWatcher<ScopeOfflineRecords> watcher;
        watcher.setFuture(s.client->run(std::make_shared<ScopeOfflineJob>(10)));
        QVERIFY(waitFinished(watcher.future()));
        const ScopeOfflineRecords records = watcher.future().result();
        QVERIFY2(records.error.isEmpty(), qPrintable(records.error));
        QCOMPARE(records.expected, 64);
        QCOMPARE(records.samples.size(), 64);
        QCOMPARE(records.clipped, 0);
        // The bar a user watches ends full. (Its steps are not counted: QFuture passes on at
        // most one every 40 ms, and a quick job may end before the watcher is attached.)
        QCOMPARE(watcher.future().progressMaximum(), 64);
        QCOMPARE(watcher.future().progressValue(), 64);
        for (qsizetype i = 0; i < records.samples.size(); ++i) {
            QCOMPARE(records.samples[i].time, i * 10);
            QCOMPARE(records.samples[i].channel(0), kMaxSpeedDefault);
            QCOMPARE(records.samples[i].channel(2), 400);
        }
    }

    void offlineRecordsNeedAConnectionThatCarriesThem()
    {
        Session s(simulated(Protocol::Hsp5, fast())); // seed 000 has no service 21
        QVERIFY(s.connected());
        const QFuture<ScopeOfflineRecords> job = s.client->run(std::make_shared<ScopeOfflineJob>());
        QVERIFY(waitFinished(job));
        QVERIFY2(job.result().error.contains(QStringLiteral("service 21")),
                 qPrintable(job.result().error));
        QVERIFY(job.result().samples.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestScopeRecording)
#include "tst_scoperecording.moc"
