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

    QString description() const override;

private:
    void openTransport() override;
    void closeTransport() override;
    void transmit(const QByteArray &bytes) override;
    void pollTransport() override;
    void onErrorOccurred(QSerialPort::SerialPortError error);
    // In words, with the system's own text.
    QString reasonFor(QSerialPort::SerialPortError error) const;

    ConnectionSettings m_settings;
    QSerialPort *m_port = nullptr;
};

// "8E1", "7E1", "8N2": data bits, parity letter, stop bits.
QString characterFormatName(QSerialPort::DataBits dataBits, QSerialPort::Parity parity,
                            QSerialPort::StopBits stopBits);

} // namespace DriveDesk
