#include "MainWindow.h"

#include "parameters/DriveIdentity.h"

#include "DriveSession.h"
#include "NoticeBar.h"
#include "ParameterBrowser.h"
#include "ParameterView.h"
#include "RecentConnections.h"
#include "WindowFeatures.h"

#include "delegate/ParameterDelegate.h"
#include "edit/DocumentEditor.h"
#include "edit/EditController.h"
#include "model/ParameterModel.h"
#include "session/UploadRun.h"

#include <QAction>
#include <QCloseEvent>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDockWidget>
#include <QFile>
#include <QIcon>
#include <QLabel>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
const QString kBrowserKey = QStringLiteral("window/browser");
const QString kFavouritesGroup = QStringLiteral("favourites");

// Favourites belong to a drive: its identification and serial number (In.10) where it has
// them, otherwise where it was reached. A parameter file of the drive shares its favourites;
// one without an identification (`settings` nullptr) has none remembered.
QString favouritesKey(const DriveDescription &drive, const ConnectionSettings *settings)
{
    QString identity = DriveIdentity::summary(drive);
    if (const GroupDescription *info = drive.findGroup(QStringLiteral("In"))) {
        if (const ParameterDescription *serial = drive.find(quint16(info->address + 10))) {
            if (serial->values[0])
                identity += QStringLiteral("/serial %1").arg(*serial->values[0]);
        }
    }
    if (identity.isEmpty() && !settings)
        return {};
    if (identity.isEmpty())
        identity = QStringLiteral("%1/%2").arg(settings->target()).arg(settings->driveAddress);
    return QString::fromLatin1(
        QCryptographicHash::hash(identity.toUtf8(), QCryptographicHash::Sha1).toHex().left(16));
}

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
    m_model = new ParameterModel(this);
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

    connect(m_notice, &NoticeBar::cancelClicked, this, [this] {
        if (m_upload)
            m_upload->cancel();
        else if (m_session)
            m_session->cancelScan();
    });
    connect(m_notice, &NoticeBar::reconnectClicked, this, &MainWindow::reconnect);
    connect(m_notice, &NoticeBar::connectClicked, this, &MainWindow::openConnectionDialog);
    connect(m_browser->delegate(), &ParameterDelegate::editRefused, this,
            [this](const QModelIndex &, const QString &reason) { showMessage(reason); });
    connect(m_browser->view(), &ParameterView::editRefused, this, &MainWindow::showMessage);
    connect(m_model, &ParameterModel::favouritesChanged, this, &MainWindow::saveFavourites);
    // A file's title marks unsaved changes; undoing back to where it was saved clears the mark.
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (m_document)
            setWindowModified(!clean);
    });
    connect(m_model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex &topLeft, const QModelIndex &bottomRight) {
                if (!m_session)
                    return;
                const auto address = topLeft.data(ParameterModel::AddressRole).value<quint16>();
                if (topLeft.row() != bottomRight.row() || address == m_session->activeSetAddress()
                    || address == m_session->setPointerAddress())
                    updateSetsLabel();
            });
    connect(m_model, &QAbstractItemModel::modelReset, this, &MainWindow::updateSetsLabel);
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
    delete m_document;
    m_document = nullptr;
    // Children still talk while they are destroyed (the stack announces its clearing, an open
    // editor commits): nothing here is left to update.
    m_undoStack->disconnect(this);
    m_model->disconnect(this);
    m_browser->delegate()->disconnect(this);
    m_browser->view()->selectionModel()->disconnect(this);
}

bool MainWindow::isReady() const
{
    return m_session && m_session->state() == DriveClient::State::Connected
        && m_session->hasDescription() && !m_session->isScanning();
}

ParameterEditing *MainWindow::editing() const
{
    if (m_document)
        return m_document;
    return isReady() ? m_session->editController() : nullptr;
}

