#pragma once

#include "bus/SimulatedBus.h"
#include "bus/SimulatorServer.h"
#include "frame/DriveSession.h"
#include "frame/NoticeBar.h"
#include "frame/ParameterBrowser.h"
#include "frame/ParameterView.h"
#include "main/MainWindow.h"
#include "model/ParameterFilterModel.h"
#include "model/ParameterModel.h"
#include "transfer/SaveDriveFeature.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QPointer>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <QTreeView>

// What the main window tests share: settings of their own, the simulated F5 and waiting for
// the window to have read it.
namespace DriveDesk::MainWindowTest {

constexpr int kWaitMs = 20000;

// Parameters of the simulated F5 (core/sim/data/sim_f5_parameters.csv) the tests rely on.
constexpr quint16 kInverterState = 0x0200; // ru.00, read-only
constexpr quint16 kDemoPeriod = 0x0305; // op.05, one value, 4.0..600.0 s, default 20.0
constexpr quint16 kFixedSpeed1 = 0x0314; // op.20, -4000..4000 rpm, default 100, 8 sets
constexpr quint16 kPassword = 0x0801; // ud.01
constexpr int kSimulatedGroups = 16;
constexpr int kSimulatedParameters = 206;

// QSettings in a directory of the test's own, removed afterwards.
class IsolatedSettings
{
public:
    IsolatedSettings()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("DriveDesk"));
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_dir.path());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        // The metadata cache as well: each test starts with none.
        qputenv("XDG_CACHE_HOME", cacheHome().toLocal8Bit());
    }
    void clear()
    {
        QSettings().clear();
        QDir(cacheHome()).removeRecursively();
    }
    QString cacheHome() const { return m_dir.filePath(QStringLiteral("cache")); }

private:
    QTemporaryDir m_dir;
};

// The simulated drive behind a TCP port, served from a thread of its own: QTRY_ waits in
// steps of 10 ms, which would otherwise be the pace of every answer.
class ServedDrive
{
public:
    ServedDrive(Protocol protocol, const SimulationOptions &options)
        : m_protocol(protocol)
    {
        m_context.moveToThread(&m_thread);
        m_thread.start();
        // Made in its thread, so that its timers and sockets belong there.
        QMetaObject::invokeMethod(
            &m_context, [&] { m_server = new SimulatorServer(protocol, options); },
            Qt::BlockingQueuedConnection);
    }
    ~ServedDrive()
    {
        QMetaObject::invokeMethod(
            m_server, [this] { delete m_server; }, Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    }

    // Port 0 picks a free one.
    bool listen(quint16 port, QString *error)
    {
        bool ok = false;
        QMetaObject::invokeMethod(
            m_server,
            [&] {
                ok = m_server->listenTcp(QStringLiteral("127.0.0.1"), port, error);
                m_port = m_server->tcpPort();
            },
            Qt::BlockingQueuedConnection);
        return ok;
    }
    void close()
    {
        QMetaObject::invokeMethod(
            m_server, [this] { m_server->close(); }, Qt::BlockingQueuedConnection);
    }
    // Freezes the drives (the connection stays open, nothing is answered) or thaws them.
    void setSilent(bool silent)
    {
        QMetaObject::invokeMethod(
            m_server, [this, silent] { m_server->bus().setSilent(silent); },
            Qt::BlockingQueuedConnection);
    }
    quint16 port() const { return m_port; }
    Protocol protocol() const { return m_protocol; }
    ConnectionSettings settings(Protocol protocol) const
    {
        ConnectionSettings settings;
        settings.parseTarget(QStringLiteral("tcp:127.0.0.1:%1").arg(m_port), nullptr);
        settings.protocol = protocol;
        return settings;
    }

private:
    Protocol m_protocol;
    QThread m_thread;
    QObject m_context; // runs the server's calls in m_thread
    SimulatorServer *m_server = nullptr; // lives in m_thread
    quint16 m_port = 0;
};

inline ConnectionSettings simulated(Protocol protocol = Protocol::Hsp5)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.protocol = protocol;
    settings.simulation.replyLatencyUs = 0;
    return settings;
}

