// MainWindow: its actions, menus, toolbar and status bar, and which actions apply when.
#include "MainWindow.h"

#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"
#include "frame/ParameterBrowser.h"

#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QStatusBar>
#include <QToolBar>

namespace DriveDesk {

void MainWindow::createActions()
{
    m_connectAction = new QAction(themedIcon("network-connect", QStyle::SP_DriveNetIcon),
                                  tr("&Connect..."), this);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    m_connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    m_connectAction->setToolTip(tr("Connect to a drive or the simulated one"));
    connect(m_connectAction, &QAction::triggered, this, &MainWindow::openConnectionDialog);

    m_disconnectAction = new QAction(themedIcon("network-disconnect", QStyle::SP_DialogCloseButton),
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
        = new QAction(themedIcon("view-refresh", QStyle::SP_BrowserReload), tr("&Refresh"), this);
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

    m_driveInfoAction = new QAction(themedIcon("help-about", QStyle::SP_MessageBoxInformation),
                                    tr("Drive Inf&ormation..."), this);
    m_driveInfoAction->setObjectName(QStringLiteral("driveInfoAction"));
    m_driveInfoAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    connect(m_driveInfoAction, &QAction::triggered, this, &MainWindow::showDriveInformation);

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
}

// The frame's part of the menus; the features add theirs, then finishMenus() closes them.
void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(tr("&File"));

    m_driveMenu = menuBar()->addMenu(tr("&Drive"));
    m_driveMenu->addAction(m_connectAction);
    m_driveMenu->addAction(m_disconnectAction);
    m_driveMenu->addAction(m_findDrivesAction);
    m_driveMenu->addSeparator();
    m_driveMenu->addAction(m_refreshAction);
    m_driveMenu->addAction(m_readMetadataAction);

    m_editMenu = menuBar()->addMenu(tr("&Edit"));
    m_editMenu->addAction(m_browser->findAction());

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(m_browser->differsAction());
    m_viewMenu->addAction(m_browser->favouritesAction());
    m_viewMenu->addAction(m_browser->hideAboveLevelAction());
    m_viewMenu->addAction(m_browser->rawValuesAction());
}

void MainWindow::finishMenus()
{
    m_driveMenu->addSeparator();
    m_driveMenu->addAction(m_driveInfoAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_viewMenu->addSeparator();
    // Said before the choice is made: the window's and the drive's texts change only when
    // DriveDesk starts again.
    QMenu *language = m_viewMenu->addMenu(tr("&Language (from the next start)"));
    language->setObjectName(QStringLiteral("languageMenu"));
    language->setToolTipsVisible(true);
    for (QAction *action : m_languageGroup->actions())
        action->setToolTip(tr("Takes effect when DriveDesk starts again"));
    language->addActions(m_languageGroup->actions());

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);

    m_toolBar->addSeparator();
    m_toolBar->addAction(m_driveInfoAction);
    // Only the most used actions (connect, refresh, polling) show their text beside the icon:
    // the others show the icon and say what they do in the tooltip, so that the toolbar fits
    // the window in every language instead of hiding actions behind its overflow arrow.
    m_disconnectAction->setPriority(QAction::LowPriority);
    m_driveInfoAction->setPriority(QAction::LowPriority);
}

QMenu *MainWindow::menu(Menu menu)
{
    switch (menu) {
    case Menu::File: return m_fileMenu;
    case Menu::Drive: return m_driveMenu;
    case Menu::Edit: return m_editMenu;
    case Menu::View: return m_viewMenu;
    }
    return m_viewMenu;
}

void MainWindow::createToolBar()
{
    m_toolBar = addToolBar(tr("Main Toolbar"));
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->addAction(m_connectAction);
    m_toolBar->addAction(m_disconnectAction);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_refreshAction);
}

// The frame's labels; the features add theirs, and the connection's state comes last, at the
// right edge.
void MainWindow::createStatusBar()
{
    m_stateLabel = new QLabel;
    m_stateLabel->setObjectName(QStringLiteral("connectionState"));
    m_metadataLabel = new QLabel(tr("Metadata from cache"));
    m_metadataLabel->setObjectName(QStringLiteral("metadataSource"));
    m_metadataLabel->setToolTip(tr("The groups, names, limits and texts come from the metadata "
                                   "cache of this kind of drive; the values were read from the "
                                   "drive. Drive > Read Metadata Again reads everything."));
    m_metadataLabel->hide();
    addStatusWidget(m_metadataLabel);
}

void MainWindow::addStatusWidget(QWidget *widget)
{
    // A field of its own, sunk into the bar: a long message on the left stops short of it
    // instead of running into its text.
    if (auto *label = qobject_cast<QLabel *>(widget)) {
        label->setFrameStyle(QFrame::StyledPanel | QFrame::Sunken);
        label->setContentsMargins(4, 0, 4, 0);
    }
    statusBar()->addPermanentWidget(widget);
}

void MainWindow::addDock(QDockWidget *dock)
{
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    dock->hide();
}

void MainWindow::updateActions()
{
    const bool session = m_session != nullptr;
    const bool connected = session && m_session->state() == DriveClient::State::Connected;
    const bool connecting = session && m_session->state() == DriveClient::State::Connecting;
    m_disconnectAction->setEnabled(connected || connecting);
    // Save Drive to File reads the drive with progress in the notice bar: one read at a time.
    const bool reading = isReadingDrive();
    m_refreshAction->setEnabled(connected && !m_session->isScanning() && !reading);
    m_readMetadataAction->setEnabled(connected && !m_session->isScanning() && !reading);
    m_driveInfoAction->setEnabled(session && m_session->hasDescription());
    m_browser->setEditingEnabled(editing() != nullptr);
    for (WindowFeature *feature : std::as_const(m_features))
        feature->updateActions();
}

} // namespace DriveDesk