void MainWindow::connectTo(ConnectionSettings settings)
{
    if (m_document) {
        // One thing at a time: the file goes (asked about if it was changed), then the drive
        // comes.
        settleUnsavedChanges([this, settings] {
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

    m_session = new DriveSession(settings, m_model, m_undoStack, this);
    DriveSession *session = m_session;
    connect(session, &DriveSession::stateChanged, this, &MainWindow::onStateChanged);
    connect(session, &DriveSession::connected, this, [this, session] {
        RecentConnections::remember(session->settings());
        if (!session->hasDescription()) {
            // Another drive, or the same one anew: what the last one showed goes now.
            m_model->clear();
            m_favouritesKey.clear();
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
    connect(session, &DriveSession::connectionFailed, this, &MainWindow::onConnectionFailed);
    connect(session, &DriveSession::linkLost, this, &MainWindow::onLinkLost);
    connect(session, &DriveSession::driveSilentChanged, this, &MainWindow::onDriveSilentChanged);
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
    connect(session, &DriveSession::message, this, &MainWindow::showMessage);
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

void MainWindow::onStateChanged(DriveClient::State state)
{
    QString text;
    switch (state) {
    case DriveClient::State::Disconnected:
        text = tr("Not connected");
        break;
    case DriveClient::State::Connecting:
        text = tr("Connecting...");
        break;
    case DriveClient::State::Connected:
        text = m_session->isDriveSilent()
                   ? tr("Connected: %1; the drive is not answering")
                         .arg(RecentConnections::describe(m_session->settings()))
                   : tr("Connected: %1").arg(RecentConnections::describe(m_session->settings()));
        break;
    case DriveClient::State::Lost:
        text = tr("Connection lost");
        break;
    }
    m_stateLabel->setText(text);
    updateActions();
    // connectTo() waits for the old link to close; the session may not go from inside its own
    // signal.
    if (m_nextSettings && state != DriveClient::State::Connected
        && state != DriveClient::State::Connecting)
        QMetaObject::invokeMethod(this, &MainWindow::openNextSession, Qt::QueuedConnection);
}

void MainWindow::onScanProgress(int value, int maximum, const QString &text)
{
    m_notice->showProgress(text.isEmpty() ? tr("Reading the drive...")
                                          : tr("Reading the drive: %1").arg(text),
                           value, maximum);
}

void MainWindow::onDescribed(const DriveDescription &drive)
{
    m_metadataLabel->setVisible(drive.metadataFromCache);
    if (!drive.warnings.isEmpty())
        m_notice->showInformation(drive.warnings.join(QLatin1Char('\n')));
    restoreFavourites(drive, &m_session->settings());
    const QString identity = DriveIdentity::summary(drive);
    const QString name
        = identity.isEmpty() ? RecentConnections::describe(m_session->settings()) : identity;
    setWindowTitle(tr("%1 - DriveDesk").arg(name));
}

void MainWindow::restoreFavourites(const DriveDescription &drive,
                                   const ConnectionSettings *settings)
{
    m_favouritesKey = favouritesKey(drive, settings);
    QSet<quint16> favourites;
    if (!m_favouritesKey.isEmpty()) {
        const QStringList stored = QSettings()
                                       .value(kFavouritesGroup + QLatin1Char('/') + m_favouritesKey)
                                       .toStringList();
        for (const QString &hex : stored) {
            bool ok = false;
            const uint address = hex.toUInt(&ok, 16);
            if (ok && address <= 0xFFFF && m_model->parameter(quint16(address)))
                favourites.insert(quint16(address));
        }
    }
    m_model->setFavourites(favourites);
}

void MainWindow::onScanFinished(const QString &problem)
{
    m_browser->setEmptyText(problem.isEmpty()
                                ? tr("The drive reported no parameters.")
                                : tr("Nothing was read from the drive: %1.").arg(problem));
    int parameters = 0;
    for (int group = 0; group < m_model->rowCount(); ++group)
        parameters += m_model->rowCount(m_model->index(group, 0));
    if (problem.isEmpty()) {
        m_notice->hide();
        // One sentence per count: the plural of each is its own.
        showMessage(tr("Read %n parameter(s).", nullptr, parameters) + QLatin1Char(' ')
                    + tr("The drive has %n group(s).", nullptr, m_model->rowCount()));
    } else if (m_model->rowCount() == 0) {
        m_notice->showInformation(
            tr("Nothing was read: %1. Press Refresh (%2) to read the drive.")
                .arg(problem, m_refreshAction->shortcut().toString(QKeySequence::NativeText)));
    } else {
        const QString shown = tr("the table shows the %n parameter(s) read", nullptr, parameters);
        m_notice->showProblem(tr("The drive was read only in part (%1): %2. Read it again with "
                                 "Drive > Read Metadata Again.")
                                  .arg(problem, shown));
        showMessage(tr("Incomplete: %1").arg(shown));
    }
    updateActions();
    emit driveRead();
}

void MainWindow::onLinkLost(const QString &reason)
{
    const QString text = tr("The connection to the drive was lost: %1. What was read stays "
                            "shown; editing is off until the drive is reconnected.")
                             .arg(reason);
    m_notice->showProblem(text);
    showMessage(tr("Connection lost: %1").arg(reason));
    updateActions();
}

void MainWindow::onDriveSilentChanged(bool silent)
{
    if (silent) {
        const QDateTime now = QDateTime::currentDateTime();
        m_model->setStaleSince(now.toMSecsSinceEpoch());
        m_silenceNotice
            = tr("The drive is not answering: the connection to %1 is open, but nothing came "
                 "from the drive since %2. The values shown are the last read and are marked "
                 "stale. This clears by itself when the drive answers again.")
                  .arg(RecentConnections::describe(m_session->settings()),
                       now.toString(QStringLiteral("HH:mm:ss")));
        m_notice->showProblem(m_silenceNotice);
        showMessage(tr("The drive is not answering"));
    } else {
        m_model->setStaleSince(0);
        if (!m_silenceNotice.isEmpty() && m_notice->isVisible()
            && m_notice->text() == m_silenceNotice) {
            m_notice->hide();
            if (m_session && m_session->state() == DriveClient::State::Connected)
                showMessage(tr("The drive answers again."));
        }
        m_silenceNotice.clear();
    }
    onStateChanged(m_session ? m_session->state() : DriveClient::State::Disconnected);
}

void MainWindow::onConnectionFailed(const QString &reason)
{
    m_browser->setEmptyText(tr("Could not connect: %1").arg(reason));
    const QString target = RecentConnections::describe(m_session->settings());
    // What an earlier connection read stays shown.
    m_notice->showProblem(m_model->rowCount() > 0
                              ? tr("Could not connect to %1: %2. What was shown before stays.")
                                    .arg(target, reason)
                              : tr("Could not connect to %1: %2").arg(target, reason));
    showMessage(tr("Could not connect: %1").arg(reason));
    updateActions();
}

void MainWindow::showMessage(const QString &text)
{
    statusBar()->showMessage(text);
}

void MainWindow::updateSetsLabel()
{
    const auto valueText = [this](std::optional<quint16> address) {
        if (!address)
            return QString();
        const std::optional<qint32> value = m_model->value(*address, 0);
        return value ? QString::number(*value) : tr("?");
    };
    // The table marks the active set's column, following every reading of Fr.02.
    m_model->setActiveSet(m_session ? m_session->activeSet() : -1);
    const QString active = m_session ? valueText(m_session->activeSetAddress()) : QString();
    const QString pointer = m_session ? valueText(m_session->setPointerAddress()) : QString();
    QStringList parts;
    if (!active.isEmpty())
        parts << tr("Active set: %1").arg(active);
    if (!pointer.isEmpty())
        parts << tr("Set pointer (Fr.09): %1").arg(pointer);
    m_setsLabel->setText(parts.join(QStringLiteral("   ")));
    m_setsLabel->setVisible(!parts.isEmpty());
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
    if (!m_session || m_session->state() != DriveClient::State::Connected)
        return;
    if (!m_session->hasDescription())
        m_session->rescan();
    else
        m_session->editController()->refresh();
}

void MainWindow::saveFavourites()
{
    if (m_favouritesKey.isEmpty())
        return;
    QStringList addresses;
    const QSet<quint16> favourites = m_model->favourites();
    for (quint16 address : favourites)
        addresses << QString::number(address, 16).rightJustified(4, QLatin1Char('0'));
    addresses.sort();
    QSettings settings;
    const QString key = kFavouritesGroup + QLatin1Char('/') + m_favouritesKey;
    if (addresses.isEmpty())
        settings.remove(key);
    else
        settings.setValue(key, addresses);
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
    if (hasUnsavedChanges() && !m_closeAnyway) {
        event->ignore();
        settleUnsavedChanges([this] {
            m_closeAnyway = true;
            close();
        });
        return;
    }
    saveSettings();
    saveFavourites();
    QMainWindow::closeEvent(event);
}

} // namespace DriveDesk
