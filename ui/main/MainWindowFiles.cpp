// MainWindow: the parameter file shown instead of a drive (the file commands are a feature's,
// ui/files), the features' unsaved work settled before the window shows something else or
// closes, and the file dialogs of the window and its features.
#include "MainWindow.h"

#include "RecentConnections.h"

#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"
#include "frame/ParameterBrowser.h"

#include "model/ParameterModel.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QUndoStack>

#include <algorithm>

namespace DriveDesk {

namespace {

const QString kDirectoryKey = QStringLiteral("files/lastDirectory");

void rememberDirectory(const QString &path)
{
    QSettings().setValue(kDirectoryKey, QFileInfo(path).absolutePath());
}

} // namespace

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
    m_model->state()->setStaleSince(0);
    m_model->state()->setActiveSet(-1);
    m_model->state()->setPasswordLevel(PasswordLevel::Supervisor);
    m_model->state()->setDescription(drive);
    m_filePath = QFileInfo(path).absoluteFilePath();
    rememberDirectory(m_filePath);
    // The file's edits are a feature's, as the drive's are.
    for (WindowFeature *feature : std::as_const(m_features))
        feature->attachFile(m_filePath);
    m_favourites.restore(drive, nullptr);

    m_metadataLabel->hide();
    m_stateLabel->setText(tr("No drive: parameter file"));
    m_browser->setEmptyText(tr("The parameter file holds no parameters."));
    updateFileTitle();
    updateActions();
    showMessage(message);
}

void MainWindow::renameParameterFile(const QString &path)
{
    m_filePath = QFileInfo(path).absoluteFilePath();
    rememberDirectory(m_filePath);
    updateFileTitle();
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
    m_model->state()->clear();
    setWindowModified(false);
    setWindowTitle(tr("DriveDesk"));
    m_stateLabel->setText(tr("Not connected"));
    updateActions();
}

void MainWindow::settleFeatures(WindowFeature::Leaving leaving, std::function<void()> proceed,
                                qsizetype from)
{
    if (from >= m_features.size()) {
        proceed();
        return;
    }
    // A feature that asks answers later: the next is asked only then.
    WindowFeature *feature = m_features[from];
    feature->settle(leaving, [this, leaving, proceed = std::move(proceed), from]() mutable {
        settleFeatures(leaving, std::move(proceed), from + 1);
    });
}

bool MainWindow::holdsUnsavedWork() const
{
    return std::any_of(m_features.cbegin(), m_features.cend(),
                       [](const WindowFeature *feature) { return feature->holdsUnsavedWork(); });
}

void MainWindow::updateFileTitle()
{
    setWindowTitle(tr("%1[*] - DriveDesk").arg(QFileInfo(m_filePath).fileName()));
    setWindowModified(!m_undoStack->isClean());
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
                                   std::function<bool(const QString &path)> chosen)
{
    QFileDialog *dialog = fileDialog(title, name, filter);
    connect(dialog, &QFileDialog::fileSelected, this,
            [this, chosen = std::move(chosen)](const QString &path) {
                confirmReplace(path, [path, chosen] {
                    if (chosen(path))
                        rememberDirectory(path);
                });
            });
    openDialog(dialog);
}

} // namespace DriveDesk
