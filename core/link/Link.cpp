#include "Link.h"

#include <QIODevice>
#include <QTimer>

namespace DriveDesk {

void Link::open()
{
    close();
    m_state = State::Opening;
    openTransport();
}

void Link::close()
{
    ++m_attempt;
    // Closed before the transport stops, so that what the transport signals meanwhile is
    // ignored.
    m_state = State::Closed;
    closeTransport();
}

void Link::send(const QByteArray &bytes)
{
    if (m_state != State::Open) {
        qWarning("DriveDesk: %d bytes not sent: %s is not open", int(bytes.size()),
                 qPrintable(description()));
        return;
    }
    transmit(bytes);
}

void Link::readWaiting()
{
    if (m_state == State::Open)
        pollTransport();
}

void Link::reportOpened()
{
    if (m_state != State::Opening)
        return;
    m_state = State::Open;
    emit opened();
}

void Link::reportOutcomeLater(const QString &failure)
{
    QTimer::singleShot(0, this, [this, attempt = m_attempt, failure] {
        if (attempt != m_attempt || m_state != State::Opening)
            return;
        if (failure.isEmpty())
            reportOpened();
        else
            fail(failure);
    });
}

void Link::fail(const QString &reason)
{
    if (m_state == State::Closed)
        return;
    const QString message = QStringLiteral("%1: %2").arg(description(), reason);
    close();
    emit failed(message);
}

void Link::handOn(const QByteArray &bytes)
{
    if (m_state == State::Open && !bytes.isEmpty())
        emit received(bytes);
}

void Link::handOnReceived(QIODevice *device)
{
    connect(device, &QIODevice::readyRead, this, [this, device] { handOn(device->readAll()); });
}

void Link::handOnLineError(const QString &reason)
{
    if (m_state == State::Open)
        emit lineError(reason);
}

} // namespace DriveDesk
