#include "tst_editsupport.h"

#include "bus/SimulatorServer.h"
#include "edit/AccessController.h"
#include "edit/EditController.h"
#include "journal/Journal.h"

#include <QAbstractItemModelTester>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>

using namespace DriveDesk;
using namespace DriveDesk::EditTest;

// Writes with read-back, refusals in the drive's words, undo and redo, reset to default, set
// copy and refresh, against the simulated drive through a real client.
class TestEditController : public QObject
{
    Q_OBJECT
private:
    // Replies that take their time (20 ms), and op.11 = 1111 and op.20 = -222 in set 0 alone:
    // a copy from set 0 writes these two, op.11 first. The drive is served over TCP from this
    // test's own thread: it answers only when the test's event loop runs, so that what the test
    // does on seeing a request go out is done before the answer, however busy the machine.
    void startSlowDriveWithSetZeroChanged()
    {
        cleanup();
        SimulationOptions slow;
        slow.replyLatencyUs = 20000;
        m_server = std::make_unique<SimulatorServer>(Protocol::Hsp5, slow);
        QString error;
        QVERIFY2(m_server->listenTcp(QStringLiteral("127.0.0.1"), 0, &error), qPrintable(error));
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = m_server->tcpPort();
        m_drive = std::make_unique<SimulatedDrive>(settings);
        QVERIFY(m_drive->start({kMaxSpeedForward >> 8}));
        m_editor = std::make_unique<EditController>(&m_drive->client, &m_drive->model,
                                                    &m_drive->undoStack);
        m_messages = std::make_unique<QSignalSpy>(m_editor.get(), &EditController::message);
        QVERIFY(m_drive->model.requestWrite(kMaxSpeedForward, 0x01, 1111));
        QVERIFY(m_drive->model.requestWrite(kFixedSpeed1, 0x01, -222));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->undoStack.count(), 2, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
    }

private slots:
    void init()
    {
        m_drive = std::make_unique<SimulatedDrive>();
        QVERIFY(m_drive->start());
        m_editor = std::make_unique<EditController>(&m_drive->client, &m_drive->model,
                                                    &m_drive->undoStack);
        m_messages = std::make_unique<QSignalSpy>(m_editor.get(), &EditController::message);
    }

    void cleanup()
    {
        m_messages.reset();
        m_editor.reset();
        m_drive.reset();
        m_server.reset();
    }

    void editInOneSetIsWrittenAndReadBack()
    {
        ParameterModel &model = m_drive->model;
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.state()->value(kMaxSpeedForward, 2), 3000);

