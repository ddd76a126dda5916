#pragma once

#include "ConnectionSettings.h"
#include "Link.h"

#include <QAbstractSocket>
#include <QTimer>

class QTcpSocket;

namespace DriveDesk {

// A drive behind a serial device server: the TCP stream carries the raw bytes of the serial
// line. Refused or timed-out connections and a lost connection report failed() at once.
class TcpLink : public Link
{
    Q_OBJECT
public:
    explicit TcpLink(const ConnectionSettings &settings, QObject *parent = nullptr);
    ~TcpLink() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    void send(const QByteArray &bytes) override;
    QString description() const override;

    // How long open() waits for the device server before giving up.
    void setConnectTimeoutMs(int ms) { m_connectTimeout.setInterval(ms); }
    int connectTimeoutMs() const { return m_connectTimeout.interval(); }

private:
    enum class State : quint8 { Closed, Connecting, Open };

    void onConnected();
    void onDisconnected();
    void onErrorOccurred(QAbstractSocket::SocketError error);
    void onReadyRead();
    void fail(const QString &reason);

    ConnectionSettings m_settings;
    QTcpSocket *m_socket = nullptr;
    QTimer m_connectTimeout;
    State m_state = State::Closed;
    quint64 m_attempt = 0; // a queued outcome of an abandoned open() is not reported
};

} // namespace DriveDesk
