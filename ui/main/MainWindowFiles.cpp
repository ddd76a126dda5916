// MainWindow: parameter files. Opening one shows it with no drive and edits it (the features'
// attachFile()); saving writes it atomically; the file dialogs of the window and its features.
#include "MainWindow.h"

#include "DriveSession.h"
#include "FrameSupport.h"
#include "NoticeBar.h"
#include "ParameterBrowser.h"
#include "RecentConnections.h"

#include "model/ParameterModel.h"
#include "parameters/ParameterDocument.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QUndoStack>

namespace DriveDesk {

namespace {

const QString kDirectoryKey = QStringLiteral("files/lastDirectory");

QString shownPath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

void rememberDirectory(const QString &path)
{
    QSettings().setValue(kDirectoryKey, QFileInfo(path).absolutePath());
}

} // namespace

bool MainWindow::hasUnsavedChanges() const
{
    return !m_filePath.isEmpty() && !m_undoStack->isClean();
}

bool MainWindow::openParameterFile(const QString &path)
{
    QString error;
    const std::optional<DriveDescription> drive = ParameterDocument::load(path, &error);
    if (!drive) {
        return reportFileProblem(tr("Open Parameter File"),
                                 tr("Could not open the file: %1").arg(error));
    }
    rememberDirectory(path);
    settleUnsavedChanges([this, shown = *drive, path] { showParameterFile(shown, path); });
    return true;
}

void MainWindow::showParameterFile(const DriveDescription &drive, const QString &path)
{
    const QString name = QFileInfo(path).fileName();
    QString message
        = tr("Opened %1: %n parameter(s), no drive connected.", nullptr, drive.parameterCount())
              .arg(name);
    if (m_session) {
        message = tr("Disconnected from %1 to show the parameter file %2.")
                      .arg(RecentConnections::describe(m_session->settings()), name);
    }
    closeSession();
    m_nextSettings.reset();
    closeParameterFile();

    // A file has no password level and no live values: what is writable may be edited.
    m_model->setStaleSince(0);
    m_model->setActiveSet(-1);
    m_model->setPasswordLevel(PasswordLevel::Supervisor);
    m_model->setDescription(drive);
    m_filePath = QFileInfo(path).absoluteFilePath();
    // The file's edits are a feature's, as the drive's are.
    for (WindowFeature *feature : std::as_const(m_features))
        feature->attachFile(m_filePath);
    m_favourites.restore(drive, nullptr);

    m_metadataLabel->hide();
    m_stateLabel->setText(tr("No drive: parameter file"));
    m_browser->setEmptyText(tr("The parameter file holds no parameters."));
    m_notice->showInformation(
        tr("No drive is connected: the table shows the parameter file %1, and edits change the "
           "file only, once you save it (%2). Nothing is sent to a drive.")
            .arg(shownPath(m_filePath),
                 m_saveFileAction->shortcut().toString(QKeySequence::NativeText)));
    updateFileTitle();
    updateActions();
    showMessage(message);
}

void MainWindow::closeParameterFile()
{
    if (m_filePath.isEmpty())
        return;
    for (WindowFeature *feature : std::as_const(m_features))
        feature->attachFile({});
    m_undoStack->clear();
    m_filePath.clear();
    m_favourites.forget();
    m_model->clear();
    setWindowModified(false);
    setWindowTitle(tr("DriveDesk"));
    m_stateLabel->setText(tr("Not connected"));
    updateActions();
}

bool MainWindow::saveParameterFile()
{
    return saveParameterFileAs(m_filePath);
}

bool MainWindow::saveParameterFileAs(const QString &path)
{
    if (m_filePath.isEmpty())
        return false;
    QString error;
    if (!ParameterDocument::save(path, m_model->description(), &error)) {
        return reportFileProblem(tr("Save Parameter File"),
                                 tr("Could not save %1: %2. The file on disk is as it was.")
                                     .arg(shownPath(path), error));
    }
    rememberDirectory(path);
    m_filePath = QFileInfo(path).absoluteFilePath();
    m_undoStack->setClean();
    updateFileTitle();
    showMessage(tr("Saved %1.").arg(shownPath(m_filePath)));
    return true;
}

bool MainWindow::reportFileProblem(const QString &title, const QString &text)
{
    showMessage(text);
    auto *box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("fileProblem"));
    openDialog(box);
    return false;
}

void MainWindow::updateFileTitle()
{
    setWindowTitle(tr("%1[*] - DriveDesk").arg(QFileInfo(m_filePath).fileName()));
    setWindowModified(!m_undoStack->isClean());
}

