#include "tst_mainwindow_support.h"

#include "delegate/ParameterDelegate.h"
#include "edit/AccessController.h"
#include "edit/PasswordDialog.h"
#include "edit/SetsDialog.h"
#include "frame/DriveSession.h"
#include "frame/ParameterEditing.h"
#include "journal/Journal.h"

#include <QAction>
#include <QApplication>
#include <QFont>
#include <QGuiApplication>
#include <QPalette>
#include <QPointer>
#include <QSignalSpy>
#include <QLabel>
#include <QLineEdit>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>

#include <functional>
#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

// Editing in the main window against the simulated F5: a value typed into the table is
// written and read back, one set or several, a refusal is shown in the drive's words, undo
// writes the old value back, reset to default, refresh and the password.
class TestMainWindowEdit : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    std::unique_ptr<MainWindow> m_window;

    QAction *action(const char *name) const
    {
        auto *found = m_window->findChild<QAction *>(QString::fromLatin1(name));
        Q_ASSERT(found);
        return found;
    }
    DriveClient *client() const { return m_window->session()->client(); }
    EditState state(quint16 address, int set) const
    {
        return m_window->model()->state()->editState(address, set);
    }
    // Works the modal dialog `T` that `trigger` opens, once it is up.
    template<typename T>
    void answerDialog(const std::function<void(T *)> &work, const std::function<void()> &trigger)
    {
        bool answered = false;
        auto *timer = new QTimer(m_window.get());
        connect(timer, &QTimer::timeout, this, [&answered, timer, work] {
            if (auto *dialog = qobject_cast<T *>(QApplication::activeModalWidget())) {
                timer->stop();
                answered = true;
                work(dialog);
            }
        });
        timer->start(10);
        trigger(); // the dialog opens without a nested event loop: wait for it here
        QTRY_VERIFY_WITH_TIMEOUT(answered, kWaitMs);
        delete timer;
    }

    // As a user does it: QTest's double click alone leaves the press without its release.
    static void doubleClick(QAbstractItemView *view, const QModelIndex &index)
    {
        const QPoint point = view->visualRect(index).center();
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, point);
        QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, point);
    }

