#include "../client/ClientTestSupport.h"
#include "../client/SpoilingProxy.h"

#include "bus/SimulatedBus.h"
#include "parameters/DriveDescription.h"
#include "state/EditText.h"
#include "state/DriveState.h"
#include "state/ValueEdits.h"

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

namespace {

// op.11 as the drive describes it: 0..4000 1/min, 8 sets.
ParameterDescription maxSpeedForward()
{
    ParameterDescription parameter;
    parameter.address = kMaxSpeedForward;
    parameter.name = QStringLiteral("Maximum speed forward");
    parameter.minimum = 0;
    parameter.maximum = 4000;
    parameter.properties1 = 1u << 11; // set-programmable
    parameter.scaling = DisplayScalingData{kMaxSpeedForward, 1, 1, 0, 0};
    return parameter;
}

// A drive of one group holding the parameter, as a scan finds it.
DriveDescription driveWith(const ParameterDescription &parameter)
{
    GroupDescription group;
    group.address = quint16(parameter.address & 0xFF00);
    group.id = QStringLiteral("op");
    group.parameters << parameter;
    DriveDescription drive;
    drive.groups << group;
    return drive;
}

} // namespace

// A drive that takes a write whose answer never reaches DriveDesk (lost on the line, every
// attempt's): the edit says what the drive holds, found by reading it, never "not written".
class TestLostAnswers : public QObject
{
    Q_OBJECT
private slots:
    void aWriteTheDriveTookIsWrittenThoughItsAnswerWasLost_data()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }

    void aWriteTheDriveTookIsWrittenThoughItsAnswerWasLost()
    {
        QFETCH(Protocol, protocol);
        ProxiedDrive line(protocol, fast(), SpoilingProxy::Spoil::None);
        QString error;
        QVERIFY2(line.listen(&error), qPrintable(error));
        Session s(line.proxy.settings());
        QVERIFY(s.connected());

        line.proxy.setSpoil(SpoilingProxy::Spoil::WritesUnanswered);
        const ParameterDescription parameter = maxSpeedForward();
        DriveState state;
        state.setDescription(driveWith(parameter));
        ValueEdits edits(s.client.get(), &state);
        std::optional<EditOutcome> outcome;
        edits.write(parameter, 0x04, 2345, [&outcome](const EditOutcome &o) { outcome = o; });
        QTRY_VERIFY_WITH_TIMEOUT(outcome, kWaitMs);
        const QString said = EditText(QStringLiteral("op.11"), &parameter).outcome(*outcome);
        QVERIFY2(outcome->complete(), qPrintable(said));
        QCOMPARE(outcome->confirmedByReadingMask, quint8(0x04));
        QVERIFY2(said.startsWith(QStringLiteral("op.11 = 2345 written (set 2)"))
                     && said.contains(QStringLiteral("reading it back showed it taken")),
                 qPrintable(said));
        // The drive's state says so too: what the window's cell shows.
        QCOMPARE(state.editState(kMaxSpeedForward, 2), EditState::Written);
        QCOMPARE(state.value(kMaxSpeedForward, 2), 2345);

        // What the drive holds, asked with every answer passing again.
        line.proxy.setSpoil(SpoilingProxy::Spoil::None);
        QCOMPARE(valueOf(s.call(s.client->readValue(kMaxSpeedForward, 0x04))), 2345);
    }

    // The line freezes once the write is on its way: neither the write nor the read after it
    // is answered. Whether the drive took it is unknown, and said so.
    void aWriteWhoseSetCannotBeReadIsUnknown()
    {
        SimulatorServer server(Protocol::Din66019II, fast());
        QString error;
        QVERIFY2(server.listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        Session s(tcpTo(server, Protocol::Din66019II));
        QVERIFY(s.connected());
        const ParameterDescription parameter = maxSpeedForward();
        DriveState state;
        state.setDescription(driveWith(parameter));
        state.setValue(kMaxSpeedForward, 2, 3000);
        ValueEdits edits(s.client.get(), &state);
        server.bus().setSilent(true);
        std::optional<EditOutcome> outcome;
        edits.write(parameter, 0x04, 2345, [&outcome](const EditOutcome &o) { outcome = o; });
        QTRY_VERIFY_WITH_TIMEOUT(outcome, kWaitMs);
        const QString said = EditText(QStringLiteral("op.11"), &parameter).outcome(*outcome);
        QVERIFY(outcome->anyUnknown());
        QVERIFY2(said.startsWith(QStringLiteral("op.11 = 2345 (set 2) unknown: no answer"))
                     && !said.contains(QStringLiteral("not written")),
                 qPrintable(said));
        // The cell: unknown with the reason, and the value as last read, not the one asked.
        QCOMPARE(state.editState(kMaxSpeedForward, 2), EditState::Unknown);
        QVERIFY(!state.find(kMaxSpeedForward)->failure(2).isEmpty());
        QCOMPARE(state.value(kMaxSpeedForward, 2), 3000);
    }
};

QTEST_GUILESS_MAIN(TestLostAnswers)
#include "tst_lostanswers.moc"
