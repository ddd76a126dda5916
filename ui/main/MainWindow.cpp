#include "MainWindow.h"

#include "DriveFavourites.h"
#include "frame/DriveSession.h"
#include "frame/NoticeBar.h"
#include "frame/ParameterBrowser.h"
#include "frame/ParameterView.h"
#include "RecentConnections.h"
#include "WindowFeatures.h"

#include "delegate/ParameterDelegate.h"
#include "model/ParameterModel.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFile>
#include <QIcon>
#include <QLabel>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

namespace DriveDesk {

namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
const QString kBrowserKey = QStringLiteral("window/browser");
// The icon built into the program (resources/), or the desktop theme's.
QIcon applicationIcon()
{
    QIcon icon;
    for (int size : { 16, 32, 48, 64, 128, 256 }) {
        const QString file = QStringLiteral(":/icons/drivedesk-%1.png").arg(size);
        if (QFile::exists(file))
            icon.addFile(file, QSize(size, size));
    }
    return icon.isNull() ? QIcon::fromTheme(QStringLiteral("drivedesk")) : icon;
}

} // namespace

MainWindow::MainWindow(Language language, QWidget *parent)
    : QMainWindow(parent)
    , m_language(language)
{
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(tr("DriveDesk"));
    setWindowIcon(applicationIcon());
    m_state = new DriveState(this);
    m_model = new ParameterModel(m_state, this);
    m_favourites = DriveFavourites(m_model);
    m_undoStack = new QUndoStack(this);
    m_browser = new ParameterBrowser(m_model);
    m_notice = new NoticeBar;

    auto *central = new QWidget;
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(4, 4, 4, 0);
    layout->addWidget(m_notice);
    layout->addWidget(m_browser, 1);
    setCentralWidget(central);

    createActions();
    createMenus();
    createToolBar();
    createStatusBar();
    m_features = makeWindowFeatures(*this);
    for (WindowFeature *feature : std::as_const(m_features))
        feature->setParent(this);
    finishMenus();
    addStatusWidget(m_stateLabel);

    // A feature reading the drive stops its reading on Cancel.
    connect(m_notice, &NoticeBar::cancelClicked, this, [this] {
        if (m_session && !isReadingDrive())
            m_session->cancelScan();
    });
    connect(m_notice, &NoticeBar::reconnectClicked, this, &MainWindow::reconnect);
    connect(m_notice, &NoticeBar::connectClicked, this, &MainWindow::openConnectionDialog);
    connect(m_browser->delegate(), &ParameterDelegate::editRefused, this,
            [this](const QModelIndex &, const QString &reason) { showMessage(reason); });
    connect(m_browser->view(), &ParameterView::editRefused, this, &MainWindow::showMessage);
    connect(m_model, &ParameterModel::favouritesChanged, this, [this] { m_favourites.save(); });
    // A file's title marks unsaved changes; undoing back to where it was saved clears the mark.
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (!m_filePath.isEmpty())
            setWindowModified(!clean);
    });
    connect(m_browser->view()->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &MainWindow::updateActions);
    connect(m_browser->view()->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &MainWindow::updateActions);

    restoreSettings();
    m_notice->showInformation(
        tr("Not connected. Choose Connect... (%1) to reach a drive or the simulated one.")
            .arg(m_connectAction->shortcut().toString(QKeySequence::NativeText)));
    onStateChanged(DriveClient::State::Disconnected);
}

MainWindow::~MainWindow()
{
    // The session's client may still answer into the model: it goes before the model does.
    // The features go first: the children destroyed after this body still announce things
    // (the undo stack its clearing) that a feature would pass on to a frame half gone.
    qDeleteAll(m_features);
    m_features.clear();
    delete m_session;
    m_session = nullptr;
    // Children still talk while they are destroyed (the stack announces its clearing, an open
    // editor commits): nothing here is left to update.
    m_undoStack->disconnect(this);
    m_model->disconnect(this);
    m_browser->delegate()->disconnect(this);
    m_browser->view()->selectionModel()->disconnect(this);
}

bool MainWindow::isReady() const
{
    return m_session && m_session->isReady();
}

ParameterEditing *MainWindow::editing() const
{
    for (WindowFeature *feature : m_features) {
        if (ParameterEditing *editing = feature->editing())
            return editing;
    }
    return nullptr;
}

void MainWindow::connectTo(ConnectionSettings settings)
{
    if (!m_filePath.isEmpty()) {
        // One thing at a time: the file goes (asked about if it was changed), then the drive
        // comes.
        settleFeatures(WindowFeature::Leaving::Shown, [this, settings] {
            closeParameterFile();
            connectTo(settings);
        });
        return;
    }
    settings.language = m_language;
    m_nextSettings = settings;
    const DriveClient::State state = m_session ? m_session->state() : DriveClient::State::Lost;
    if (state == DriveClient::State::Connected || state == DriveClient::State::Connecting) {
        // A device server may serve one connection at a time: the old link is closed first,
        // and the new one opened once the client reports it closed (onStateChanged).
        m_notice->showProgress(tr("Closing the connection to %1...")
                                   .arg(RecentConnections::describe(m_session->settings())),
                               0, 0);
        m_session->disconnectFromDrive();
        return;
    }
    openNextSession();
}

