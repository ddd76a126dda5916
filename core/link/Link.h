#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

namespace DriveDesk {

struct ConnectionSettings;

// The byte pipe to a drive: serial port, TCP socket to a serial device server, or the
// simulated drive in process. The client sees no difference between them.
// Thread: a link lives in the client's worker thread and is used only from there.
class Link : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    ~Link() override = default;

    // Starts opening; ends in opened() or failed().
    virtual void open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual void send(const QByteArray &bytes) = 0;
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
};

// How a client gets its link: the application decides which kinds it offers (the serial port,
// TCP, the simulated drive), so the client depends on no particular one.
using LinkMaker = std::function<std::unique_ptr<Link>(const ConnectionSettings &settings)>;

} // namespace DriveDesk