private slots:
    void init()
    {
        m_settings.clear();
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1300, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QVERIFY(connectAndRead(*m_window, simulated()));
        // The level is known: the table locks what lies above it.
        QTRY_VERIFY(!m_window->statusBar()
                         ->findChild<QLabel *>(QStringLiteral("passwordLevel"))
                         ->text()
                         .isEmpty());
    }

    void cleanup() { m_window.reset(); }

    void reconnectingToTheBuiltInDriveForgetsWhatItNoLongerHolds()
    {
        QVERIFY(m_window->model()->requestWrite(kFixedSpeed1, 0x04, 250));
        QTRY_COMPARE_WITH_TIMEOUT(state(kFixedSpeed1, 2), EditState::Written, kWaitMs);
        QCOMPARE(m_window->undoStack()->count(), 1);

        action("disconnectAction")->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->isReady(), kWaitMs);
        m_window->session()->start();
        QTRY_VERIFY_WITH_TIMEOUT(m_window->isReady(), kWaitMs);
        // The drive starts afresh: its value, no mark, nothing to undo.
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kFixedSpeed1, 2), 100, kWaitMs);
        QCOMPARE(state(kFixedSpeed1, 2), EditState::None);
        QCOMPARE(m_window->undoStack()->count(), 0);
    }

    void valueTypedIntoOneSetIsWrittenAndReadBack()
    {
        m_window->browser()->showGroup(QStringLiteral("op"));
        ParameterView *view = m_window->browser()->view();
        const QModelIndex index = viewIndex(*m_window, kFixedSpeed1, 2);
        view->scrollTo(index);
        view->setCurrentIndex(index);
        view->edit(index);
        QWidget *editor = view->indexWidget(index);
        QVERIFY(editor);
        editor->setFocus();
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, QStringLiteral("250"));
        QTest::keyClick(editor, Qt::Key_Return);

        QTRY_COMPARE_WITH_TIMEOUT(state(kFixedSpeed1, 2), EditState::Written, kWaitMs);
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 2), 250);
        QCOMPARE(viewIndex(*m_window, kFixedSpeed1, 2).data().toString(),
                 QStringLiteral("250 1/min"));
        QCOMPARE(driveValue(client(), kFixedSpeed1, 2), 250);
        QCOMPARE(driveValue(client(), kFixedSpeed1, 1), 100); // the other sets stay
        QCOMPARE(state(kFixedSpeed1, 1), EditState::None);
    }

    void valueWrittenToSeveralSets()
    {
        m_window->browser()->showGroup(QStringLiteral("op"));
        ParameterView *view = m_window->browser()->view();
        // As the view commits an editor: setData on the table's model, set 0.
        const QModelIndex set0 = viewIndex(*m_window, kFixedSpeed1, 0);
        QVERIFY(view->model()->setData(set0, QStringLiteral("300")));
        QTRY_COMPARE_WITH_TIMEOUT(state(kFixedSpeed1, 0), EditState::Written, kWaitMs);
        view->setCurrentIndex(set0);

        answerDialog<SetsDialog>(
            [](SetsDialog *dialog) {
                QCOMPARE(dialog->mode(), SetsDialog::Mode::ChooseSets);
                dialog->setSetMask(0x0E); // sets 1, 2, 3
                dialog->accept();
            },
            [this] { action("writeSetsAction")->trigger(); });

        for (int set = 1; set <= 3; ++set) {
            QTRY_COMPARE_WITH_TIMEOUT(state(kFixedSpeed1, set), EditState::Written, kWaitMs);
            QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, set), 300);
            QCOMPARE(driveValue(client(), kFixedSpeed1, set), 300);
        }
        QCOMPARE(driveValue(client(), kFixedSpeed1, 4), 100);
    }

    void refusedWriteShowsTheDrivesReason()
    {
        // ud.01 takes passwords: the drive refuses a wrong one (ack 8).
        m_window->browser()->showGroup(QStringLiteral("ud"));
        const QModelIndex index = viewIndex(*m_window, kPassword, 0);
        QVERIFY(m_window->browser()->view()->model()->setData(index, QStringLiteral("1234")));
        QTRY_COMPARE_WITH_TIMEOUT(state(kPassword, 0), EditState::Failed, kWaitMs);
        QTRY_VERIFY(
            m_window->statusBar()->currentMessage().contains(QStringLiteral("password invalid")));
        QVERIFY(
            index.data(Qt::ToolTipRole).toString().contains(QStringLiteral("password invalid")));
        QVERIFY(m_window->undoStack()->count() == 0); // nothing happened to undo
    }

    void valueOutsideTheLimitsIsRefusedInTheTable()
    {
        m_window->browser()->showGroup(QStringLiteral("op"));
        ParameterView *view = m_window->browser()->view();
        const QModelIndex index = viewIndex(*m_window, kFixedSpeed1, 0);
        view->setCurrentIndex(index);
        view->edit(index);
        QWidget *editor = view->indexWidget(index);
        QVERIFY(editor);
        editor->setFocus();
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, QStringLiteral("9999"));
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_VERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("4000")));
        QCOMPARE(state(kFixedSpeed1, 0), EditState::None);
        QCOMPARE(driveValue(client(), kFixedSpeed1, 0), 100);
    }

    void undoWritesTheOldValueBack()
    {
        m_window->browser()->showGroup(QStringLiteral("op"));
        QCOMPARE(m_window->model()->state()->value(kDemoPeriod, 0), 200);
        QVERIFY(!action("undoAction")->isEnabled());
        const QModelIndex index = viewIndex(*m_window, kDemoPeriod, 0);
        QVERIFY(m_window->browser()->view()->model()->setData(index, QStringLiteral("30.0")));
        QTRY_COMPARE_WITH_TIMEOUT(state(kDemoPeriod, 0), EditState::Written, kWaitMs);
        QCOMPARE(driveValue(client(), kDemoPeriod), 300);
        QTRY_VERIFY(action("undoAction")->isEnabled());

        action("undoAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kDemoPeriod, 0), 200, kWaitMs);
        QCOMPARE(driveValue(client(), kDemoPeriod), 200);
        QTRY_VERIFY(action("redoAction")->isEnabled());

        action("redoAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kDemoPeriod, 0), 300, kWaitMs);
        QCOMPARE(driveValue(client(), kDemoPeriod), 300);
    }

    // The edit, its undo and its redo each leave an entry in the journal, as the drive took them.
    void everyWriteIsJournaled()
    {
        Journal journal; // the default one: the test's own data folder
        auto entriesFor = [&journal](quint16 address) {
            QList<JournalEntry> found;
            if (journal.open(Journal::Access::Read)) {
                for (const JournalEntry &entry : journal.entries().value_or(QList<JournalEntry>()))
                    if (entry.parameterAddress == address)
                        found << entry;
            }
            journal.close();
            return found;
        };
        const qsizetype before = entriesFor(kFixedSpeed1).size();
        m_window->browser()->showGroup(QStringLiteral("op"));
        const QModelIndex index = viewIndex(*m_window, kFixedSpeed1, 2);
        QVERIFY(m_window->browser()->view()->model()->setData(index, QStringLiteral("345")));
        QTRY_COMPARE_WITH_TIMEOUT(state(kFixedSpeed1, 2), EditState::Written, kWaitMs);
        QTRY_VERIFY(action("undoAction")->isEnabled());
        action("undoAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kFixedSpeed1, 2), 100, kWaitMs);
        QTRY_VERIFY(action("redoAction")->isEnabled());
        action("redoAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kFixedSpeed1, 2), 345, kWaitMs);
        QTRY_VERIFY(!m_window->editing()->isBusy());

        const QList<JournalEntry> entries = entriesFor(kFixedSpeed1).mid(before);
        QCOMPARE(entries.size(), 3);
        const QList<qint32> written { 345, 100, 345 };
        for (int i = 0; i < 3; ++i) {
            const JournalEntry &entry = entries.at(i);
            QCOMPARE(entry.set, 2);
            QCOMPARE(entry.written.raw, written.at(i));
            QCOMPARE(entry.readBack.raw, written.at(i));
            QCOMPARE(entry.outcome, JournalOutcome::Written);
            QCOMPARE(entry.parameterId, QStringLiteral("op.20"));
            QVERIFY(!entry.drive.serialNumber.isEmpty());
        }
        QCOMPARE(entries.at(0).before.raw, 100);
        QCOMPARE(entries.at(1).before.raw, 345);

        // Off: the next write is not journaled.
        action("journalWritesAction")->setChecked(false);
        QVERIFY(m_window->browser()->view()->model()->setData(index, QStringLiteral("346")));
        QTRY_COMPARE_WITH_TIMEOUT(state(kFixedSpeed1, 2), EditState::Written, kWaitMs);
        QCOMPARE(entriesFor(kFixedSpeed1).mid(before).size(), 3);
        action("journalWritesAction")->setChecked(true);

        // Copy set: each value it writes is an entry of its own.
        m_window->editing()->copySet(2, 6);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kFixedSpeed1, 6), 346, kWaitMs);
        QTRY_VERIFY(!m_window->editing()->isBusy());
        const QList<JournalEntry> copied = entriesFor(kFixedSpeed1).mid(before + 3);
        QCOMPARE(copied.size(), 1);
        QCOMPARE(copied.constFirst().set, 6);
        QCOMPARE(copied.constFirst().before.raw, 100);
        QCOMPARE(copied.constFirst().readBack.raw, 346);
        QCOMPARE(copied.constFirst().outcome, JournalOutcome::Written);
    }

    void resetToDefaultOfTheSelectedCell()
    {
        m_window->browser()->showGroup(QStringLiteral("op"));
        ParameterView *view = m_window->browser()->view();
        const QModelIndex index = viewIndex(*m_window, kFixedSpeed1, 5);
        QVERIFY(view->model()->setData(index, QStringLiteral("-250")));
        QTRY_COMPARE_WITH_TIMEOUT(state(kFixedSpeed1, 5), EditState::Written, kWaitMs);
        view->setCurrentIndex(index);
        view->selectionModel()->select(index, QItemSelectionModel::ClearAndSelect);
        QVERIFY(action("resetAction")->isEnabled());
        action("resetAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kFixedSpeed1, 5), 100, kWaitMs);
        QCOMPARE(driveValue(client(), kFixedSpeed1, 5), 100);
    }

    void refreshShowsWhatChangedOnTheDrive()
    {
        // Changed behind the window's back, then F5.
        const QFuture<Reply> write = client()->writeValue(kDemoPeriod, 450, 0x01);
        QVERIFY(waitFinished(write));
        QVERIFY(write.result().ok());
        QCOMPARE(m_window->model()->state()->value(kDemoPeriod, 0), 200);
        action("refreshAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kDemoPeriod, 0), 450, kWaitMs);
    }

    void passwordOpensAHigherLevel()
    {
        auto *level = m_window->statusBar()->findChild<QLabel *>(QStringLiteral("passwordLevel"));
        QCOMPARE(level->text(), QStringLiteral("Password level: Application"));
        answerDialog<PasswordDialog>(
            [](PasswordDialog *dialog) {
                auto *field = dialog->findChild<QLineEdit *>();
                QVERIFY(field);
                field->setText(QStringLiteral("500"));
                dialog->accept();
            },
            [this] { action("passwordAction")->trigger(); });
        QTRY_COMPARE_WITH_TIMEOUT(level->text(), QStringLiteral("Password level: Drive mode"),
                                  kWaitMs);
    }

    void wrongPasswordKeepsTheDialogOpenWithTheDrivesReason()
    {
        QPointer<PasswordDialog> dialog;
        answerDialog<PasswordDialog>([&dialog](PasswordDialog *d) { dialog = d; },
                                     [this] { action("passwordAction")->trigger(); });
        auto *field = dialog->findChild<QLineEdit *>();
        field->setText(QStringLiteral("1234"));
        QTest::keyClick(field, Qt::Key_Return);
        auto *answer = dialog->findChild<QLabel *>(QStringLiteral("passwordAnswer"));
        QTRY_VERIFY_WITH_TIMEOUT(answer->text().contains(ackText(Ack::PasswordInvalid)), kWaitMs);
        QVERIFY(dialog->isVisible());

        field->setText(QStringLiteral("7070"));
        QTest::keyClick(field, Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog || !dialog->isVisible(), kWaitMs);
        auto *level = m_window->statusBar()->findChild<QLabel *>(QStringLiteral("passwordLevel"));
        QTRY_COMPARE_WITH_TIMEOUT(level->text(), QStringLiteral("Password level: Supervisor"),
                                  kWaitMs);
    }

    void aHigherLevelReadsWhatItOpensAndALowerOneGreysIt()
    {
        constexpr quint16 kCalibration = 0x0E28; // In.40, read at Security (6)
        ParameterModel *model = m_window->model();
        QCOMPARE(model->state()->value(kCalibration, 0), std::nullopt);
        QVERIFY(model->state()->isAboveLevel(kCalibration));
        QVERIFY(m_window->findChild<AccessController *>());
        m_window->findChild<AccessController *>()->enterPassword(7070);
        // No refresh asked for: the level's change reads what it opened.
        QTRY_VERIFY_WITH_TIMEOUT(model->state()->value(kCalibration, 0).has_value(), kWaitMs);
        QCOMPARE(model->valueIndex(kCalibration, 0).data().toString(), QStringLiteral("5A5Ah"));
        QVERIFY(!model->state()->isAboveLevel(kCalibration));

        m_window->findChild<AccessController *>()->enterPassword(440);
        QTRY_VERIFY_WITH_TIMEOUT(model->state()->isAboveLevel(kCalibration), kWaitMs);
        QCOMPARE(model->valueIndex(kCalibration, 0).data(Qt::ForegroundRole).value<QColor>(),
                 QGuiApplication::palette().color(QPalette::Disabled, QPalette::Text));
    }

    void editingThePasswordParameterInTheTableAsksForAPassword()
    {
        m_window->browser()->showGroup(QStringLiteral("ud"));
        ParameterView *view = m_window->browser()->view();
        const QModelIndex index = viewIndex(*m_window, kPassword, 0);
        view->scrollTo(index);
        view->setCurrentIndex(index);
        answerDialog<PasswordDialog>(
            [](PasswordDialog *dialog) {
                auto *field = dialog->findChild<QLineEdit *>();
                field->setText(QStringLiteral("500"));
                dialog->accept();
            },
            [view, index] { doubleClick(view, index); });
        QVERIFY(!view->indexWidget(index)); // no editor in the cell
        auto *level = m_window->statusBar()->findChild<QLabel *>(QStringLiteral("passwordLevel"));
        QTRY_COMPARE_WITH_TIMEOUT(level->text(), QStringLiteral("Password level: Drive mode"),
                                  kWaitMs);
        QCOMPARE(state(kPassword, 0), EditState::None);
        QCOMPARE(m_window->undoStack()->count(), 0);
    }

    void readOnlyCellsLookReadOnlyAndSayWhyTheyCannotBeEdited()
    {
        constexpr quint16 kSetSpeedDisplay = 0x0300; // op.00, read-only
        m_window->browser()->showGroup(QStringLiteral("op"));
        ParameterView *view = m_window->browser()->view();
        const QModelIndex readOnly = viewIndex(*m_window, kSetSpeedDisplay, 0);
        const QModelIndex editable = viewIndex(*m_window, kDemoPeriod, 0);
        QVERIFY(readOnly.data(Qt::BackgroundRole).value<QColor>().isValid());
        QVERIFY(readOnly.data(Qt::BackgroundRole) != editable.data(Qt::BackgroundRole));

        view->setCurrentIndex(readOnly);
        doubleClick(view, readOnly);
        QVERIFY(!view->indexWidget(readOnly));
        QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("op.00 is read-only"));

        // A digit typed on it neither edits nor jumps to a row that starts with it.
        m_window->statusBar()->clearMessage();
        view->setFocus();
        QTest::keyClick(view, Qt::Key_5);
        QCOMPARE(view->currentIndex(), readOnly);
        QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("op.00 is read-only"));
    }

    void theActiveSetsColumnIsMarkedAndFollowsFr02()
    {
        constexpr quint16 kActiveSet = 0x0902; // Fr.02
        ParameterModel *model = m_window->model();
        const auto header = [model](int set) {
            return model->headerData(ParameterModel::columnOfSet(set), Qt::Horizontal).toString();
        };
        QTRY_COMPARE_WITH_TIMEOUT(header(0), QStringLiteral("Value / set 0 (active)"), kWaitMs);
        QCOMPARE(header(2), QStringLiteral("Set 2"));

        QVERIFY(model->requestWrite(kActiveSet, 0x01, 2));
        QTRY_COMPARE_WITH_TIMEOUT(header(2), QStringLiteral("Set 2 (active)"), kWaitMs);
        QCOMPARE(header(0), QStringLiteral("Value / set 0"));
        QVERIFY(model->headerData(ParameterModel::columnOfSet(2), Qt::Horizontal, Qt::FontRole)
                    .value<QFont>()
                    .bold());
        // The table's header says so, through its filter.
        QCOMPARE(m_window->browser()
                     ->view()
                     ->model()
                     ->headerData(ParameterModel::columnOfSet(2), Qt::Horizontal)
                     .toString(),
                 QStringLiteral("Set 2 (active)"));
    }
};

QTEST_MAIN(TestMainWindowEdit)
#include "tst_mainwindow_edit.moc"