        // As the view's delegate does it.
        QVERIFY(model.setData(model.valueIndex(kMaxSpeedForward, 2), 2500));
        QCOMPARE(m_drive->state(kMaxSpeedForward, 2), EditState::Pending);
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kMaxSpeedForward, 2), EditState::Written, kWaitMs);

        QCOMPARE(model.state()->value(kMaxSpeedForward, 2), 2500);
        QCOMPARE(model.valueIndex(kMaxSpeedForward, 2).data().toString(),
                 QStringLiteral("2500 1/min"));
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 2), 2500);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 1), 3000);
        QCOMPARE(m_drive->state(kMaxSpeedForward, 1), EditState::None);
        QCOMPARE(m_drive->undoStack.count(), 1);
        QVERIFY(m_drive->undoStack.undoText().contains(QStringLiteral("op.11")));
        QVERIFY2(texts(*m_messages).join(QLatin1Char('\n')).contains(QStringLiteral("written")),
                 qPrintable(texts(*m_messages).join(QLatin1Char('\n'))));
        QTRY_VERIFY(!m_editor->isBusy());
    }

    void oneValueInSeveralSets()
    {
        ParameterModel &model = m_drive->model;
        const quint8 sets = 0b1010'0101;
        QVERIFY(model.requestWrite(kMaxSpeedForward, sets, 1234));
        for (int set = 0; set < kParameterSets; ++set) {
            const bool chosen = sets & (1u << set);
            QCOMPARE(m_drive->state(kMaxSpeedForward, set),
                     chosen ? EditState::Pending : EditState::None);
        }
        QTRY_VERIFY_WITH_TIMEOUT(m_drive->undoStack.count() == 1, kWaitMs);
        for (int set = 0; set < kParameterSets; ++set) {
            const bool chosen = sets & (1u << set);
            QCOMPARE(m_drive->state(kMaxSpeedForward, set),
                     chosen ? EditState::Written : EditState::None);
            QCOMPARE(model.state()->value(kMaxSpeedForward, set), chosen ? 1234 : 3000);
            QCOMPARE(m_drive->driveValue(kMaxSpeedForward, set), chosen ? 1234 : 3000);
        }
    }

    void quickEditsOfOneCellEndWithTheLast()
    {
        ParameterModel &model = m_drive->model;
        QVERIFY(model.requestWrite(kMaxSpeedForward, 0x02, 1000));
        QVERIFY(model.requestWrite(kMaxSpeedForward, 0x02, 2000));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->undoStack.count(), 2, kWaitMs);
        QTRY_VERIFY(!m_editor->isBusy());
        QCOMPARE(m_drive->state(kMaxSpeedForward, 1), EditState::Written);
        QCOMPARE(model.state()->value(kMaxSpeedForward, 1), 2000);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 1), 2000);

        m_drive->undoStack.undo();
        m_drive->undoStack.undo();
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_drive->state(kMaxSpeedForward, 1), EditState::Written);
        QCOMPARE(model.state()->value(kMaxSpeedForward, 1), 3000);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 1), 3000);
    }

    void parameterWithoutSetsIsWrittenAsItsOneValue()
    {
        m_editor->write(kDemoPeriod, 0xFF, 300);
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kDemoPeriod), EditState::Written, kWaitMs);
        QCOMPARE(m_drive->model.state()->value(kDemoPeriod, 0), 300);
        const Reply reply = m_drive->call(m_drive->client.readValueStandard(kDemoPeriod, 0));
        QVERIFY(reply.data<ParameterValue>());
        QCOMPARE(reply.data<ParameterValue>()->value, 300);
    }

    void readOnlyParameterIsRefusedWithTheDrivesReason()
    {
        const std::optional<qint32> before = m_drive->model.state()->value(kActualFrequency, 0);
        m_editor->write(kActualFrequency, 0x01, 100);
        QCOMPARE(m_drive->state(kActualFrequency), EditState::Pending);
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kActualFrequency), EditState::Failed, kWaitMs);
        const QString reason = ackText(Ack::WriteProtected);
        QVERIFY2(m_drive->toolTip(kActualFrequency).contains(reason),
                 qPrintable(m_drive->toolTip(kActualFrequency)));
        QTRY_VERIFY(!m_messages->isEmpty());
        const QString said = m_messages->constLast().at(0).toString();
        QVERIFY2(said.contains(QStringLiteral("ru.03")) && said.contains(reason), qPrintable(said));
        QCOMPARE(m_drive->model.state()->value(kActualFrequency, 0), before);
        QCOMPARE(m_drive->undoStack.count(), 0);
    }

    void valueOutsideTheLimitsIsRefusedByTheDrive()
    {
        // The model would not let the view ask for it; a direct write reaches the drive.
        QString error;
        QVERIFY(!m_drive->model.requestWrite(kMaxSpeedForward, 0x01, 5000, &error));
        QVERIFY2(error.contains(QStringLiteral("op.11")), qPrintable(error));

        m_editor->write(kMaxSpeedForward, 0x01, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kMaxSpeedForward), EditState::Failed, kWaitMs);
        QVERIFY2(m_drive->toolTip(kMaxSpeedForward).contains(ackText(Ack::DataInvalid)),
                 qPrintable(m_drive->toolTip(kMaxSpeedForward)));
        QCOMPARE(m_drive->model.state()->value(kMaxSpeedForward, 0), 3000);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 0), 3000);
        QCOMPARE(m_drive->undoStack.count(), 0);
        QTRY_VERIFY(!m_editor->isBusy());
    }

    void undoAndRedoGoToTheDrive()
    {
        ParameterModel &model = m_drive->model;
        QUndoStack &stack = m_drive->undoStack;
        // Two sets with different values, then one write over both.
        QVERIFY(m_drive->setDriveValue(kFixedSpeed1, 1, 222));
        QVERIFY(model.state()->setValue(kFixedSpeed1, 1, 222));
        QVERIFY(model.requestWrite(kFixedSpeed1, 0x03, 999));
        QTRY_COMPARE_WITH_TIMEOUT(stack.count(), 1, kWaitMs);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 0), 999);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 1), 999);

        stack.undo();
        QCOMPARE(m_drive->state(kFixedSpeed1, 0), EditState::Pending);
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kFixedSpeed1, 1), EditState::Written, kWaitMs);
        QTRY_COMPARE(m_drive->state(kFixedSpeed1, 0), EditState::Written);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 0), 100);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 1), 222);
        QCOMPARE(model.state()->value(kFixedSpeed1, 0), 100);
        QCOMPARE(model.state()->value(kFixedSpeed1, 1), 222);
        QVERIFY(stack.canRedo());

        stack.redo();
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 0), 999);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 1), 999);
        QCOMPARE(model.state()->value(kFixedSpeed1, 1), 999);
        QVERIFY(texts(*m_messages).contains(QStringLiteral("Redone: ") + stack.undoText()));
    }

    void refusedUndoLeavesTheStackWhereTheDriveIs()
    {
        QUndoStack &stack = m_drive->undoStack;
        m_editor->write(kMaxSpeedForward, 0x01, 2000);
        QTRY_COMPARE_WITH_TIMEOUT(stack.count(), 1, kWaitMs);

        // CP read only: the drive refuses every write of op.11 now.
        AccessController access(&m_drive->client, m_drive->model.state());
        access.enterPassword(100);
        QTRY_COMPARE_WITH_TIMEOUT(access.level(), PasswordLevel::CpReadOnly, kWaitMs);

        stack.undo();
        QCOMPARE(stack.index(), 0);
        QTRY_COMPARE_WITH_TIMEOUT(stack.index(), 1, kWaitMs);
        QVERIFY(stack.canUndo());
        QCOMPARE(m_drive->state(kMaxSpeedForward), EditState::Failed);
        QVERIFY(
            m_drive->toolTip(kMaxSpeedForward).contains(ackText(Ack::AddressOrPasswordInvalid)));
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 0), std::nullopt); // not readable now
        const QString said = m_messages->constLast().at(0).toString();
        QVERIFY2(said.startsWith(QStringLiteral("Undo failed")), qPrintable(said));

        access.enterPassword(440);
        QTRY_COMPARE_WITH_TIMEOUT(access.level(), PasswordLevel::Application, kWaitMs);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 0), 2000);
        stack.undo();
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kMaxSpeedForward), EditState::Written, kWaitMs);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 0), 3000);
        QCOMPARE(stack.index(), 0);
    }

    void resetToDefaultIsUndoable()
    {
        QVERIFY(m_drive->model.requestWrite(kMaxSpeedForward, 0x18, 1000));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->undoStack.count(), 1, kWaitMs);

        m_editor->resetToDefault(kMaxSpeedForward, 0x08);
        QCOMPARE(m_drive->state(kMaxSpeedForward, 3), EditState::Pending);
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->undoStack.count(), 2, kWaitMs);
        QCOMPARE(m_drive->state(kMaxSpeedForward, 3), EditState::Written);
        QCOMPARE(m_drive->model.state()->value(kMaxSpeedForward, 3), 3000);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 3), 3000);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 4), 1000);
        QVERIFY(m_drive->undoStack.undoText().contains(QStringLiteral("default")));

        m_drive->undoStack.undo();
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 3), 1000);
        QCOMPARE(m_drive->model.state()->value(kMaxSpeedForward, 3), 1000);
    }

    void resetOfThePasswordIsRefused()
    {
        m_editor->resetToDefault(kPassword, 0x01);
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->state(kPassword), EditState::Failed, kWaitMs);
        QVERIFY(m_drive->toolTip(kPassword).contains(ackText(Ack::PasswordInvalid)));
        QCOMPARE(m_drive->undoStack.count(), 0);
    }

    void copySetWritesWhatDiffersAsOneUndoStep()
    {
        QVERIFY(m_drive->model.requestWrite(kMaxSpeedForward, 0x01, 1111));
        QVERIFY(m_drive->model.requestWrite(kFixedSpeed1, 0x01, -222));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->undoStack.count(), 2, kWaitMs);

        QSignalSpy progress(m_editor.get(), &EditController::progress);
        QSignalSpy busy(m_editor.get(), &EditController::busyChanged);
        m_editor->copySet(0, 5);
        QVERIFY(m_editor->isBusy());
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(busy.constLast().at(0).toBool(), false);
        // QFuture drops progress steps closer than 40 ms apart: the start and the end are what
        // a user always sees.
        QVERIFY(progress.size() >= 2);
        const QList<QVariant> first = progress.constFirst();
        const QList<QVariant> last = progress.constLast();
        QCOMPARE(first.at(0).toInt(), 0);
        QVERIFY(first.at(1).toInt() >= 2);
        QCOMPARE(last.at(0).toInt(), last.at(1).toInt());
        QCOMPARE(last.at(1).toInt(), first.at(1).toInt());

        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 5), 1111);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 5), -222);
        QCOMPARE(m_drive->model.state()->value(kFixedSpeed1, 5), -222);
        QCOMPARE(m_drive->state(kFixedSpeed1, 5), EditState::Written);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 4), 3000);
        QCOMPARE(m_drive->undoStack.count(), 3);
        QCOMPARE(m_drive->undoStack.undoText(), QStringLiteral("Copy set 0 to set 5"));
        const QString said = m_messages->constLast().at(0).toString();
        QVERIFY2(said.contains(QStringLiteral("copied")), qPrintable(said));
        // In.25 differs per set and is read-only: left as it is, and said so.
        QVERIFY2(said.contains(QStringLiteral("read-only")), qPrintable(said));

        m_drive->undoStack.undo();
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 5), 3000);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 5), 100);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 0), 1111);
    }

    void cancelledCopyKeepsWhatWasWrittenUndoable()
    {
        // The cancel comes as the first write goes out, before the drive (in this thread) can
        // answer it: the write the drive took is reported and undoable, the next is not sent.
        startSlowDriveWithSetZeroChanged();
        if (QTest::currentTestFailed())
            return;

        connect(&m_drive->client, &DriveClient::traffic, this, [this](const TrafficRecord &record) {
            if (record.kind == TrafficRecord::Kind::Sent && m_editor->isBusy())
                m_editor->cancel();
        });
        m_editor->copySet(0, 6);
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_drive->undoStack.count(), 3);
        QCOMPARE(m_drive->undoStack.command(2)->childCount(), 1);
        const QString said = m_messages->constLast().at(0).toString();
        QVERIFY2(said.contains(QStringLiteral("cancelled")), qPrintable(said));
        // op.11 comes before op.20: only it was copied, and the window shows what the drive holds.
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 6), 1111);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 6), 100);
        QCOMPARE(m_drive->model.state()->value(kFixedSpeed1, 6), 100);
        QCOMPARE(m_drive->state(kFixedSpeed1, 6), EditState::None);
        QCOMPARE(m_drive->state(kMaxSpeedForward, 6), EditState::Written);

        m_drive->undoStack.undo();
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 6), 3000);
    }

    // Every value a copy writes is journaled before anything is sent, all in one transaction,
    // and completed with what the drive holds.
    void copySetJournalsEveryValueTogether()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        Journal journal(path);
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        EditJournal editJournal(&journal, JournalDrive {}, QStringLiteral("edit"));
        m_editor->setJournal(&editJournal);
        QVERIFY(m_drive->model.requestWrite(kMaxSpeedForward, 0x01, 1111));
        QVERIFY(m_drive->model.requestWrite(kFixedSpeed1, 0x01, -222));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->undoStack.count(), 2, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        const qsizetype before = journal.entries().value_or(QList<JournalEntry>()).size();
        QCOMPARE(before, 2);

        m_editor->copySet(0, 5);
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        const QList<JournalEntry> copied
            = journal.entries().value_or(QList<JournalEntry>()).mid(before);
        QVERIFY(copied.size() >= 2);
        QList<quint16> addresses;
        for (const JournalEntry &entry : copied) {
            addresses << entry.parameterAddress;
            QCOMPARE(entry.set, 5);
            QCOMPARE(entry.outcome, JournalOutcome::Written);
            QCOMPARE(entry.jobId, copied.constFirst().jobId);
            const std::optional<qint32> held = m_drive->driveValue(entry.parameterAddress, 5);
            QVERIFY(held.has_value());
            QCOMPARE(entry.written.raw, held);
            QCOMPARE(entry.readBack.raw, held);
            QCOMPARE(m_drive->driveValue(entry.parameterAddress, 0), held);
        }
        QVERIFY(addresses.contains(kMaxSpeedForward) && addresses.contains(kFixedSpeed1));
        QCOMPARE(copied.at(addresses.indexOf(kFixedSpeed1)).before.raw, 100);

        // A journal that takes the first entry of the next copy and not the second keeps
        // neither: the entries are one transaction. Nothing is sent, and each cell says why.
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"),
                                                        QStringLiteral("full"));
            db.setDatabaseName(path);
            QVERIFY(db.open());
            QSqlQuery full(db);
            QVERIFY(full.exec(QStringLiteral("CREATE TRIGGER full BEFORE INSERT ON entries "
                                             "WHEN (SELECT count(*) FROM entries) > %1 "
                                             "BEGIN SELECT RAISE(ABORT, 'full'); END")
                                  .arg(before + copied.size())));
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("full"));
        m_editor->copySet(0, 6);
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(journal.entries().value_or(QList<JournalEntry>()).size(),
                 before + copied.size());
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 6), 3000);
        QCOMPARE(m_drive->state(kMaxSpeedForward, 6), EditState::Failed);
        QVERIFY2(m_drive->toolTip(kMaxSpeedForward, 6).contains(QStringLiteral("journal")),
                 qPrintable(m_drive->toolTip(kMaxSpeedForward, 6)));
        const QString said = m_messages->constLast().at(0).toString();
        QVERIFY2(said.contains(QStringLiteral("not copied")), qPrintable(said));
        QCOMPARE(m_drive->undoStack.count(), 3);
        m_editor->setJournal(nullptr);
    }

    // A value typed while a copy writes the same parameter is written after the copy's write:
    // the drive ends with what was typed.
    void anEditDuringACopyWaitsForTheCopysWrite()
    {
        startSlowDriveWithSetZeroChanged();
        if (QTest::currentTestFailed())
            return;

        QList<qint32> ended; // op.20's edits as they end, by the value each asked for
        connect(m_editor->driveEdits(), &ValueEdits::edited, this,
                [&ended](const EditOutcome &outcome) {
                    if (outcome.address == kFixedSpeed1)
                        ended << outcome.steps.constFirst().raw;
                });
        m_editor->copySet(0, 5);
        QVERIFY(m_drive->model.requestWrite(kFixedSpeed1, 0x20, 777)); // set 5
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_drive->driveValue(kFixedSpeed1, 5), 777);
        QCOMPARE(ended, (QList<qint32> { -222, 777 }));
        QCOMPARE(m_drive->model.state()->value(kFixedSpeed1, 5), 777);
        QCOMPARE(m_drive->state(kFixedSpeed1, 5), EditState::Written);
        QCOMPARE(m_drive->driveValue(kMaxSpeedForward, 5), 1111);
        QCOMPARE(m_drive->undoStack.count(), 4);
    }

    void badSetsAreRefusedInWords()
    {
        m_editor->copySet(2, 2);
        m_editor->copySet(0, 8);
        QCOMPARE(m_messages->size(), 2);
        QVERIFY(!m_editor->isBusy());
        QCOMPARE(m_drive->undoStack.count(), 0);
        m_editor->write(kMaxSpeedForward, 0x00, 1000);
        QCOMPARE(m_messages->size(), 3);
        QVERIFY(m_messages->constLast().at(0).toString().contains(QStringLiteral("no set")));
    }

    void refreshRereadsEveryValueAndKeepsFailuresPerCell()
    {
        ParameterModel &model = m_drive->model;
        // Changed behind the model's back.
        QVERIFY(m_drive->setDriveValue(kMaxSpeedForward, 4, 2222));
        QVERIFY(m_drive->setDriveValue(kDemoPeriod, 0, 450));
        QCOMPARE(model.state()->value(kMaxSpeedForward, 4), 3000);

        QSignalSpy progress(m_editor.get(), &EditController::progress);
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        m_editor->refresh();
        QVERIFY(m_editor->isBusy());
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(model.state()->value(kMaxSpeedForward, 4), 2222);
        QCOMPARE(model.state()->value(kDemoPeriod, 0), 450);
        QCOMPARE(m_drive->state(kMaxSpeedForward, 4), EditState::None);
        const QList<QVariant> last = progress.constLast();
        QCOMPARE(last.at(0).toInt(), last.at(1).toInt());
        QVERIFY(last.at(1).toInt() > 200);

        // Until the level is read, everything is tried: what needs Security is refused.
        QVERIFY(m_editor->readFailureCount() > 0);
        QVERIFY2(
            m_editor->readFailure(kCalibration, 0).contains(ackText(Ack::AddressOrPasswordInvalid)),
            qPrintable(m_editor->readFailure(kCalibration, 0)));
        QVERIFY(m_editor->readFailure(kMaxSpeedForward, 4).isEmpty());
        QVERIFY(m_messages->constLast().at(0).toString().contains(QStringLiteral("could not")));

        // With the level known, what it locks is not asked for.
        model.state()->setPasswordLevel(PasswordLevel::Application);
        m_editor->refresh();
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
        QCOMPARE(m_editor->readFailureCount(), 0);
        QVERIFY(m_editor->readFailure(kCalibration, 0).isEmpty());
    }

    void refreshDuringACopyIsRefused()
    {
        QVERIFY(m_drive->model.requestWrite(kMaxSpeedForward, 0x01, 1111));
        QTRY_COMPARE_WITH_TIMEOUT(m_drive->undoStack.count(), 1, kWaitMs);
        m_editor->copySet(0, 1);
        m_editor->refresh();
        QVERIFY(m_messages->constLast().at(0).toString().contains(QStringLiteral("Still")));
        QTRY_VERIFY_WITH_TIMEOUT(!m_editor->isBusy(), kWaitMs);
    }

private:
    std::unique_ptr<SimulatorServer> m_server; // the slow drive's, when a test serves one
    std::unique_ptr<SimulatedDrive> m_drive;
    std::unique_ptr<EditController> m_editor;
    std::unique_ptr<QSignalSpy> m_messages;
};

QTEST_MAIN(TestEditController)
#include "tst_editcontroller.moc"
