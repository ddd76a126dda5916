// MainWindow: the commands behind the menus that open a dialog or act on the selection.
#include "MainWindow.h"

#include "ConnectionDialog.h"
#include "DriveInfoDialog.h"
#include "DriveSession.h"
#include "FindDrivesDialog.h"
#include "ParameterBrowser.h"
#include "ParameterView.h"
#include "RecentConnections.h"

#include "edit/AccessController.h"
#include "edit/EditController.h"
#include "edit/PasswordDialog.h"
#include "edit/PollingController.h"
#include "edit/SetsDialog.h"
#include "model/ParameterModel.h"

#include <QActionGroup>
#include <QComboBox>
#include <QMessageBox>
#include <QSettings>
#include <QTimer>

namespace DriveDesk {

namespace {

// Dialogs open with open() and act in a handler: no nested event loop, and what the handler
// needs it reads when the dialog closes, not before it opened.
template<typename Dialog>
Dialog *openDialog(Dialog *dialog)
{
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

} // namespace

ConnectionDialog *MainWindow::openConnectionDialog()
{
    auto *dialog = new ConnectionDialog(this);
    if (m_session)
        dialog->setSettings(m_session->settings());
    connect(dialog, &QDialog::accepted, this, [this, dialog] { connectTo(dialog->settings()); });
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

void MainWindow::resetToDefault()
{
    if (!isReady())
        return;
    QStringList skipped;
    const QList<QPair<quint16, quint8>> selected = m_browser->selectedParameters();
    for (const auto &[address, setMask] : selected) {
        if (m_model->isEditable(address))
            m_session->editController()->resetToDefault(address, setMask);
        else
            skipped << m_model->indexOf(address).data(Qt::DisplayRole).toString();
    }
    if (!skipped.isEmpty()) {
        constexpr int kNamed = 8;
        QString names = skipped.mid(0, kNamed).join(QStringLiteral(", "));
        if (skipped.size() > kNamed)
            names += tr(" and %n more", nullptr, int(skipped.size() - kNamed));
        showMessage(tr("Not reset, read-only or above the password level in force: %1").arg(names));
    }
}

int MainWindow::activeSet() const
{
    if (!m_session || !m_session->activeSetAddress())
        return -1;
    return m_model->value(*m_session->activeSetAddress(), 0).value_or(-1);
}

void MainWindow::writeToSets()
{
    if (!isReady())
        return;
    // The value of the current cell (or the parameter's first set) goes to the sets chosen.
    const QModelIndex current = m_browser->view()->currentIndex();
    const QList<QPair<quint16, quint8>> selected = m_browser->selectedParameters();
    if (selected.isEmpty())
        return;
    const quint16 address = current.isValid()
        ? current.data(ParameterModel::AddressRole).value<quint16>()
        : selected.constFirst().first;
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter)
        return;
    const QString id = m_model->indexOf(address).data(Qt::DisplayRole).toString();
    if (!parameter->isSetProgrammable()) {
        showMessage(tr("%1 is not set-programmable: it holds one value for every set.").arg(id));
        return;
    }
    if (!m_model->isEditable(address)) {
        showMessage(tr("%1 cannot be changed: it is read-only or above the password level in "
                       "force.")
                        .arg(id));
        return;
    }
    const int set = std::max(0, ParameterModel::setOfColumn(current.column()));
    const std::optional<qint32> raw = m_model->value(address, set);
    if (!raw) {
        showMessage(tr("%1 has no value read in set %2 to write.").arg(id).arg(set));
        return;
    }
    auto *dialog = new SetsDialog(SetsDialog::Mode::ChooseSets, this);
    dialog->setWindowTitle(tr("Write to Sets"));
    dialog->setPrompt(
        tr("Write %1 to %2 in:")
            .arg(m_model->valueIndex(address, set).data(Qt::DisplayRole).toString(), id));
    dialog->setActiveSet(activeSet());
    dialog->setSetMask(quint8(1u << set));
    connect(dialog, &QDialog::accepted, this, [this, dialog, address, set, id] {
        // The value as it is now: polling or another write may have changed it meanwhile.
        const std::optional<qint32> now = isReady() ? m_model->value(address, set) : std::nullopt;
        if (!now) {
            showMessage(tr("%1 has no value read in set %2 to write.").arg(id).arg(set));
            return;
        }
        QString problem;
        if (!m_model->requestWrite(address, dialog->setMask(), *now, &problem))
            showMessage(problem);
    });
    openDialog(dialog);
}

void MainWindow::copySet()
{
    if (!isReady())
        return;
    auto *dialog = new SetsDialog(SetsDialog::Mode::CopySet, this);
    dialog->setWindowTitle(tr("Copy Set"));
    dialog->setPrompt(tr("Copy every set-programmable value you may change from one set to "
                         "another:"));
    const int active = activeSet();
    dialog->setActiveSet(active);
    const int from = std::max(active, 0);
    dialog->setCopy(from, (from + 1) % kParameterSets);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        if (isReady())
            m_session->editController()->copySet(dialog->fromSet(), dialog->toSet());
    });
    openDialog(dialog);
}

void MainWindow::enterPassword()
{
    if (!isReady())
        return;
    const AccessController *access = m_session->accessController();
    auto *dialog = new PasswordDialog(this);
    dialog->setLevel(access->isLevelKnown() ? std::optional<PasswordLevel>(access->level())
                                            : std::nullopt);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        if (isReady() && dialog->password())
            m_session->accessController()->enterPassword(*dialog->password());
    });
    openDialog(dialog);
}

void MainWindow::showDriveInformation()
{
    if (!m_session || !m_session->hasDescription())
        return;
    openDialog(new DriveInfoDialog(m_model->description(), m_session->settings(), this));
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

void MainWindow::setPollingInterval(int ms)
{
    m_pollingIntervalMs = std::clamp(ms, int(PollingController::kMinimumIntervalMs),
                                     int(PollingController::kMaximumIntervalMs));
    for (QAction *action : m_intervalGroup->actions())
        action->setChecked(action->data().toInt() == m_pollingIntervalMs);
    const int index = m_intervalBox->findData(m_pollingIntervalMs);
    if (index >= 0)
        m_intervalBox->setCurrentIndex(index);
    if (m_session)
        m_session->pollingController()->setIntervalMs(m_pollingIntervalMs);
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
