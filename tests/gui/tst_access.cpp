#include "tst_editsupport.h"

#include "edit/AccessController.h"
#include "edit/EditController.h"

using namespace DriveDesk;
using namespace DriveDesk::EditTest;

// The password level: read from ud.01, raised and lowered by passwords, refused in the drive's
// words, and what it opens in the model.
class TestAccess : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        m_drive = std::make_unique<SimulatedDrive>();
        QVERIFY(m_drive->start());
        m_access = std::make_unique<AccessController>(&m_drive->client, m_drive->model.state());
        m_levels = std::make_unique<QSignalSpy>(m_access.get(), &AccessController::levelChanged);
        m_messages = std::make_unique<QSignalSpy>(m_access.get(), &AccessController::message);
    }

    void cleanup()
    {
        m_messages.reset();
        m_levels.reset();
        m_access.reset();
        m_drive.reset();
    }

    void readsTheLevelInForce()
    {
        QVERIFY(!m_access->isLevelKnown());
        m_access->readLevel();
        QTRY_COMPARE_WITH_TIMEOUT(m_levels->size(), 1, kWaitMs);
        QCOMPARE(m_levels->constFirst().at(0).value<PasswordLevel>(), PasswordLevel::Application);
        QVERIFY(m_access->isLevelKnown());
        QCOMPARE(m_access->level(), PasswordLevel::Application);
        QCOMPARE(m_drive->model.state()->passwordLevel(), PasswordLevel::Application);
        QCOMPARE(m_drive->model.state()->value(kPassword, 0), -4);
        QVERIFY(!m_drive->model.state()->isEditable(kControlMode));
        QVERIFY(m_drive->model.state()->isEditable(kMaxSpeedForward));

        // The same level read again is no change, once its answer is in.
        QSignalSpy traffic(&m_drive->client, &DriveClient::traffic);
        m_access->readLevel();
        QVERIFY(m_drive->answerToALaterRead());
        QCOMPARE(records(traffic, TrafficRecord::Kind::Received), 2); // and the later read's
        QCOMPARE(m_levels->size(), 1);
        QCOMPARE(m_messages->size(), 1);
    }

    void wrongPasswordIsRefusedWithTheDrivesReason()
    {
        m_access->readLevel();
        QTRY_COMPARE_WITH_TIMEOUT(m_levels->size(), 1, kWaitMs);
        m_messages->clear();
        QSignalSpy answers(m_access.get(), &AccessController::passwordAnswered);
        m_access->enterPassword(1234);
        QTRY_COMPARE_WITH_TIMEOUT(m_messages->size(), 1, kWaitMs);
        const QString said = m_messages->constFirst().at(0).toString();
        QVERIFY2(said.contains(ackText(Ack::PasswordInvalid)), qPrintable(said));
        QCOMPARE(answers.size(), 1);
        QCOMPARE(answers.constFirst().at(0).toBool(), false);
        QVERIFY(answers.constFirst().at(1).toString().contains(ackText(Ack::PasswordInvalid)));
        QCOMPARE(m_access->level(), PasswordLevel::Application);
        QCOMPARE(m_levels->size(), 1);
    }

    void passwordWrittenInTheTableIsNoUndoStepAndNoFailure()
    {
        // ud.01 reads the level, never the password written: that is no failed write, and
        // writing the old value back would be a wrong password blocking every older undo step.
        EditController editor(&m_drive->client, &m_drive->model, &m_drive->undoStack);
        QSignalSpy said(&editor, &EditController::message);
        m_access->readLevel();
        QTRY_COMPARE_WITH_TIMEOUT(m_levels->size(), 1, kWaitMs);
        QVERIFY(m_drive->model.requestWrite(kPassword, 0x01, 500));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kPassword), EditState::Written, kWaitMs);
        QCOMPARE(m_drive->model.state()->value(kPassword, 0), -5);
        QTRY_COMPARE_WITH_TIMEOUT(m_access->level(), PasswordLevel::DriveMode, kWaitMs);
        QCOMPARE(m_drive->undoStack.count(), 0);
        QTRY_VERIFY_WITH_TIMEOUT(!said.isEmpty(), kWaitMs);
        const QString text = said.constLast().at(0).toString();
        QVERIFY2(text.contains(QLatin1String("cannot be undone")), qPrintable(text));
        QVERIFY2(!text.contains(QLatin1String("500")), qPrintable(text)); // never the password
    }

    void rightPasswordOpensWhatItsLevelAllows()
    {
        m_access->readLevel();
        QTRY_COMPARE_WITH_TIMEOUT(m_levels->size(), 1, kWaitMs);
        QVERIFY(!m_drive->model.state()->isEditable(kControlMode));
        QVERIFY(m_drive->model.flags(m_drive->model.valueIndex(kControlMode, 0))
                    .testFlag(Qt::ItemIsEditable)
                == false);

        QSignalSpy raised(m_access.get(), &AccessController::levelRaised);
        m_access->enterPassword(500);
        QTRY_COMPARE_WITH_TIMEOUT(m_levels->size(), 2, kWaitMs);
        QCOMPARE(raised.size(), 1);
        QCOMPARE(raised.constFirst().at(0).value<PasswordLevel>(), PasswordLevel::Application);
        QCOMPARE(raised.constFirst().at(1).value<PasswordLevel>(), PasswordLevel::DriveMode);
        QCOMPARE(m_levels->constLast().at(0).value<PasswordLevel>(), PasswordLevel::DriveMode);
        QCOMPARE(m_drive->model.state()->passwordLevel(), PasswordLevel::DriveMode);
        QVERIFY(m_drive->model.state()->isEditable(kControlMode));
        QVERIFY(!m_drive->model.state()->isAboveLevel(kControlMode));

        // And the drive agrees: cn.00 can be written now.
        EditController editor(&m_drive->client, &m_drive->model, &m_drive->undoStack);
        QVERIFY(m_drive->model.requestWrite(kControlMode, 0x01, 1));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kControlMode), EditState::Written, kWaitMs);
        QCOMPARE(m_drive->driveValue(kControlMode), 1);
    }

    void lowerPasswordLocksParameters()
    {
        m_access->enterPassword(100);
        QTRY_COMPARE_WITH_TIMEOUT(m_access->level(), PasswordLevel::CpReadOnly, kWaitMs);
        QVERIFY(!m_drive->model.state()->isEditable(kMaxSpeedForward));
        QVERIFY(m_drive->model.state()->isAboveLevel(kMaxSpeedForward));
        // ud.01 stays open at every level.
        QVERIFY(m_drive->model.state()->isEditable(kPassword));
        m_access->enterPassword(7070);
        QTRY_COMPARE_WITH_TIMEOUT(m_access->level(), PasswordLevel::Supervisor, kWaitMs);
        QVERIFY(m_drive->model.state()->isEditable(kCalibration));
    }

    void aRefreshThatReadsThePasswordParameterTellsTheLevel()
    {
        EditController editor(&m_drive->client, &m_drive->model, &m_drive->undoStack);
        const Reply reply = m_drive->call(m_drive->client.writeValueStandard(kPassword, 330, 0));
        QVERIFY(reply.ok());
        editor.refresh();
        QTRY_COMPARE_WITH_TIMEOUT(m_access->level(), PasswordLevel::CpService, kWaitMs);
        QCOMPARE(m_levels->size(), 1);
    }

private:
    std::unique_ptr<SimulatedDrive> m_drive;
    std::unique_ptr<AccessController> m_access;
    std::unique_ptr<QSignalSpy> m_levels;
    std::unique_ptr<QSignalSpy> m_messages;
};

QTEST_MAIN(TestAccess)
#include "tst_access.moc"
