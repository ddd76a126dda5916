#include "ParameterFileFeature.h"

#include "frame/FileProblem.h"
#include "frame/FrameSupport.h"
#include "frame/NoticeBar.h"

#include "model/ParameterModel.h"
#include "parameters/ParameterDocument.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QToolBar>
#include <QUndoStack>

#include <algorithm>

namespace DriveDesk {

ParameterFileFeature::ParameterFileFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_openAction = new QAction(themedIcon("document-open", QStyle::SP_DialogOpenButton),
                               tr("&Open Parameter File..."), this);
    m_openAction->setObjectName(QStringLiteral("openFileAction"));
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setToolTip(tr("Show and edit a parameter file with no drive"));
    connect(m_openAction, &QAction::triggered, this, &ParameterFileFeature::chooseFileToOpen);

    m_saveAction
        = new QAction(themedIcon("document-save", QStyle::SP_DialogSaveButton), tr("&Save"), this);
    m_saveAction->setObjectName(QStringLiteral("saveFileAction"));
    m_saveAction->setShortcut(QKeySequence::Save);
    m_saveAction->setToolTip(tr("Save the changes of the parameter file shown"));
    connect(m_saveAction, &QAction::triggered, this, &ParameterFileFeature::saveParameterFile);

    m_saveAsAction = new QAction(tr("Save &As..."), this);
    m_saveAsAction->setObjectName(QStringLiteral("saveFileAsAction"));
    m_saveAsAction->setShortcut(QKeySequence::SaveAs);
    m_saveAsAction->setToolTip(tr("Save the parameter file shown under another name"));
    connect(m_saveAsAction, &QAction::triggered, this, &ParameterFileFeature::chooseFileToSaveAs);

    QMenu *file = frame.menu(WindowFrame::Menu::File);
    file->addAction(m_openAction);
    file->addAction(m_saveAction);
    file->addAction(m_saveAsAction);
    // In the toolbar's first section, beside Connect and Disconnect, where users know them;
    // the icons say it without text.
    QToolBar *bar = frame.toolBar();
    const QList<QAction *> placed = bar->actions();
    const auto separator = std::find_if(placed.cbegin(), placed.cend(), [](const QAction *action) {
        return action->isSeparator();
    });
    QAction *before = separator == placed.cend() ? nullptr : *separator;
    bar->insertAction(before, m_openAction);
    bar->insertAction(before, m_saveAction);
    m_openAction->setPriority(QAction::LowPriority);
    m_saveAction->setPriority(QAction::LowPriority);
}

bool ParameterFileFeature::hasUnsavedChanges() const
{
    return !frame().parameterFilePath().isEmpty() && !frame().undoStack()->isClean();
}

bool ParameterFileFeature::openParameterFile(const QString &path)
{
    QString error;
    const std::optional<DriveDescription> drive = ParameterDocument::load(path, &error);
    if (!drive) {
        return reportProblem(tr("Open Parameter File"),
                             tr("Could not open the file: %1").arg(error));
    }
    settle(Leaving::Shown, [this, shown = *drive, path] { showFile(shown, path); });
    return true;
}

void ParameterFileFeature::showFile(const DriveDescription &drive, const QString &path)
{
    frame().showParameterFile(drive, path);
    frame().noticeBar()->showInformation(
        tr("No drive is connected: the table shows the parameter file %1, and edits change the "
           "file only, once you save it (%2). Nothing is sent to a drive.")
            .arg(shownPath(frame().parameterFilePath()),
                 m_saveAction->shortcut().toString(QKeySequence::NativeText)));
}

bool ParameterFileFeature::saveParameterFile()
{
    return saveParameterFileAs(frame().parameterFilePath());
}

bool ParameterFileFeature::saveParameterFileAs(const QString &path)
{
    if (frame().parameterFilePath().isEmpty())
        return false;
    QString error;
    if (!ParameterDocument::save(path, frame().state()->description(), &error)) {
        return reportProblem(tr("Save Parameter File"),
                             tr("Could not save %1: %2. The file on disk is as it was.")
                                 .arg(shownPath(path), error));
    }
    frame().undoStack()->setClean();
    frame().renameParameterFile(path);
    frame().showMessage(tr("Saved %1.").arg(shownPath(frame().parameterFilePath())));
    return true;
}

void ParameterFileFeature::settle(Leaving leaving, std::function<void()> proceed)
{
    Q_UNUSED(leaving)
    if (!hasUnsavedChanges()) {
        proceed();
        return;
    }
    if (m_unsavedQuestion) {
        // Already asked: that answer comes first.
        m_unsavedQuestion->raise();
        m_unsavedQuestion->activateWindow();
        return;
    }
    auto *box = new QMessageBox(
        QMessageBox::Warning, tr("Unsaved Changes"),
        tr("The parameter file %1 has changes that are not saved.")
            .arg(QFileInfo(frame().parameterFilePath()).fileName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, frame().frameWidget());
    box->setObjectName(QStringLiteral("unsavedChangesQuestion"));
    box->setInformativeText(tr("Save them before going on?"));
    box->setDefaultButton(QMessageBox::Save);
    m_unsavedQuestion = box;
    connect(box, &QMessageBox::finished, this, [this, box, proceed = std::move(proceed)] {
        m_unsavedQuestion.clear(); // answered; it goes later
        const QMessageBox::StandardButton answer = box->standardButton(box->clickedButton());
        if (answer == QMessageBox::Discard || (answer == QMessageBox::Save && saveParameterFile()))
            proceed();
    });
    openDialog(box);
}

void ParameterFileFeature::updateActions()
{
    const bool shown = !frame().parameterFilePath().isEmpty();
    m_saveAction->setEnabled(shown);
    m_saveAsAction->setEnabled(shown);
}

void ParameterFileFeature::chooseFileToOpen()
{
    frame().chooseParameterFile(tr("Open Parameter File"),
                                [this](const QString &path) { openParameterFile(path); });
}

void ParameterFileFeature::chooseFileToSaveAs()
{
    const QString shown = frame().parameterFilePath();
    if (shown.isEmpty())
        return;
    frame().chooseFileToWrite(tr("Save Parameter File As"), QFileInfo(shown).fileName(), {},
                              [this](const QString &path) { return saveParameterFileAs(path); });
}

bool ParameterFileFeature::reportProblem(const QString &title, const QString &text)
{
    frame().showMessage(text);
    showFileProblem(frame().frameWidget(), title, text);
    return false;
}

} // namespace DriveDesk