// Connects and waits until the scan filled the model and the level and sets were read.
inline bool connectAndRead(MainWindow &window, const ConnectionSettings &settings)
{
    // A session still connected closes its link first: the new one is ready when it is gone.
    const QPointer<DriveSession> old = window.session();
    window.connectTo(settings);
    return QTest::qWaitFor([&window, old] { return old.isNull() && window.isReady(); }, kWaitMs);
}

// A drive that answers at once, for a ServedDrive a test freezes, closes or takes away while
// the window is connected to it.
inline SimulationOptions answeringAtOnce()
{
    SimulationOptions options;
    options.replyLatencyUs = 0;
    return options;
}

// Serves `server` on a free loopback port and connects `window` to it, the drive read. Empty
// when that worked; otherwise what failed (the listen's error, or the window's notice).
inline QString serveAndConnect(MainWindow &window, ServedDrive &server)
{
    QString error;
    if (!server.listen(0, &error))
        return error.isEmpty() ? QStringLiteral("cannot listen") : error;
    if (!connectAndRead(window, server.settings(server.protocol())))
        return QStringLiteral("not read: %1").arg(window.noticeBar()->text());
    return {};
}

template<typename T> bool waitFinished(const QFuture<T> &future)
{
    return QTest::qWaitFor([&future] { return future.isFinished(); }, kWaitMs);
}

// File > Save Drive to File once chosen: the drive is read afresh, then saved. True once the
// read ended and a file is at `path`.
inline bool saveDriveAndWait(MainWindow &window, const QString &path)
{
    auto *feature = window.findChild<SaveDriveFeature *>();
    return feature && feature->saveDriveToFile(path)
        && QTest::qWaitFor([feature] { return !feature->isSavingDrive(); }, kWaitMs)
        && QFileInfo::exists(path);
}

// What the drive holds, read past the window.
inline std::optional<qint32> driveValue(DriveClient *client, quint16 address, int set = 0)
{
    const QFuture<Reply> future = client->readValue(address, quint8(1u << set));
    if (!waitFinished(future) || future.resultCount() == 0)
        return std::nullopt;
    const Reply reply = future.result(); // kept: data() points into it
    if (const auto *value = reply.data<ParameterValue>())
        return value->value;
    return std::nullopt;
}

// The table's index of a value cell (through the filter model).
inline QModelIndex viewIndex(MainWindow &window, quint16 address, int set = 0)
{
    return window.browser()->filterModel()->mapFromSource(window.model()->valueIndex(address, set));
}

// The source-model addresses of the parameter rows the table shows now.
inline QList<quint16> shownAddresses(MainWindow &window)
{
    const QTreeView *view = window.browser()->view();
    const QAbstractItemModel *model = view->model();
    QList<quint16> addresses;
    const auto collect = [&](const QModelIndex &parent) {
        for (int row = 0; row < model->rowCount(parent); ++row) {
            if (view->isRowHidden(row, parent))
                continue;
            addresses
                << model->index(row, 0, parent).data(ParameterModel::AddressRole).value<quint16>();
        }
    };
    const QModelIndex root = view->rootIndex();
    if (root.isValid()) {
        collect(root);
    } else {
        for (int group = 0; group < model->rowCount(); ++group)
            collect(model->index(group, 0));
    }
    return addresses;
}

// The row of the group list whose text starts so ("op  ", "All parameters").
inline QModelIndex groupItem(MainWindow &window, const QString &text)
{
    const QAbstractItemModel *groups = window.browser()->groupTree()->model();
    const QModelIndexList rows = groups->match(groups->index(0, 0), Qt::DisplayRole, text, 1,
                                               Qt::MatchStartsWith);
    return rows.isEmpty() ? QModelIndex() : rows.constFirst();
}

} // namespace DriveDesk::MainWindowTest
