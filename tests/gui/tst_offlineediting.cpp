#include "tst_mainwindow_support.h"

#include "files/ParameterFileFeature.h"
#include "frame/NoticeBar.h"
#include "frame/ParameterEditing.h"
#include "main/StartupOptions.h"
#include "parameters/ParameterAccess.h"
#include "parameters/ParameterDocument.h"
#include "parameters/ParameterList.h"

#include <QAction>
#include <QFile>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QUndoStack>

#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

// Parameter files in the window: the drive read saved to a file, a file shown and edited with
// no drive (undo, redo, save, the title's mark of unsaved changes), a corrupt file, a value
// outside the limits, and the question about unsaved changes.
class TestOfflineEditing : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    QString m_driveFile; // the simulated F5 saved by the window, made once
    DriveDescription m_driveDocument; // what that file holds

    QString path(const QString &name) const { return m_dir.filePath(name); }

    QAction *action(const char *name) const
    {
        auto *found = m_window->findChild<QAction *>(QString::fromLatin1(name));
        Q_ASSERT(found);
        return found;
    }

    void newWindow()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1300, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    }

    // A copy of the drive's file under `name`, opened in the window.
    QString openCopy(const QString &name)
    {
        const QString copy = path(name);
        QFile::remove(copy);
        if (!QFile::copy(m_driveFile, copy))
            return {};
        if (!files()->openParameterFile(copy))
            return {};
        return copy;
    }

    // Types `text` into the table's editor of the value cell, as a user does; the view commits
    // it on its next turn.
    void typeValue(quint16 address, int set, const QString &text)
    {
        m_window->browser()->showGroup(QStringLiteral("op"));
        ParameterView *view = m_window->browser()->view();
        const QModelIndex index = viewIndex(*m_window, address, set);
        QVERIFY(index.isValid());
        view->scrollTo(index);
        view->setCurrentIndex(index);
        view->edit(index);
        QWidget *editor = view->indexWidget(index);
        QVERIFY(editor);
        editor->setFocus();
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, text);
        QTest::keyClick(editor, Qt::Key_Return);
    }

    QString statusMessage() const { return m_window->statusBar()->currentMessage(); }

    // The one visible message box of that name, once it is up.
    QMessageBox *messageBox(const char *name) const
    {
        QMessageBox *found = nullptr;
        (void)QTest::qWaitFor(
            [&] {
                const auto boxes = m_window->findChildren<QMessageBox *>(QString::fromLatin1(name));
                for (QMessageBox *box : boxes) {
                    if (box->isVisible())
                        found = box;
                }
                return found != nullptr;
            },
            kWaitMs);
        return found;
    }

    // Without the values the drive changes by itself: they move between two reads.
    static DriveDescription settled(DriveDescription drive)
    {
        drive.metadataFromCache = false; // not part of a file
        for (GroupDescription &group : drive.groups) {
            for (ParameterDescription &parameter : group.parameters) {
                if (readBackMayDiffer(parameter))
                    parameter.values = {};
            }
        }
        return drive;
    }

    static DriveDescription withValue(DriveDescription drive, quint16 address, int set, qint32 raw)
    {
        for (GroupDescription &group : drive.groups) {
            for (ParameterDescription &parameter : group.parameters) {
                if (parameter.address == address)
                    parameter.values[std::size_t(set)] = raw;
            }
        }
        return drive;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_settings.clear();
        // (a) The simulated drive, scanned and saved by the window: the fixture of the rest.
        newWindow();
        QVERIFY(!action("saveDriveAction")->isEnabled());
        QVERIFY(connectAndRead(*m_window, simulated()));
        QVERIFY(action("saveDriveAction")->isEnabled());
        QVERIFY(!action("saveFileAction")->isEnabled()); // no file shown
        m_driveFile = path(QStringLiteral("drive.json"));
        QVERIFY(saveDriveAndWait(*m_window, m_driveFile));
        QVERIFY(statusMessage().contains(QStringLiteral("drive.json")));

        QString error;
        const std::optional<DriveDescription> saved = ParameterDocument::load(m_driveFile, &error);
        QVERIFY2(saved, qPrintable(error));
        m_driveDocument = *saved;
        // Read afresh, it is what the table shows of the drive just read.
        QCOMPARE(settled(m_driveDocument),
                 settled(ParameterList::fromScan(m_window->model()->state()->description())));
        QVERIFY(m_driveDocument.parameterCount() > 100);
        // The drive's values, as the drive holds them.
        const ParameterDescription *fixedSpeed = m_driveDocument.find(kFixedSpeed1);
        QVERIFY(fixedSpeed);
        for (int set = 0; set < kParameterSets; ++set)
            QCOMPARE(fixedSpeed->values[std::size_t(set)], 100);
        QCOMPARE(m_driveDocument.find(kDemoPeriod)->values[0],
                 driveValue(m_window->session()->client(), kDemoPeriod));
        // The window goes on with the drive: the file is a backup.
        QVERIFY(m_window->isReady());
        QVERIFY(m_window->parameterFilePath().isEmpty());
        QVERIFY(!m_window->isWindowModified());
        m_window.reset();
    }

    void init()
    {
        m_settings.clear();
        newWindow();
    }

    void cleanup() { m_window.reset(); }

    ParameterFileFeature *files() const { return m_window->feature<ParameterFileFeature>(); }

    void fileShowsWithNoDrive()
    {
        const QString file = openCopy(QStringLiteral("shown.json"));
        QVERIFY(!file.isEmpty());
        QVERIFY(!m_window->session());
        QVERIFY(!m_window->isReady());
        QVERIFY(m_window->editing());
        QCOMPARE(m_window->parameterFilePath(), file);
        QCOMPARE(m_window->model()->state()->description(), m_driveDocument);
        QCOMPARE(m_window->model()->rowCount(), m_driveDocument.groups.size());
        QVERIFY(m_window->windowTitle().contains(QStringLiteral("shown.json[*]")));
        QVERIFY(!m_window->isWindowModified());
        QVERIFY(m_window->noticeBar()->text().contains(QStringLiteral("No drive")));
        QVERIFY(action("saveFileAction")->isEnabled());
        QVERIFY(!action("saveDriveAction")->isEnabled());
        QVERIFY(!action("refreshAction")->isEnabled());
        QVERIFY(!action("pollingAction")->isEnabled());
        // The same editors as for a drive: a spin box with the limits, a plaintext combo.
        QVERIFY(viewIndex(*m_window, kFixedSpeed1, 3).flags() & Qt::ItemIsEditable);
        QVERIFY(!(viewIndex(*m_window, kInverterState, 0).flags() & Qt::ItemIsEditable));
    }

    // (b)
    void editUndoRedoAndSave()
    {
        const QString file = openCopy(QStringLiteral("edited.json"));
        QVERIFY(!file.isEmpty());
        QUndoStack *stack = m_window->undoStack();

        typeValue(kFixedSpeed1, 2, QStringLiteral("250"));
        // The view commits an editor on its next turn.
        QTRY_COMPARE(m_window->model()->state()->value(kFixedSpeed1, 2), 250);
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 1), 100);
        QCOMPARE(viewIndex(*m_window, kFixedSpeed1, 2).data().toString(),
                 QStringLiteral("250 1/min"));
        QCOMPARE(stack->count(), 1);
        QVERIFY(m_window->isWindowModified());
        QVERIFY(files()->hasUnsavedChanges());
        QVERIFY(statusMessage().contains(QStringLiteral("op.20")));

        QVERIFY(action("undoAction")->isEnabled());
        action("undoAction")->trigger();
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 2), 100);
        QVERIFY(!m_window->isWindowModified());
        // The status bar no longer speaks of the edit as if it stood.
        QVERIFY2(statusMessage().startsWith(QStringLiteral("Undone in the file: "))
                     && statusMessage().contains(QStringLiteral("op.20")),
                 qPrintable(statusMessage()));
        QCOMPARE(m_window->model()->state()->description(), m_driveDocument);

        QVERIFY(action("redoAction")->isEnabled());
        action("redoAction")->trigger();
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 2), 250);
        QVERIFY(m_window->isWindowModified());
        QVERIFY2(statusMessage().startsWith(QStringLiteral("Redone in the file: ")),
                 qPrintable(statusMessage()));

        action("saveFileAction")->trigger();
        QVERIFY(!m_window->isWindowModified());
        QVERIFY(statusMessage().contains(QStringLiteral("edited.json")));

        QString error;
        const std::optional<DriveDescription> saved = ParameterDocument::load(file, &error);
        QVERIFY2(saved, qPrintable(error));
        QCOMPARE(saved->find(kFixedSpeed1)->values[2], 250);
        // Nothing else changed.
        QCOMPARE(*saved, withValue(m_driveDocument, kFixedSpeed1, 2, 250));

        // Undo after the save: unsaved again, and saved as it was.
        action("undoAction")->trigger();
        QVERIFY(m_window->isWindowModified());
        const QString other = path(QStringLiteral("saved-as.json"));
        QVERIFY(files()->saveParameterFileAs(other));
        QCOMPARE(m_window->parameterFilePath(), other);
        QVERIFY(m_window->windowTitle().contains(QStringLiteral("saved-as.json")));
        QVERIFY(!m_window->isWindowModified());
        QCOMPARE(ParameterDocument::load(other), m_driveDocument);
        QCOMPARE(ParameterDocument::load(file), withValue(m_driveDocument, kFixedSpeed1, 2, 250));
    }

    // An edited cell is marked as a written one is for a drive, until the file holds its value:
    // undone back to it, typed back to it, or saved.
    void editedCellsAreMarkedUntilSaved()
    {
        const QString file = openCopy(QStringLiteral("marked.json"));
        QVERIFY(!file.isEmpty());
        ParameterModel *model = m_window->model();
        const auto state = [model](int set) { return model->state()->editState(kFixedSpeed1, set); };
        const QModelIndex cell = model->valueIndex(kFixedSpeed1, 2);
        const QModelIndex neighbour = model->valueIndex(kFixedSpeed1, 1);

        typeValue(kFixedSpeed1, 2, QStringLiteral("250"));
        QTRY_COMPARE(model->state()->value(kFixedSpeed1, 2), 250);
        QCOMPARE(state(2), EditState::Changed);
        QCOMPARE(state(1), EditState::None);
        // The written cell's look: its ground and icon, and a tip that says what is unsaved.
        QCOMPARE(cell.data(Qt::BackgroundRole).value<QColor>(),
                 CellDecoration().background(EditState::Written));
        QVERIFY(!cell.data(Qt::DecorationRole).value<QIcon>().isNull());
        QVERIFY2(cell.data(Qt::ToolTipRole).toString().contains(QStringLiteral("save")),
                 qPrintable(cell.data(Qt::ToolTipRole).toString()));
        QVERIFY(!neighbour.data(Qt::BackgroundRole).isValid());

        // A second change of the cell, undone: still not what the file holds.
        QVERIFY(model->requestWrite(kFixedSpeed1, 0x04, 300));
        QCOMPARE(state(2), EditState::Changed);
        m_window->undoStack()->undo();
        QCOMPARE(model->state()->value(kFixedSpeed1, 2), 250);
        QCOMPARE(state(2), EditState::Changed);
        // Undone back to the file's value: unmarked; redone: marked again.
        m_window->undoStack()->undo();
        QCOMPARE(model->state()->value(kFixedSpeed1, 2), 100);
        QCOMPARE(state(2), EditState::None);
        QVERIFY(!cell.data(Qt::BackgroundRole).isValid());
        m_window->undoStack()->redo();
        QCOMPARE(state(2), EditState::Changed);
        // Typed back to the file's value: unmarked too.
        QVERIFY(model->requestWrite(kFixedSpeed1, 0x04, 100));
        QCOMPARE(state(2), EditState::None);
        m_window->undoStack()->undo();
        QCOMPARE(state(2), EditState::Changed);

        // Saved: the file holds it, nothing is marked. Undone after: unlike the file again.
        action("saveFileAction")->trigger();
        QVERIFY(!m_window->isWindowModified());
        QCOMPARE(state(2), EditState::None);
        QVERIFY(!cell.data(Qt::BackgroundRole).isValid());
        m_window->undoStack()->undo();
        QCOMPARE(model->state()->value(kFixedSpeed1, 2), 100);
        QCOMPARE(state(2), EditState::Changed);
        m_window->undoStack()->redo();
        QCOMPARE(state(2), EditState::None);

        // A set copied: every cell it changed is marked, and unmarked by its undo.
        ParameterEditing *editing = m_window->editing();
        editing->copySet(2, 6);
        QCOMPARE(model->state()->value(kFixedSpeed1, 6), 250);
        QCOMPARE(state(6), EditState::Changed);
        QCOMPARE(state(2), EditState::None);
        m_window->undoStack()->undo();
        QCOMPARE(state(6), EditState::None);
    }

    void resetAndCopySetAreUndoable()
    {
        QVERIFY(!openCopy(QStringLiteral("sets.json")).isEmpty());
        ParameterModel *model = m_window->model();
        QVERIFY(model->requestWrite(kFixedSpeed1, 0x01, -300));
        QCOMPARE(model->state()->value(kFixedSpeed1, 0), -300);

        m_window->browser()->showGroup(QStringLiteral("op"));
        m_window->browser()->view()->setCurrentIndex(viewIndex(*m_window, kFixedSpeed1, 0));
        QVERIFY(action("resetAction")->isEnabled());
        action("resetAction")->trigger();
        QCOMPARE(model->state()->value(kFixedSpeed1, 0), 100); // its default
        QCOMPARE(m_window->undoStack()->count(), 2);
        m_window->undoStack()->undo();
        QCOMPARE(model->state()->value(kFixedSpeed1, 0), -300);

        ParameterEditing *editing = m_window->editing();
        QVERIFY(editing);
        editing->copySet(0, 5);
        QCOMPARE(model->state()->value(kFixedSpeed1, 5), -300);
        QVERIFY(statusMessage().contains(QStringLiteral("Copied")));
        m_window->undoStack()->undo();
        QCOMPARE(model->state()->value(kFixedSpeed1, 5), 100);
        m_window->undoStack()->undo();
        QCOMPARE(model->state()->description(), m_driveDocument);
        QVERIFY(!m_window->isWindowModified());
    }

    void valueNeverReadIsRestoredByUndo()
    {
        DriveDescription unread = withValue(m_driveDocument, kFixedSpeed1, 4, 0);
        for (GroupDescription &group : unread.groups) {
            for (ParameterDescription &parameter : group.parameters) {
                if (parameter.address == kFixedSpeed1)
                    parameter.values[4].reset();
            }
        }
        const QString file = path(QStringLiteral("unread.json"));
        QVERIFY(ParameterDocument::save(file, unread));
        QVERIFY(files()->openParameterFile(file));
        QVERIFY(m_window->model()->requestWrite(kFixedSpeed1, 0x10, 42));
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 4), 42);
        m_window->undoStack()->undo();
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 4), std::nullopt);
        QCOMPARE(m_window->model()->state()->description(), unread);
    }

    // (c)
    void corruptFileNamesTheLineAndChangesNothing()
    {
        const QString file = openCopy(QStringLiteral("kept.json"));
        QVERIFY(!file.isEmpty());
        QVERIFY(m_window->model()->requestWrite(kFixedSpeed1, 0x01, 321));
        const DriveDescription shown = m_window->model()->state()->description();
        const QString title = m_window->windowTitle();

        const QString corrupt = path(QStringLiteral("corrupt.json"));
        QFile out(corrupt);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write("{\n    \"format\": \"drivedesk-parameters\",\n    \"version\": 1,\n    ]\n}\n");
        out.close();
        QVERIFY(!files()->openParameterFile(corrupt));

        QVERIFY2(statusMessage().contains(QStringLiteral("line 4")), qPrintable(statusMessage()));
        QVERIFY(statusMessage().contains(QStringLiteral("corrupt.json")));
        QMessageBox *box = messageBox("fileProblem");
        QVERIFY(box);
        QVERIFY(box->text().contains(QStringLiteral("line 4")));
        box->close();
        QCOMPARE(m_window->parameterFilePath(), file);
        QCOMPARE(m_window->windowTitle(), title);
        QVERIFY(m_window->isWindowModified());
        QCOMPARE(m_window->model()->state()->description(), shown);
        QCOMPARE(m_window->undoStack()->count(), 1);
    }

    void corruptFileLeavesTheDriveConnected()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        QVERIFY(!files()->openParameterFile(path(QStringLiteral("missing.json"))));
        QVERIFY(m_window->isReady());
        QVERIFY(m_window->parameterFilePath().isEmpty());
    }

    // (d)
    void valueOutsideTheLimitsIsRefused()
    {
        QVERIFY(!openCopy(QStringLiteral("limits.json")).isEmpty());
        typeValue(kFixedSpeed1, 0, QStringLiteral("9999"));
        QTRY_VERIFY2(statusMessage().contains(QStringLiteral("4000")), qPrintable(statusMessage()));
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 0), 100);
        QCOMPARE(m_window->model()->state()->editState(kFixedSpeed1, 0), EditState::None);

        // Past the table's own check, the editor of the file refuses it as well.
        m_window->showMessage(QString());
        emit m_window->model()->valueEdited(kFixedSpeed1, 0x01, 9999);
        QVERIFY2(statusMessage().contains(QStringLiteral("4000")), qPrintable(statusMessage()));
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 0), 100);
        // Read-only stays read-only in a file.
        QString problem;
        QVERIFY(!m_window->model()->requestWrite(kInverterState, 0x01, 1, &problem));
        QVERIFY(problem.contains(QStringLiteral("read-only")));

        QCOMPARE(m_window->undoStack()->count(), 0);
        QVERIFY(!m_window->isWindowModified());
        QCOMPARE(m_window->model()->state()->description(), m_driveDocument);
    }

    void openingAFileDisconnectsTheDrive()
    {
        QVERIFY(connectAndRead(*m_window, simulated()));
        QVERIFY(m_window->model()->requestWrite(kFixedSpeed1, 0x01, 250));
        QTRY_COMPARE_WITH_TIMEOUT(m_window->undoStack()->count(), 1, kWaitMs);
        QVERIFY(!openCopy(QStringLiteral("after-drive.json")).isEmpty());
        QVERIFY(!m_window->session());
        QVERIFY(statusMessage().contains(QStringLiteral("Disconnected")));
        QCOMPARE(m_window->undoStack()->count(), 0); // the drive's writes are not the file's
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 0), 100);

        // And back to a drive: the file goes.
        QVERIFY(connectAndRead(*m_window, simulated()));
        QVERIFY(m_window->parameterFilePath().isEmpty());
        QVERIFY(!m_window->windowTitle().contains(QStringLiteral("after-drive")));
    }

    void unsavedChangesAreAskedAbout()
    {
        const QString first = openCopy(QStringLiteral("first.json"));
        QVERIFY(!first.isEmpty());
        QVERIFY(m_window->model()->requestWrite(kDemoPeriod, 0x01, 300));
        const QString second = path(QStringLiteral("second.json"));
        QVERIFY(QFile::copy(m_driveFile, second));

        // Cancel: the first file stays, changed.
        QVERIFY(files()->openParameterFile(second));
        QMessageBox *box = messageBox("unsavedChangesQuestion");
        QVERIFY(box);
        box->button(QMessageBox::Cancel)->click();
        QCOMPARE(m_window->parameterFilePath(), first);
        QCOMPARE(m_window->model()->state()->value(kDemoPeriod, 0), 300);

        // Discard: the second file shows; the first is as it was on disk.
        QVERIFY(files()->openParameterFile(second));
        box = messageBox("unsavedChangesQuestion");
        QVERIFY(box);
        box->button(QMessageBox::Discard)->click();
        QCOMPARE(m_window->parameterFilePath(), second);
        QCOMPARE(ParameterDocument::load(first), m_driveDocument);

        // Connecting with changes: asked first; Cancel keeps the file and connects nowhere.
        QVERIFY(m_window->model()->requestWrite(kDemoPeriod, 0x01, 350));
        m_window->connectTo(simulated());
        box = messageBox("unsavedChangesQuestion");
        QVERIFY(box);
        box->button(QMessageBox::Cancel)->click();
        QVERIFY(!m_window->session());
        QCOMPARE(m_window->parameterFilePath(), second);
        QCOMPARE(m_window->model()->state()->value(kDemoPeriod, 0), 350);

        // Closing with changes: Save, then the window closes.
        QVERIFY(m_window->model()->requestWrite(kDemoPeriod, 0x01, 400));
        QVERIFY(!m_window->close());
        QVERIFY(m_window->isVisible());
        box = messageBox("unsavedChangesQuestion");
        QVERIFY(box);
        box->button(QMessageBox::Save)->click();
        QTRY_VERIFY(!m_window->isVisible());
        QCOMPARE(ParameterDocument::load(second), withValue(m_driveDocument, kDemoPeriod, 0, 400));
    }

    void startupOptionOpensAFile()
    {
        const StartupOptions options = StartupOptions::parse(
            { QStringLiteral("drivedesk"), QStringLiteral("--open"), QStringLiteral("f.json") });
        QVERIFY2(options.error.isEmpty(), qPrintable(options.error));
        QCOMPARE(options.parameterFile, QStringLiteral("f.json"));
        QVERIFY(!options.connection);

        const StartupOptions both = StartupOptions::parse(
            { QStringLiteral("drivedesk"), QStringLiteral("--open"), QStringLiteral("f.json"),
              QStringLiteral("--connect"), QStringLiteral("sim") });
        QVERIFY(both.error.contains(QStringLiteral("--open")));
    }
};

QTEST_MAIN(TestOfflineEditing)
#include "tst_offlineediting.moc"
