#include "SerialLink.h"

namespace DriveDesk {

namespace {

QString explain(QSerialPort::SerialPortError error)
{
    switch (error) {
    case QSerialPort::DeviceNotFoundError:
        return SerialLink::tr("no such serial device");
    case QSerialPort::PermissionError:
        return SerialLink::tr("permission denied (the port may be in use by another program, "
                              "or the user may lack access to it)");
    case QSerialPort::OpenError:
        return SerialLink::tr("the port is already open");
    case QSerialPort::ResourceError:
        return SerialLink::tr("the device is no longer available (adapter unplugged?)");
    case QSerialPort::ReadError:
        return SerialLink::tr("reading from the port failed");
    case QSerialPort::WriteError:
        return SerialLink::tr("writing to the port failed");
    case QSerialPort::UnsupportedOperationError:
        return SerialLink::tr("the port does not support these settings");
    case QSerialPort::NotOpenError:
        return SerialLink::tr("the port is not open");
    case QSerialPort::TimeoutError:
        return SerialLink::tr("timeout");
    case QSerialPort::UnknownError:
    case QSerialPort::NoError:
        break;
    }
    return SerialLink::tr("unknown serial port error");
}

} // namespace

QString characterFormatName(QSerialPort::DataBits dataBits, QSerialPort::Parity parity,
                            QSerialPort::StopBits stopBits)
{
    QChar parityLetter = QLatin1Char('?');
    switch (parity) {
    case QSerialPort::NoParity: parityLetter = QLatin1Char('N'); break;
    case QSerialPort::EvenParity: parityLetter = QLatin1Char('E'); break;
    case QSerialPort::OddParity: parityLetter = QLatin1Char('O'); break;
    case QSerialPort::SpaceParity: parityLetter = QLatin1Char('S'); break;
    case QSerialPort::MarkParity: parityLetter = QLatin1Char('M'); break;
    }
    QString stop;
    switch (stopBits) {
    case QSerialPort::OneStop: stop = QStringLiteral("1"); break;
    case QSerialPort::OneAndHalfStop: stop = QStringLiteral("1.5"); break;
    case QSerialPort::TwoStop: stop = QStringLiteral("2"); break;
    }
    return QString::number(int(dataBits)) + parityLetter + stop;
}

SerialLink::SerialLink(const ConnectionSettings &settings, QObject *parent)
    : Link(parent)
    , m_settings(settings)
    , m_port(new QSerialPort(this))
{
    connect(m_port, &QSerialPort::errorOccurred, this, &SerialLink::onErrorOccurred);
    handOnReceived(m_port);
}

void SerialLink::openTransport()
{
    m_port->setPortName(m_settings.device);
    m_port->setBaudRate(m_settings.baudRate);
    m_port->setDataBits(m_settings.effectiveDataBits());
    m_port->setParity(m_settings.effectiveParity());
    m_port->setStopBits(m_settings.effectiveStopBits());
    m_port->setFlowControl(QSerialPort::NoFlowControl);

    QString reason;
    if (m_settings.device.isEmpty())
        reason = tr("no serial device given");
    else if (!m_port->open(QIODevice::ReadWrite))
        reason = reasonFor(m_port->error());
    else
        m_port->clear();
    reportOutcomeLater(reason);
}

void SerialLink::closeTransport()
{
    if (m_port->isOpen())
        m_port->close();
    m_port->clearError();
}

void SerialLink::transmit(const QByteArray &bytes)
{
    if (m_port->write(bytes) != bytes.size())
        return fail(reasonFor(QSerialPort::WriteError));
    // Out now, not when the event loop next gets to it: the answer's deadline has started.
    m_port->flush();
}

void SerialLink::pollTransport()
{
    // A wait of 0 ms is a look, not a wait; its "timeout" is no error (onErrorOccurred).
    m_port->waitForReadyRead(0);
}

QString SerialLink::description() const
{
    return QStringLiteral("serial %1 %2 %3")
        .arg(m_settings.device)
        .arg(m_settings.baudRate)
        .arg(characterFormatName(m_settings.effectiveDataBits(), m_settings.effectiveParity(),
                                 m_settings.effectiveStopBits()));
}

QString SerialLink::reasonFor(QSerialPort::SerialPortError error) const
{
    return explain(error) + QStringLiteral(" (%1)").arg(m_port->errorString());
}

void SerialLink::onErrorOccurred(QSerialPort::SerialPortError error)
{
    if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError)
        return;
    // Errors while opening are reported by openTransport() itself.
    if (state() != State::Open)
        return;
    fail(reasonFor(error));
}

} // namespace DriveDesk