void MainWindow::openNextSession()
{
    if (!m_nextSettings)
        return;
    const ConnectionSettings settings = *m_nextSettings;
    m_nextSettings.reset();
    closeSession();
    // The model keeps what was read until the new drive is connected.

    m_session = new DriveSession(settings, m_state, this);
    DriveSession *session = m_session;
    DriveClient *client = session->client();
    connect(client, &DriveClient::stateChanged, this, &MainWindow::onStateChanged);
    connect(session, &DriveSession::connected, this, [this, session] {
        RecentConnections::remember(session->settings());
        if (!session->hasDescription()) {
            // Another drive, or the same one anew: what the last one showed goes now.
            m_model->state()->clear();
            m_favourites.forget();
            setWindowTitle(tr("DriveDesk"));
            m_notice->showProgress(tr("Connected. Reading the drive..."), 0, 0);
            return;
        }
        m_notice->hide();
        if (!session->incompleteReason().isEmpty()) {
            // The session reads the drive anew; its progress takes the notice bar.
            showMessage(tr("Reconnected to %1; the drive was read only in part: reading it again.")
                            .arg(RecentConnections::describe(session->settings())));
            return;
        }
        // Back after a lost link: the table stays, its values are read again.
        showMessage(tr("Reconnected to %1; reading the values again.")
                        .arg(RecentConnections::describe(session->settings())));
    });
    connect(client, &DriveClient::connectionFailed, this, &MainWindow::onConnectionFailed);
    connect(client, &DriveClient::linkLost, this, &MainWindow::onLinkLost);
    connect(client, &DriveClient::driveSilentChanged, this, &MainWindow::onDriveSilentChanged);
    connect(session, &DriveSession::scanStarted, this, [this] {
        m_notice->showProgress(tr("Reading the drive..."), 0, 1000);
        m_browser->setEmptyText(tr("Reading the drive..."));
        updateActions();
    });
    connect(session, &DriveSession::scanProgress, this, &MainWindow::onScanProgress);
    connect(session, &DriveSession::described, this, &MainWindow::onDescribed);
    connect(session, &DriveSession::scanFinished, this, &MainWindow::onScanFinished);
    connect(session, &DriveSession::scanDiscarded, this, [this, session](const QString &reason) {
        // What the re-read found so far is dropped: the table keeps the complete reading before.
        // A re-read stopped by a lost link still offers Reconnect.
        m_notice->showInformation(
            tr("Reading the drive again stopped (%1). The table keeps what was read before: "
               "every parameter with its limits, units and texts, and the values as last read.")
                .arg(reason),
            session->state() != DriveClient::State::Connected);
        showMessage(tr("Reading the drive again stopped: %1").arg(reason));
        updateActions();
    });
    for (WindowFeature *feature : std::as_const(m_features))
        feature->attach(session);

    m_browser->setEmptyText(tr("Connecting..."));
    m_notice->showProgress(tr("Connecting to %1...").arg(RecentConnections::describe(settings)), 0,
                           0);
    session->start();
    updateActions();
}

void MainWindow::closeSession()
{
    if (!m_session)
        return;
    for (WindowFeature *feature : std::as_const(m_features))
        feature->attach(nullptr);
    // The undo history holds the old session's writes.
    m_undoStack->clear();
    delete m_session;
    m_session = nullptr;
}

void MainWindow::showMessage(const QString &text)
{
    statusBar()->showMessage(text);
}

void MainWindow::withdrawMessage(const QString &text)
{
    if (!text.isEmpty() && statusBar()->currentMessage() == text)
        statusBar()->clearMessage();
}

void MainWindow::reconnect()
{
    if (!m_session) {
        openConnectionDialog();
        return;
    }
    m_notice->showProgress(
        tr("Connecting to %1...").arg(RecentConnections::describe(m_session->settings())), 0, 0);
    m_session->reconnect();
}

void MainWindow::disconnectFromDrive()
{
    if (!m_session)
        return;
    m_session->disconnectFromDrive();
    m_notice->showInformation(tr("Disconnected from %1. What was read stays shown.")
                                  .arg(RecentConnections::describe(m_session->settings())),
                              true);
    updateActions();
}

void MainWindow::refresh()
{
    if (m_session)
        m_session->readValuesAgain();
}

bool MainWindow::isReadingDrive() const
{
    return std::any_of(m_features.cbegin(), m_features.cend(),
                       [](const WindowFeature *feature) { return feature->isReadingDrive(); });
}

void MainWindow::restoreSettings()
{
    QSettings settings;
    if (!restoreGeometry(settings.value(kGeometryKey).toByteArray()))
        resize(1300, 820);
    restoreState(settings.value(kStateKey).toByteArray());
    m_browser->restoreState(settings.value(kBrowserKey).toByteArray());
}

void MainWindow::saveSettings()
{
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    settings.setValue(kBrowserKey, m_browser->saveState());
    for (WindowFeature *feature : std::as_const(m_features))
        feature->saveSettings();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (holdsUnsavedWork() && !m_closeAnyway) {
        event->ignore();
        settleFeatures(WindowFeature::Leaving::Window, [this] {
            m_closeAnyway = true;
            close();
        });
        return;
    }
    saveSettings();
    m_favourites.save();
    QMainWindow::closeEvent(event);
}

} // namespace DriveDesk
