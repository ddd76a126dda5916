// DriveState: a drive's values, edit states and level held once; EditCheck: the one rule for
// what may be written. What the window's cells, the messages and the command line all read.
#include "../parameters/EditorSampleDrive.h"

#include "session/ValueChange.h"
#include "state/DriveState.h"
#include "state/EditCheck.h"
#include "state/FileEdits.h"

#include <QDateTime>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

namespace {

WriteOutcome acknowledged(quint16 address, quint8 mask, qint32 readBack)
{
    WriteOutcome outcome;
    outcome.address = address;
    outcome.acknowledgedMask = mask;
    for (int set = 0; set < kParameterSets; ++set) {
        if (mask & (1u << set))
            outcome.readBack[std::size_t(set)] = readBack;
    }
    return outcome;
}

// Read times are milliseconds: what is read after this was read later than what came before.
void nextMillisecond()
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    while (QDateTime::currentMSecsSinceEpoch() == now)
        QThread::yieldCurrentThread();
}

} // namespace

class TestDriveState : public QObject
{
    Q_OBJECT

private slots:
    void theDescriptionHoldsTheValuesReadSince()
    {
        DriveState state;
        state.setDescription(drive());
        const DriveDescription *first = &state.description();
        QCOMPARE(first, &state.description()); // asked again, not built again
        QCOMPARE(state.description().find(kMaxFrequency)->values[1], 6000);

        QSignalSpy cells(&state, &DriveState::cellsChanged);
        QVERIFY(state.setValue(kMaxFrequency, 1, 7000));
        QCOMPARE(cells.size(), 1);
        QCOMPARE(cells.constFirst().at(1).toInt(), 1);
        QCOMPARE(state.description().find(kMaxFrequency)->values[1], 7000);
        QCOMPARE(state.value(kMaxFrequency, 1), 7000);

        // The same value read again changes nothing a view must redraw.
        QVERIFY(state.setValue(kMaxFrequency, 1, 7000));
        QCOMPARE(cells.size(), 1);
        // A parameter without sets holds any set's value in its one cell.
        QVERIFY(state.setValue(kRampTime, 4, 800));
        QCOMPARE(state.value(kRampTime, 0), 800);
        QVERIFY(!state.setValue(0x0999, 0, 1));
        QVERIFY(!state.setValue(kRampTime, 8, 1));
    }

    void aValueReadAfterTheDriveFellSilentIsFreshAgain()
    {
        DriveState state;
        state.setDescription(drive());
        nextMillisecond();
        QSignalSpy stale(&state, &DriveState::staleChanged);
        state.setStaleSince(QDateTime::currentMSecsSinceEpoch());
        QCOMPARE(stale.size(), 1);
        QVERIFY(state.isStale(kFrequency));
        nextMillisecond();
        QSignalSpy whole(&state, &DriveState::parameterChanged);
        QVERIFY(state.setValue(kFrequency, 0, -4180)); // the same value, but read now
        QVERIFY(!state.isStale(kFrequency));
        QCOMPARE(whole.size(), 1);
        QVERIFY(state.isStale(kState));
        state.setStaleSince(0);
        QVERIFY(!state.isStale(kState));
    }

    void aWriteReadBackAsAskedIsWritten()
    {
        DriveState state;
        state.setDescription(drive());
        state.markPending(kMaxFrequency, 0b100, 4500);
        QCOMPARE(state.editState(kMaxFrequency, 2), EditState::Pending);
        QCOMPARE(state.find(kMaxFrequency)->shownValue(2), 4500);
        QCOMPARE(state.value(kMaxFrequency, 2), 5000); // not the drive's until it says so

        state.showOutcome(acknowledged(kMaxFrequency, 0b100, 4500));
        QCOMPARE(state.editState(kMaxFrequency, 2), EditState::Written);
        QCOMPARE(state.value(kMaxFrequency, 2), 4500);
        QCOMPARE(state.description().find(kMaxFrequency)->values[2], 4500);
    }

    void aReadBackHoldingSomethingElseFailsSayingWhat()
    {
        DriveState state;
        state.setDescription(drive());
        state.markPending(kMaxFrequency, 0b10, 4500);
        state.showOutcome(acknowledged(kMaxFrequency, 0b10, 4400));
        QCOMPARE(state.editState(kMaxFrequency, 1), EditState::Failed);
        QCOMPARE(state.find(kMaxFrequency)->failure(1),
                 QStringLiteral("the drive holds 44.00 Hz, not 45.00 Hz"));
        QCOMPARE(state.value(kMaxFrequency, 1), 4400);
    }

    void anUnansweredWriteIsUnknownNotFailed()
    {
        DriveState state;
        state.setDescription(drive());
        state.markPending(kRampTime, 1, 900);
        WriteOutcome outcome;
        outcome.address = kRampTime;
        outcome.refusedMask = 1;
        outcome.unansweredMask = 1;
        outcome.error = QStringLiteral("no answer from the drive");
        state.showOutcome(outcome);
        QCOMPARE(state.editState(kRampTime, 0), EditState::Unknown);
        QCOMPARE(state.find(kRampTime)->failure(0), outcome.error);
        QCOMPARE(state.value(kRampTime, 0), 500); // what was last read, not what was asked

        // A refusal the drive gave is a failure.
        state.markPending(kRampTime, 1, 900);
        outcome.unansweredMask = 0;
        outcome.error = QStringLiteral("password protected");
        state.showOutcome(outcome);
        QCOMPARE(state.editState(kRampTime, 0), EditState::Failed);
    }

