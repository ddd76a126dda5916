#pragma once

#include "ConnectionSettings.h"
#include "Link.h"

#include <QSerialPort>

namespace DriveDesk {

// A drive on a local serial port (RS232/RS485 adapter), in the protocol's character format.
// Any port error reports failed() at once and closes the port.
class SerialLink : public Link
{
    Q_OBJECT
public:
    explicit SerialLink(const ConnectionSettings &settings, QObject *parent = nullptr);
    ~SerialLink() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    void send(const QByteArray &bytes) override;
    QString description() const override;

private:
    void onErrorOccurred(QSerialPort::SerialPortError error);
    void onReadyRead();
    void fail(const QString &reason);

    ConnectionSettings m_settings;
    QSerialPort *m_port = nullptr;
    // Counts open() calls, so that a queued outcome of an abandoned attempt is not reported.
    quint64 m_attempt = 0;
    bool m_open = false;
};

// "8E1", "7E1", "8N2": data bits, parity letter, stop bits.
QString characterFormatName(QSerialPort::DataBits dataBits, QSerialPort::Parity parity,
                            QSerialPort::StopBits stopBits);

} // namespace DriveDesk
