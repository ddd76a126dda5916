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

    QString description() const override;

    // How long open() waits for the device server before giving up.
    void setConnectTimeoutMs(int ms) { m_connectTimeout.setInterval(ms); }
    int connectTimeoutMs() const { return m_connectTimeout.interval(); }

private:
    void openTransport() override;
    void closeTransport() override;
    void transmit(const QByteArray &bytes) override;
    void pollTransport() override;
    void onConnected();
    void onErrorOccurred(QAbstractSocket::SocketError error);

    ConnectionSettings m_settings;
    QTcpSocket *m_socket = nullptr;
    QTimer m_connectTimeout;
};

} // namespace DriveDesk