    void aSupersededEditLeavesItsCellsToTheNextOne()
    {
        DriveState state;
        state.setDescription(drive());
        state.markPending(kRampTime, 1, 900);
        WriteOutcome refused;
        refused.address = kRampTime;
        refused.refusedMask = 1;
        refused.error = QStringLiteral("busy");
        state.showOutcome(refused, true);
        QCOMPARE(state.editState(kRampTime, 0), EditState::Pending);
    }

    void aNewDescriptionDropsTheEditStatesAndKeepsTheLevel()
    {
        DriveState state;
        state.setDescription(drive());
        state.setPasswordLevel(PasswordLevel::CpReadWrite);
        state.markPending(kRampTime, 1, 900);
        QSignalSpy about(&state, &DriveState::aboutToReset);
        QSignalSpy reset(&state, &DriveState::reset);
        state.setDescription(drive());
        QCOMPARE(about.size(), 1);
        QCOMPARE(reset.size(), 1);
        QCOMPARE(state.editState(kRampTime, 0), EditState::None);
        QCOMPARE(state.passwordLevel(), PasswordLevel::CpReadWrite);
    }

    void theOneRuleRefusesWithTheParameterNamed()
    {
        DriveState state;
        state.setDescription(drive());
        QCOMPARE(state.writeRefusal(kFrequency, 1, 0), QStringLiteral("ru.03 is read-only"));
        QCOMPARE(state.writeRefusal(kRampTime, 0, 900), QStringLiteral("oP.11: no set chosen"));
        QVERIFY2(state.writeRefusal(kRampTime, 1, 30001).startsWith(QStringLiteral("oP.11: ")),
                 qPrintable(state.writeRefusal(kRampTime, 1, 30001)));
        QVERIFY(state.writeRefusal(kRampTime, 1, 30000).isEmpty());
        QVERIFY(state.isEditable(kRampTime));

        state.setPasswordLevel(PasswordLevel::CpReadWrite);
        QCOMPARE(state.writeRefusal(kService, 1, 5),
                 QStringLiteral("Pn.07 needs password level Application (in force: CP "
                                "read/write)"));
        QVERIFY(!state.isEditable(kService));
        QVERIFY(state.isAboveLevel(kService));
        QVERIFY(!state.writeRefusal(0x0999, 1, 0).isEmpty());

        // The command line asks the same rule of a parameter it looked up on its own.
        const ParameterState ramp(*state.parameter(kRampTime), QStringLiteral("oP.11"));
        QVERIFY(!EditCheck::valueRefusal(ramp, -1, PasswordLevel::Supervisor).isEmpty());
        QVERIFY(EditCheck::valueRefusal(ramp, 100, PasswordLevel::Supervisor).isEmpty());
    }

    // A file's edit goes into its state at once and says what it replaced; undo puts back
    // exactly that, a value never read included.
    void aFileEditIsMadeAtOnceAndUndoneExactly()
    {
        DriveState state;
        DriveDescription file = drive();
        file.groups[1].parameters[0].values[3] = std::nullopt; // oP.10, set 3 never read
        state.setDescription(file);
        FileEdits edits(&state);
        const ParameterDescription maxFrequency = *state.parameter(kMaxFrequency);
        std::optional<EditOutcome> outcome;
        edits.write(maxFrequency, 0b1010, 7000, [&](const EditOutcome &done) { outcome = done; });
        QVERIFY(outcome); // no waiting: a file has no drive to answer
        QCOMPARE(outcome->acknowledgedMask, quint8(0b1010));
        QVERIFY(outcome->complete());
        QCOMPARE(outcome->before[1], 6000);
        QCOMPARE(outcome->before[3], std::nullopt);
        QCOMPARE(state.value(kMaxFrequency, 1), 7000);
        QCOMPARE(state.value(kMaxFrequency, 3), 7000);
        QCOMPARE(state.value(kMaxFrequency, 2), 5000);

        edits.restore(maxFrequency, 0b1010, outcome->before);
        QCOMPARE(state.value(kMaxFrequency, 1), 6000);
        QCOMPARE(state.value(kMaxFrequency, 3), std::nullopt);

        // A drive cannot be given "never read": undo writes the known values only.
        const QList<WriteStep> steps = StateEditor::restoringSteps(0b1010, outcome->before);
        QCOMPARE(steps.size(), 1);
        QCOMPARE(steps.constFirst().setMask, quint8(0b10));
        QCOMPARE(steps.constFirst().raw, 6000);

        // A reset puts the default; a parameter without sets takes it in its one value.
        const ParameterDescription ramp = *state.parameter(kRampTime);
        state.putValue(kRampTime, 0, 900);
        edits.resetToDefault(ramp, 0b100, [&](const EditOutcome &done) { outcome = done; });
        QCOMPARE(state.value(kRampTime, 0), 500);
        QCOMPARE(outcome->before[0], 900);
    }
};

QTEST_GUILESS_MAIN(TestDriveState)
#include "tst_drivestate.moc"
