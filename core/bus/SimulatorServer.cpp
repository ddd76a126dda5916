#include "SimulatorServer.h"

#include "BusClock.h"
#include "PseudoTerminal.h"
#include "SimulatedBus.h"

#include <QHostAddress>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

namespace DriveDesk {

namespace {

QString peerName(const QTcpSocket *socket)
{
    return QStringLiteral("%1:%2").arg(socket->peerAddress().toString()).arg(socket->peerPort());
}

} // namespace

SimulatorServer::SimulatorServer(Protocol protocol, const SimulationOptions &options,
                                 QObject *parent)
    : QObject(parent)
    , m_bus(std::make_unique<SimulatedBus>(protocol, options))
    , m_clock(new BusClock(m_bus.get(), this))
    , m_server(new QTcpServer(this))
    , m_pty(new PseudoTerminal(this))
{
    connect(m_clock, &BusClock::transmit, this, &SimulatorServer::toOperator);
    connect(m_server, &QTcpServer::newConnection, this, &SimulatorServer::acceptConnections);
    connect(m_pty, &PseudoTerminal::received, this,
            [this](const QByteArray &bytes) { fromOperator(Route::Pty, bytes); });
    connect(m_pty, &PseudoTerminal::failed, this, &SimulatorServer::failed);
}

SimulatorServer::~SimulatorServer()
{
    close();
    // The clock refers to the bus: it goes first.
    delete m_clock;
}

bool SimulatorServer::listenTcp(const QString &host, quint16 port, QString *error)
{
    QHostAddress address;
    if (host == QLatin1String("*"))
        address = QHostAddress::Any;
    else if (host.compare(QLatin1String("localhost"), Qt::CaseInsensitive) == 0)
        address = QHostAddress::LocalHost;
    else if (!address.setAddress(host)) {
        if (error)
            *error = tr("\"%1\" is not an IP address to listen on (give e.g. 127.0.0.1, "
                        "localhost or *)").arg(host);
        return false;
    }
    if (!m_server->listen(address, port)) {
        if (error)
            *error = tr("cannot listen on %1:%2: %3")
                         .arg(host)
                         .arg(port)
                         .arg(m_server->errorString());
        return false;
    }
    return true;
}

bool SimulatorServer::listenPty(const QString &linkPath, QString *error)
{
    return m_pty->open(linkPath, error);
}

void SimulatorServer::close()
{
    m_server->close();
    if (QTcpSocket *waiting = m_waiting) {
        m_waiting = nullptr;
        waiting->abort();
        waiting->deleteLater();
    }
    dropClient();
    m_pty->close();
    m_clock->resetLine();
}

QStringList SimulatorServer::addresses() const
{
    QStringList list;
    if (m_server->isListening()) {
        const QHostAddress address = m_server->serverAddress();
        const QString host = address.protocol() == QAbstractSocket::IPv6Protocol
                                 ? QStringLiteral("[%1]").arg(address.toString())
                                 : address.toString();
        list.append(QStringLiteral("tcp:%1:%2").arg(host).arg(m_server->serverPort()));
    }
    if (m_pty->isOpen())
        list.append(QStringLiteral("pty:") + m_pty->linkPath());
    return list;
}

quint16 SimulatorServer::tcpPort() const
{
    return m_server->isListening() ? m_server->serverPort() : 0;
}

QString SimulatorServer::ptyDevice() const
{
    return m_pty->devicePath();
}

void SimulatorServer::acceptConnections()
{
    while (QTcpSocket *socket = m_server->nextPendingConnection()) {
        if (!m_client) {
            take(socket);
            continue;
        }
        if (m_waiting) {
            refuse(socket);
            continue;
        }
        // An operator that closed its connection and opened a new one at once: the close and
        // the new connection reach this event loop in either order. The newcomer waits a moment
        // for the one served to go; one still there then keeps the bus.
        m_waiting = socket;
        QTimer::singleShot(kHandOverMs, this, [this, socket] {
            if (m_waiting == socket) {
                m_waiting = nullptr;
                refuse(socket);
            }
        });
    }
}

void SimulatorServer::refuse(QTcpSocket *socket)
{
    // One operator per bus, as on a serial line: tell the second one by closing.
    const QString peer = peerName(socket);
    qInfo("simulated drives: refused a connection from %s: already serving %s",
          qPrintable(peer), qPrintable(m_clientPeer));
    connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    socket->disconnectFromHost();
    emit connectionRefused(peer);
}

void SimulatorServer::take(QTcpSocket *socket)
{
    m_client = socket;
    m_clientPeer = peerName(socket);
    socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    connect(socket, &QTcpSocket::readyRead, this,
            [this, socket] { fromOperator(Route::Tcp, socket->readAll()); });
    connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
        if (socket == m_client)
            dropClient();
    });
    // A new operator starts on a quiet line; what it sent while it waited is its first word.
    m_clock->resetLine();
    emit clientConnected(m_clientPeer);
    if (socket->bytesAvailable() > 0)
        fromOperator(Route::Tcp, socket->readAll());
}

void SimulatorServer::dropClient()
{
    if (!m_client)
        return;
    QTcpSocket *socket = m_client;
    const QString peer = m_clientPeer;
    m_client = nullptr;
    m_clientPeer.clear();
    socket->disconnect(this);
    socket->abort();
    socket->deleteLater();
    m_clock->resetLine();
    emit clientDisconnected(peer);
    if (QTcpSocket *next = m_waiting) {
        m_waiting = nullptr;
        if (next->state() == QAbstractSocket::ConnectedState)
            take(next);
        else
            next->deleteLater();
    }
}

void SimulatorServer::fromOperator(Route route, const QByteArray &bytes)
{
    if (bytes.isEmpty())
        return;
    // A drive on a serial line hears only what comes at its own rate; anything else is noise
    // it cannot frame. A pty carries the rate the operator's port was set to, not the timing.
    if (route == Route::Pty && !atDrivesRate()) {
        m_ignoredAtOtherRates += bytes.size();
        return;
    }
    m_route = route;
    m_clock->receive(bytes);
}

bool SimulatorServer::atDrivesRate() const
{
    const qint32 rate = m_pty->lineBaudRate();
    return rate == 0 || rate == m_bus->options().baudRate;
}

// A socket or pty cannot carry the UART's error flags: a flagged character is just missing.
void SimulatorServer::toOperator(const QByteArray &bytes)
{
    if (m_route == Route::Tcp && m_client)
        m_client->write(bytes);
    else if (m_route == Route::Pty && m_pty->isOpen())
        m_pty->write(bytes);
}

} // namespace DriveDesk
