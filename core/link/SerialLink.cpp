#include "SerialLink.h"

#include <QTimer>

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
    connect(m_port, &QSerialPort::readyRead, this, &SerialLink::onReadyRead);
}

SerialLink::~SerialLink()
{
    m_open = false;
    m_port->disconnect(this);
    m_port->close();
}

void SerialLink::open()
{
    close();
    const quint64 attempt = ++m_attempt;
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
        reason = explain(m_port->error()) + QStringLiteral(" (%1)").arg(m_port->errorString());
    else
        m_port->clear();

    // The outcome is reported from the event loop, as for the links that open asynchronously.
    QTimer::singleShot(0, this, [this, attempt, reason] {
        if (attempt != m_attempt)
            return;
        if (!reason.isEmpty()) {
            fail(reason);
            return;
        }
        if (m_port->isOpen()) {
            m_open = true;
            emit opened();
        }
    });
}

void SerialLink::close()
{
    ++m_attempt;
    m_open = false;
    if (m_port->isOpen())
        m_port->close();
    m_port->clearError();
}

bool SerialLink::isOpen() const
{
    return m_open;
}

void SerialLink::send(const QByteArray &bytes)
{
    if (!m_open) {
        qWarning("DriveDesk: %d bytes not sent: %s is not open", int(bytes.size()),
                 qPrintable(description()));
        return;
    }
    if (m_port->write(bytes) != bytes.size())
        fail(explain(QSerialPort::WriteError) + QStringLiteral(" (%1)").arg(m_port->errorString()));
}

QString SerialLink::description() const
{
    return QStringLiteral("serial %1 %2 %3")
        .arg(m_settings.device)
        .arg(m_settings.baudRate)
        .arg(characterFormatName(m_settings.effectiveDataBits(), m_settings.effectiveParity(),
                                 m_settings.effectiveStopBits()));
}

void SerialLink::onErrorOccurred(QSerialPort::SerialPortError error)
{
    if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError)
        return;
    // Errors while opening are reported by open() itself.
    if (!m_open)
        return;
    fail(explain(error) + QStringLiteral(" (%1)").arg(m_port->errorString()));
}

void SerialLink::onReadyRead()
{
    const QByteArray bytes = m_port->readAll();
    if (m_open && !bytes.isEmpty())
        emit received(bytes);
}

void SerialLink::fail(const QString &reason)
{
    const QString message = QStringLiteral("%1: %2").arg(description(), reason);
    close();
    emit failed(message);
}

} // namespace DriveDesk
