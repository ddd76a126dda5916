#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

class QIODevice;

namespace DriveDesk {

struct ConnectionSettings;

// The byte pipe to a drive: serial port, TCP socket to a serial device server, or the
// simulated drive in process. The client sees no difference between them: the open, closed
// and lost states, the failure texts and the hand-over of received bytes are this class's; a
// link adds only its transport.
// Thread: a link lives in the client's worker thread and is used only from there.
class Link : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    ~Link() override = default;

    // Starts opening; ends in opened() or failed(). Abandons any earlier attempt.
    void open();
    // Quiet: no signal, and no outcome of an abandoned open() follows.
    void close();
    bool isOpen() const { return m_state == State::Open; }
    // Only while open; otherwise the bytes are dropped with a warning.
    void send(const QByteArray &bytes);
    // Hands on now what the transport holds but has not reported yet: received() follows for
    // it. A busy machine may wake the client's thread for an answer's deadline before it
    // noticed the answer that came in time; the client asks before it judges.
    void readWaiting();
    // E.g. "serial /dev/ttyUSB0 38400 8E1", "tcp 127.0.0.1:4001", "simulated drive".
    virtual QString description() const = 0;

signals:
    void opened();
    void received(const QByteArray &bytes);
    // The line flagged a character (parity, framing or overrun error) between the bytes
    // received before and after this signal. The character itself is not passed on: the
    // telegram it belonged to is broken.
    void lineError(const QString &reason);
    // Opening failed, or the open link was lost (unplugged adapter, closed socket). Reported
    // at once; the link is closed afterwards.
    void failed(const QString &reason);

protected:
    enum class State : quint8 { Closed, Opening, Open };

    // The transport's part of open(): starts it, and ends in reportOpened(), fail() or
    // reportOutcomeLater().
    virtual void openTransport() = 0;
    // Stops the transport at once; what it still signals is ignored, the link being closed.
    virtual void closeTransport() = 0;
    // Writes bytes while open; fail() if they cannot be written.
    virtual void transmit(const QByteArray &bytes) = 0;
    // readWaiting()'s part: reads what the device has without waiting. A link whose bytes
    // never wait (the simulated drive's) has nothing to do.
    virtual void pollTransport() {}

    State state() const { return m_state; }
    // The transport is open: opened(), unless the attempt was abandoned.
    void reportOpened();
    // From the event loop, as for the links that open asynchronously: reportOpened(), or
    // fail(failure) when failure is not empty. Nothing when the attempt is abandoned meanwhile.
    void reportOutcomeLater(const QString &failure = {});
    // Opening failed or the link was lost: closes it and reports failed("<description>: reason").
    // Nothing when the link is already closed.
    void fail(const QString &reason);
    // Received bytes and flagged characters reach the client only while the link is open.
    void handOn(const QByteArray &bytes);
    void handOnLineError(const QString &reason);
    // handOn() whatever device reads.
    void handOnReceived(QIODevice *device);

private:
    State m_state = State::Closed;
    quint64 m_attempt = 0; // a queued outcome of an abandoned open() is not reported
};

// How a client gets its link: the application decides which kinds it offers (the serial port,
// TCP, the simulated drive), so the client depends on no particular one.
using LinkMaker = std::function<std::unique_ptr<Link>(const ConnectionSettings &settings)>;

} // namespace DriveDesk
