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
    connect(m_socket, &QTcpSocket::disconnected, this,
            [this] { fail(tr("the device server closed the connection")); });
    connect(m_socket, &QTcpSocket::errorOccurred, this, &TcpLink::onErrorOccurred);
    handOnReceived(m_socket);
}

void TcpLink::openTransport()
{
    if (m_settings.host.isEmpty() || m_settings.port == 0) {
        reportOutcomeLater(tr("no host or port given"));
        return;
    }
    m_connectTimeout.start();
    m_socket->connectToHost(m_settings.host, m_settings.port);
}

void TcpLink::closeTransport()
{
    m_connectTimeout.stop();
    m_socket->abort();
}

void TcpLink::transmit(const QByteArray &bytes)
{
    if (m_socket->write(bytes) != bytes.size())
        return fail(tr("writing failed (%1)").arg(m_socket->errorString()));
    // Out now, not when the event loop next gets to it: the answer's deadline has started.
    m_socket->flush();
}

void TcpLink::pollTransport()
{
    m_socket->waitForReadyRead(0);
}

QString TcpLink::description() const
{
    if (m_settings.host.contains(QLatin1Char(':')))
        return QStringLiteral("tcp [%1]:%2").arg(m_settings.host).arg(m_settings.port);
    return QStringLiteral("tcp %1:%2").arg(m_settings.host).arg(m_settings.port);
}

void TcpLink::onConnected()
{
    if (state() != State::Opening)
        return;
    m_connectTimeout.stop();
    // Telegrams are small and latency-bound.
    m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    reportOpened();
}

void TcpLink::onErrorOccurred(QAbstractSocket::SocketError error)
{
    // A look at the socket (pollTransport) that found nothing is no failure.
    if (error == QAbstractSocket::SocketTimeoutError)
        return;
    if (error == QAbstractSocket::RemoteHostClosedError)
        fail(tr("the device server closed the connection"));
    else
        fail(m_socket->errorString());
}

} // namespace DriveDesk
