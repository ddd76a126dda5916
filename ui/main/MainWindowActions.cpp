// MainWindow: its actions, menus, toolbar and status bar, and which actions apply when.
#include "MainWindow.h"

#include "DriveSession.h"
#include "ParameterBrowser.h"
#include "edit/EditController.h"

#include "monitor/TelegramMonitor.h"

#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QMenuBar>
#include <QProgressBar>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>

namespace DriveDesk {

namespace {

const int kIntervalsMs[] = { 100, 200, 500, 1000, 2000, 5000 };

QString intervalText(int ms)
{
    return ms < 1000 ? MainWindow::tr("%1 ms").arg(ms) : MainWindow::tr("%1 s").arg(ms / 1000);
}

} // namespace

void MainWindow::createActions()
{
    const auto icon = [this](const char *theme, QStyle::StandardPixmap fallback) {
        return QIcon::fromTheme(QString::fromLatin1(theme), style()->standardIcon(fallback));
    };
    m_connectAction
        = new QAction(icon("network-connect", QStyle::SP_DriveNetIcon), tr("&Connect..."), this);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    m_connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    m_connectAction->setToolTip(tr("Connect to a drive or the simulated one"));
    connect(m_connectAction, &QAction::triggered, this, &MainWindow::openConnectionDialog);

    m_disconnectAction = new QAction(icon("network-disconnect", QStyle::SP_DialogCloseButton),
                                     tr("&Disconnect"), this);
    m_disconnectAction->setObjectName(QStringLiteral("disconnectAction"));
    m_disconnectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_K));
    connect(m_disconnectAction, &QAction::triggered, this, &MainWindow::disconnectFromDrive);

    m_findDrivesAction = new QAction(tr("&Find Drives..."), this);
    m_findDrivesAction->setObjectName(QStringLiteral("findDrivesAction"));
    m_findDrivesAction->setToolTip(tr("Look for drives at the addresses 0..239 of a DIN66019II "
                                      "bus"));
    connect(m_findDrivesAction, &QAction::triggered, this, &MainWindow::findDrives);

    m_refreshAction
        = new QAction(icon("view-refresh", QStyle::SP_BrowserReload), tr("&Refresh"), this);
    m_refreshAction->setObjectName(QStringLiteral("refreshAction"));
    m_refreshAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_refreshAction->setToolTip(tr("Read every value from the drive again"));
    connect(m_refreshAction, &QAction::triggered, this, &MainWindow::refresh);

    m_readMetadataAction = new QAction(tr("Read &Metadata Again"), this);
    m_readMetadataAction->setObjectName(QStringLiteral("readMetadataAction"));
    m_readMetadataAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    m_readMetadataAction->setToolTip(tr("Read the groups, names, limits and texts from the "
                                        "drive instead of the metadata cache"));
    connect(m_readMetadataAction, &QAction::triggered, this, [this] {
        if (m_session)
            m_session->rescan(MetadataSource::RefreshCache);
    });

    m_pollingAction = new QAction(icon("media-playback-start", QStyle::SP_MediaPlay),
                                  tr("&Poll Live Values"), this);
    m_pollingAction->setObjectName(QStringLiteral("pollingAction"));
    m_pollingAction->setCheckable(true);
    m_pollingAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_pollingAction->setToolTip(tr("Read the run display (ru) again and again"));
    connect(m_pollingAction, &QAction::toggled, this, [this](bool on) {
        if (m_session)
            m_session->setPollingWanted(on);
    });
    m_intervalGroup = new QActionGroup(this);
    for (int ms : kIntervalsMs) {
        QAction *action = m_intervalGroup->addAction(tr("Every %1").arg(intervalText(ms)));
        action->setCheckable(true);
        action->setData(ms);
        connect(action, &QAction::triggered, this, [this, ms] { setPollingInterval(ms); });
    }

    // Own actions rather than the stack's: they also go off while the drive cannot be written.
    m_undoAction = new QAction(icon("edit-undo", QStyle::SP_ArrowBack), tr("&Undo"), this);
    m_undoAction->setObjectName(QStringLiteral("undoAction"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    connect(m_undoAction, &QAction::triggered, m_undoStack, &QUndoStack::undo);
    m_redoAction = new QAction(icon("edit-redo", QStyle::SP_ArrowForward), tr("&Redo"), this);
    m_redoAction->setObjectName(QStringLiteral("redoAction"));
    m_redoAction->setShortcut(QKeySequence::Redo);
    connect(m_redoAction, &QAction::triggered, m_undoStack, &QUndoStack::redo);
    // The menu names the write; the toolbar button stays short, its tooltip names it.
    m_undoAction->setIconText(tr("Undo"));
    m_redoAction->setIconText(tr("Redo"));
    connect(m_undoStack, &QUndoStack::undoTextChanged, this, [this](const QString &text) {
        m_undoAction->setText(text.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(text));
        m_undoAction->setToolTip(text.isEmpty() ? tr("Undo") : tr("Undo %1").arg(text));
    });
    connect(m_undoStack, &QUndoStack::redoTextChanged, this, [this](const QString &text) {
        m_redoAction->setText(text.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(text));
        m_redoAction->setToolTip(text.isEmpty() ? tr("Redo") : tr("Redo %1").arg(text));
    });
    connect(m_undoStack, &QUndoStack::canUndoChanged, this, &MainWindow::updateActions);
    connect(m_undoStack, &QUndoStack::canRedoChanged, this, &MainWindow::updateActions);

    m_resetAction = new QAction(icon("edit-clear", QStyle::SP_DialogResetButton),
                                tr("Reset to &Default"), this);
    m_resetAction->setObjectName(QStringLiteral("resetAction"));
    m_resetAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    m_resetAction->setToolTip(tr("Set the selected values to the drive's default"));
    connect(m_resetAction, &QAction::triggered, this, &MainWindow::resetToDefault);
    m_writeSetsAction = new QAction(tr("&Write to Sets..."), this);
    m_writeSetsAction->setObjectName(QStringLiteral("writeSetsAction"));
    m_writeSetsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    m_writeSetsAction->setToolTip(tr("Write a value to several parameter sets at once"));
    connect(m_writeSetsAction, &QAction::triggered, this, &MainWindow::writeToSets);
    m_copySetAction = new QAction(tr("&Copy Set..."), this);
    m_copySetAction->setObjectName(QStringLiteral("copySetAction"));
    m_copySetAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    m_copySetAction->setToolTip(tr("Copy every set-programmable value from one set to another"));
    connect(m_copySetAction, &QAction::triggered, this, &MainWindow::copySet);
    m_passwordAction = new QAction(icon("dialog-password", QStyle::SP_DialogYesButton),
                                   tr("&Password..."), this);
    m_passwordAction->setObjectName(QStringLiteral("passwordAction"));
    m_passwordAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    m_passwordAction->setToolTip(tr("Enter a password to open a higher password level"));
    connect(m_passwordAction, &QAction::triggered, this, &MainWindow::enterPassword);
    m_driveInfoAction = new QAction(icon("help-about", QStyle::SP_MessageBoxInformation),
                                    tr("Drive &Information..."), this);
    m_driveInfoAction->setObjectName(QStringLiteral("driveInfoAction"));
    m_driveInfoAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    connect(m_driveInfoAction, &QAction::triggered, this, &MainWindow::showDriveInformation);

    m_monitorAction = m_monitor->toggleViewAction();
    m_monitorAction->setObjectName(QStringLiteral("monitorAction"));
    m_monitorAction->setText(tr("&Telegram Monitor"));
    m_monitorAction->setIcon(icon("utilities-terminal", QStyle::SP_FileDialogDetailedView));
    m_monitorAction->setShortcut(QKeySequence(Qt::Key_F12));

    m_languageGroup = new QActionGroup(this);
    for (const auto &[language, name] :
         { std::pair { Language::English, QStringLiteral("English") },
           std::pair { Language::German, QStringLiteral("Deutsch") } }) {
        QAction *action = m_languageGroup->addAction(name);
        action->setCheckable(true);
        action->setChecked(language == m_language);
        const Language chosen = language;
        connect(action, &QAction::triggered, this, [this, chosen] { chooseLanguage(chosen); });
    }

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setObjectName(QStringLiteral("quitAction"));
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);
    m_aboutAction = new QAction(tr("&About DriveDesk"), this);
    m_aboutAction->setObjectName(QStringLiteral("aboutAction"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::about);

    m_browser->setContextActions({ m_resetAction, m_writeSetsAction });
}

void MainWindow::createMenus()
{
    QMenu *drive = menuBar()->addMenu(tr("&Drive"));
    drive->addAction(m_connectAction);
    drive->addAction(m_disconnectAction);
    drive->addAction(m_findDrivesAction);
    drive->addSeparator();
    drive->addAction(m_refreshAction);
    drive->addAction(m_readMetadataAction);
    drive->addAction(m_pollingAction);
    QMenu *interval = drive->addMenu(tr("Polling &Interval"));
    interval->addActions(m_intervalGroup->actions());
    drive->addSeparator();
    drive->addAction(m_driveInfoAction);
    drive->addSeparator();
    drive->addAction(m_quitAction);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    edit->addAction(m_resetAction);
    edit->addAction(m_writeSetsAction);
    edit->addAction(m_copySetAction);
    edit->addSeparator();
    edit->addAction(m_browser->findAction());
    edit->addSeparator();
    edit->addAction(m_passwordAction);

    QMenu *view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_browser->differsAction());
    view->addAction(m_browser->favouritesAction());
    view->addAction(m_browser->hideAboveLevelAction());
    view->addAction(m_browser->rawValuesAction());
    view->addSeparator();
    view->addAction(m_monitorAction);
    view->addSeparator();
    QMenu *language = view->addMenu(tr("&Language"));
    language->addActions(m_languageGroup->actions());

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::createToolBar()
{
    QToolBar *bar = addToolBar(tr("Main Toolbar"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->addAction(m_connectAction);
    bar->addAction(m_disconnectAction);
    bar->addSeparator();
    bar->addAction(m_refreshAction);
    bar->addAction(m_pollingAction);
    m_intervalBox = new QComboBox;
    m_intervalBox->setObjectName(QStringLiteral("pollingInterval"));
    m_intervalBox->setToolTip(tr("How often the live values are read"));
    for (int ms : kIntervalsMs)
        m_intervalBox->addItem(intervalText(ms), ms);
    connect(m_intervalBox, &QComboBox::activated, this,
            [this](int index) { setPollingInterval(m_intervalBox->itemData(index).toInt()); });
    bar->addWidget(m_intervalBox);
    bar->addSeparator();
    bar->addAction(m_undoAction);
    bar->addAction(m_redoAction);
    bar->addAction(m_resetAction);
    bar->addSeparator();
    bar->addAction(m_passwordAction);
    bar->addAction(m_driveInfoAction);
    bar->addAction(m_monitorAction);
}

void MainWindow::createStatusBar()
{
    m_stateLabel = new QLabel;
    m_stateLabel->setObjectName(QStringLiteral("connectionState"));
    m_levelLabel = new QLabel;
    m_levelLabel->setObjectName(QStringLiteral("passwordLevel"));
    m_levelLabel->setToolTip(tr("The password level in force on the drive (ud.01)"));
    m_setsLabel = new QLabel;
    m_setsLabel->setObjectName(QStringLiteral("parameterSets"));
    m_setsLabel->setToolTip(tr("Fr.02: the set the drive works with. Fr.09: the set that "
                               "indirect addressing reaches."));
    m_setsLabel->hide();
    m_metadataLabel = new QLabel(tr("Metadata from cache"));
    m_metadataLabel->setObjectName(QStringLiteral("metadataSource"));
    m_metadataLabel->setToolTip(tr("The groups, names, limits and texts come from the metadata "
                                   "cache of this kind of drive; the values were read from the "
                                   "drive. Drive > Read Metadata Again reads everything."));
    m_metadataLabel->hide();
    m_busy = new QProgressBar;
    m_busy->setObjectName(QStringLiteral("refreshProgress"));
    m_busy->setMaximumWidth(160);
    m_busy->hide();
    statusBar()->addPermanentWidget(m_busy);
    statusBar()->addPermanentWidget(m_metadataLabel);
    statusBar()->addPermanentWidget(m_setsLabel);
    statusBar()->addPermanentWidget(m_levelLabel);
    statusBar()->addPermanentWidget(m_stateLabel);
}

void MainWindow::updateActions()
{
    const bool session = m_session != nullptr;
    const bool connected = session && m_session->state() == DriveClient::State::Connected;
    const bool connecting = session && m_session->state() == DriveClient::State::Connecting;
    const bool ready = isReady();
    const bool selected = m_browser->hasSelectedParameter();
    m_disconnectAction->setEnabled(connected || connecting);
    m_refreshAction->setEnabled(connected && !m_session->isScanning());
    m_readMetadataAction->setEnabled(connected && !m_session->isScanning());
    m_resetAction->setEnabled(ready && selected);
    m_writeSetsAction->setEnabled(ready && selected);
    m_copySetAction->setEnabled(ready);
    m_passwordAction->setEnabled(ready);
    m_driveInfoAction->setEnabled(session && m_session->hasDescription());
    // An undo while a write is still on its way could leave the stack and the drive apart.
    const bool idle = ready && !m_session->editController()->isBusy();
    m_undoAction->setEnabled(idle && m_undoStack->canUndo());
    m_redoAction->setEnabled(idle && m_undoStack->canRedo());
    m_browser->setEditingEnabled(ready);
}

} // namespace DriveDesk
