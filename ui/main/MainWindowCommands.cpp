// MainWindow: the frame's commands that open a dialog.
#include "MainWindow.h"

#include "ConnectionDialog.h"
#include "DriveInfoDialog.h"
#include "frame/DriveSession.h"
#include "FindDrivesDialog.h"
#include "frame/ParameterBrowser.h"
#include "frame/ParameterView.h"
#include "RecentConnections.h"

#include "frame/FrameSupport.h"

#include "model/ParameterModel.h"

#include <QMessageBox>
#include <QSettings>
#include <QTimer>

namespace DriveDesk {

ConnectionDialog *MainWindow::openConnectionDialog()
{
    auto *dialog = new ConnectionDialog(this);
    if (m_session)
        dialog->setSettings(m_session->settings());
    connect(dialog, &QDialog::accepted, this, [this, dialog] { connectTo(dialog->settings()); });
    // The search's telegrams belong in the telegram monitor as much as the session's.
    connect(dialog, &ConnectionDialog::searchStarted, this, [this](DriveClient *client) {
        for (WindowFeature *feature : std::as_const(m_features))
            feature->followClient(client);
    });
    return openDialog(dialog);
}

void MainWindow::findDrives()
{
    // On a bus already connected, search through that connection: the port is ours.
    if (m_session && m_session->state() == DriveClient::State::Connected
        && m_session->settings().protocol != Protocol::Hsp5) {
        auto *dialog = new FindDrivesDialog(m_session->client(), this);
        connect(dialog, &QDialog::accepted, this, [this, dialog] {
            if (!m_session || !dialog->chosenAddress())
                return;
            ConnectionSettings settings = m_session->settings(); // the same bus, another drive
            settings.driveAddress = *dialog->chosenAddress();
            connectTo(settings);
        });
        openDialog(dialog);
        return;
    }
    ConnectionDialog *dialog = openConnectionDialog();
    QTimer::singleShot(0, dialog, &ConnectionDialog::findDrives);
}

void MainWindow::showDriveInformation()
{
    if (!m_session || !m_session->hasDescription())
        return;
    openDialog(new DriveInfoDialog(m_model->state()->description(), m_session->settings(), this));
}

void MainWindow::chooseLanguage(Language language)
{
    QSettings().setValue(QStringLiteral("language"), languageCode(language));
    if (language == m_language)
        return;
    openDialog(new QMessageBox(QMessageBox::Information, tr("Language"),
                               tr("DriveDesk uses the new language from its next start on: the "
                                  "window's texts and the drive's own texts."),
                               QMessageBox::Ok, this));
}

void MainWindow::about()
{
    auto *box = new QMessageBox(QMessageBox::NoIcon, tr("About DriveDesk"),
                                tr("<p><b>DriveDesk</b> %1</p><p>Reads and edits the parameters "
                                   "of KEB frequency inverters over HSP5, DIN66019II and "
                                   "DIN66019, and ships a simulated COMBIVERT F5.</p>")
                                    .arg(QCoreApplication::applicationVersion().toHtmlEscaped()),
                                QMessageBox::Ok, this);
    box->setIconPixmap(windowIcon().pixmap(64, 64));
    openDialog(box);
}

} // namespace DriveDesk