void MainWindow::settleUnsavedChanges(const std::function<void()> &proceed)
{
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
    auto *box
        = new QMessageBox(QMessageBox::Warning, tr("Unsaved Changes"),
                          tr("The parameter file %1 has changes that are not saved.")
                              .arg(QFileInfo(m_filePath).fileName()),
                          QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("unsavedChangesQuestion"));
    box->setInformativeText(tr("Save them before going on?"));
    box->setDefaultButton(QMessageBox::Save);
    m_unsavedQuestion = box;
    connect(box, &QMessageBox::finished, this, [this, box, proceed] {
        m_unsavedQuestion.clear(); // answered; it goes later
        const QMessageBox::StandardButton answer = box->standardButton(box->clickedButton());
        if (answer == QMessageBox::Discard || (answer == QMessageBox::Save && saveParameterFile()))
            proceed();
    });
    openDialog(box);
}

void MainWindow::confirmReplace(const QString &path, const std::function<void()> &proceed)
{
    if (!QFileInfo::exists(path)) {
        proceed();
        return;
    }
    auto *box = new QMessageBox(QMessageBox::Question, tr("Replace File"),
                                tr("%1 exists already. Replace it?").arg(shownPath(path)),
                                QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("replaceFileQuestion"));
    box->button(QMessageBox::Yes)->setText(tr("&Replace"));
    box->setDefaultButton(QMessageBox::Cancel);
    connect(box, &QMessageBox::finished, this, [box, proceed] {
        if (box->standardButton(box->clickedButton()) == QMessageBox::Yes)
            proceed();
    });
    openDialog(box);
}

QFileDialog *MainWindow::fileDialog(const QString &title, const QString &name,
                                    const QString &filter)
{
    const QString directory = QSettings().value(kDirectoryKey, QDir::homePath()).toString();
    auto *dialog = new QFileDialog(this, title, directory,
                                   filter.isEmpty() ? tr("DriveDesk parameter files (*.json)")
                                                    : filter);
    dialog->setObjectName(QStringLiteral("parameterFileDialog"));
    if (name.isEmpty()) {
        dialog->setAcceptMode(QFileDialog::AcceptOpen);
        dialog->setFileMode(QFileDialog::ExistingFile);
    } else {
        dialog->setAcceptMode(QFileDialog::AcceptSave);
        dialog->setFileMode(QFileDialog::AnyFile);
        const QString suffix = QFileInfo(name).suffix();
        dialog->setDefaultSuffix(suffix.isEmpty() ? QStringLiteral("json") : suffix);
        // Asked by confirmReplace(), without the dialog's own nested event loop.
        dialog->setOption(QFileDialog::DontConfirmOverwrite);
        dialog->selectFile(name);
    }
    return dialog;
}

void MainWindow::chooseParameterFile(const QString &title,
                                     std::function<void(const QString &path)> chosen)
{
    chooseFileToRead(title, {}, std::move(chosen));
}

void MainWindow::chooseFileToRead(const QString &title, const QString &filter,
                                  std::function<void(const QString &path)> chosen)
{
    QFileDialog *dialog = fileDialog(title, {}, filter);
    connect(dialog, &QFileDialog::fileSelected, this,
            [chosen = std::move(chosen)](const QString &path) {
                rememberDirectory(path);
                chosen(path);
            });
    openDialog(dialog);
}

void MainWindow::chooseFileToWrite(const QString &title, const QString &name,
                                   const QString &filter,
                                   std::function<void(const QString &path)> chosen)
{
    QFileDialog *dialog = fileDialog(title, name, filter);
    connect(dialog, &QFileDialog::fileSelected, this,
            [this, chosen = std::move(chosen)](const QString &path) {
                confirmReplace(path, [path, chosen] {
                    rememberDirectory(path);
                    chosen(path);
                });
            });
    openDialog(dialog);
}

void MainWindow::chooseFileToOpen()
{
    QFileDialog *dialog = fileDialog(tr("Open Parameter File"));
    connect(dialog, &QFileDialog::fileSelected, this,
            [this](const QString &path) { openParameterFile(path); });
    openDialog(dialog);
}

void MainWindow::chooseFileToSaveAs()
{
    if (m_filePath.isEmpty())
        return;
    QFileDialog *dialog
        = fileDialog(tr("Save Parameter File As"), QFileInfo(m_filePath).fileName());
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString &path) {
        confirmReplace(path, [this, path] { saveParameterFileAs(path); });
    });
    openDialog(dialog);
}

} // namespace DriveDesk
