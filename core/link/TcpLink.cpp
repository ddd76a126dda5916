#include "TcpLink.h"

#include <QTcpSocket>

namespace DriveDesk {

namespace {
constexpr int kDefaultConnectTimeoutMs = 5000;
}

TcpLink::TcpLink(const ConnectionSettings &settings, QObject *parent)
    : Link(parent)
    , m_settings(settings)
    , m_socket(new QTcpSocket(this))
{
    m_connectTimeout.setSingleShot(true);
    m_connectTimeout.setInterval(kDefaultConnectTimeoutMs);
    connect(&m_connectTimeout, &QTimer::timeout, this, [this] {
        fail(tr("no answer from the device server within %1 ms").arg(m_connectTimeout.interval()));
    });
    connect(m_socket, &QTcpSocket::connected, this, &TcpLink::onConnected);
    connect(m_socket, &QTcpSocket::disconnected, this, &TcpLink::onDisconnected);
    connect(m_socket, &QTcpSocket::errorOccurred, this, &TcpLink::onErrorOccurred);
    connect(m_socket, &QTcpSocket::readyRead, this, &TcpLink::onReadyRead);
}

TcpLink::~TcpLink()
{
    m_state = State::Closed;
    m_socket->disconnect(this);
    m_socket->abort();
}

void TcpLink::open()
{
    close();
    if (m_settings.host.isEmpty() || m_settings.port == 0) {
        // Reported from the event loop like every other outcome of open().
        m_state = State::Connecting;
        const quint64 attempt = m_attempt;
        QTimer::singleShot(0, this, [this, attempt] {
            if (attempt == m_attempt && m_state == State::Connecting)
                fail(tr("no host or port given"));
        });
        return;
    }
    m_state = State::Connecting;
    m_connectTimeout.start();
    m_socket->connectToHost(m_settings.host, m_settings.port);
}

void TcpLink::close()
{
    ++m_attempt;
    m_state = State::Closed;
    m_connectTimeout.stop();
    m_socket->abort();
}

bool TcpLink::isOpen() const
{
    return m_state == State::Open;
}

void TcpLink::send(const QByteArray &bytes)
{
    if (m_state != State::Open) {
        qWarning("DriveDesk: %d bytes not sent: %s is not open", int(bytes.size()),
                 qPrintable(description()));
        return;
    }
    if (m_socket->write(bytes) != bytes.size())
        fail(tr("writing failed (%1)").arg(m_socket->errorString()));
}

QString TcpLink::description() const
{
    if (m_settings.host.contains(QLatin1Char(':')))
        return QStringLiteral("tcp [%1]:%2").arg(m_settings.host).arg(m_settings.port);
    return QStringLiteral("tcp %1:%2").arg(m_settings.host).arg(m_settings.port);
}

void TcpLink::onConnected()
{
    if (m_state != State::Connecting)
        return;
    m_connectTimeout.stop();
    // Telegrams are small and latency-bound.
    m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_state = State::Open;
    emit opened();
}

void TcpLink::onDisconnected()
{
    if (m_state == State::Closed)
        return;
    fail(tr("the device server closed the connection"));
}

void TcpLink::onErrorOccurred(QAbstractSocket::SocketError error)
{
    if (m_state == State::Closed)
        return;
    if (error == QAbstractSocket::RemoteHostClosedError) {
        fail(tr("the device server closed the connection"));
        return;
    }
    fail(m_socket->errorString());
}

void TcpLink::onReadyRead()
{
    const QByteArray bytes = m_socket->readAll();
    if (m_state == State::Open && !bytes.isEmpty())
        emit received(bytes);
}

void TcpLink::fail(const QString &reason)
{
    const QString message = QStringLiteral("%1: %2").arg(description(), reason);
    close();
    emit failed(message);
}

} // namespace DriveDesk
