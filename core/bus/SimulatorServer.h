#pragma once

#include "link/ConnectionSettings.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

#include <memory>

class QTcpServer;
class QTcpSocket;

namespace DriveDesk {

class BusClock;
class PseudoTerminal;
class SimulatedBus;

// Serves simulated drives to other programs: over TCP like a serial device server (one
// connection at a time; a second one is closed at once) and over a pseudo-terminal that opens
// like a serial port. The drives keep their state across connections. Answers go back the way
// the last request came.
class SimulatorServer : public QObject
{
    Q_OBJECT
public:
    SimulatorServer(Protocol protocol, const SimulationOptions &options, QObject *parent = nullptr);
    ~SimulatorServer() override;

    // host: an IP address, "localhost" or "*" (any); port 0 picks a free one.
    bool listenTcp(const QString &host, quint16 port, QString *error);
    bool listenPty(const QString &linkPath, QString *error);
    // Stops serving; removes the pseudo-terminal link.
    void close();

    // Where it listens: "tcp:127.0.0.1:5020", "pty:/tmp/drive".
    QStringList addresses() const;
    quint16 tcpPort() const;
    QString ptyDevice() const; // the slave device the link points at, e.g. /dev/pts/4
    bool hasClient() const { return !m_client.isNull(); }

    SimulatedBus &bus() { return *m_bus; }
    // Bytes that came over the pty while its line was set to another rate than the drive's
    // (SimulationOptions::baudRate): a drive never hears them.
    qint64 ignoredAtOtherRates() const { return m_ignoredAtOtherRates; }

signals:
    void clientConnected(const QString &peer);
    void clientDisconnected(const QString &peer);
    void connectionRefused(const QString &peer);
    // The pseudo-terminal broke; the server no longer serves it.
    void failed(const QString &reason);

private:
    enum class Route : quint8 { Tcp, Pty };

    // How long a new connection waits for the one served to close before it is refused.
    static constexpr int kHandOverMs = 500;

    void acceptConnections();
    void take(QTcpSocket *socket);
    void refuse(QTcpSocket *socket);
    void dropClient();
    void fromOperator(Route route, const QByteArray &bytes);
    void toOperator(const QByteArray &bytes);
    bool atDrivesRate() const;

    std::unique_ptr<SimulatedBus> m_bus;
    BusClock *m_clock = nullptr;
    QTcpServer *m_server = nullptr;
    QPointer<QTcpSocket> m_client;
    QString m_clientPeer;
    QPointer<QTcpSocket> m_waiting; // a new connection waiting for m_client to close
    PseudoTerminal *m_pty = nullptr;
    Route m_route = Route::Tcp;
    qint64 m_ignoredAtOtherRates = 0;
};

} // namespace DriveDesk
