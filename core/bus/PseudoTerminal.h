#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

class QSocketNotifier;

namespace DriveDesk {

// The master side of a pseudo-terminal in raw mode, with a symlink to its slave device that
// QSerialPort or a terminal program opens like a real serial port. The slave stays open here
// too, so that a client closing it never hangs up the master. POSIX only.
class PseudoTerminal : public QObject
{
    Q_OBJECT
public:
    explicit PseudoTerminal(QObject *parent = nullptr);
    ~PseudoTerminal() override;

    // Creates the pseudo-terminal and the symlink at linkPath. A stale link there (pointing
    // nowhere) is replaced; anything else is left alone and reported.
    bool open(const QString &linkPath, QString *error);
    // Closes both sides and removes the symlink if it still points at this terminal.
    void close();
    bool isOpen() const { return m_master >= 0; }

    QString linkPath() const { return m_linkPath; }
    QString devicePath() const { return m_devicePath; }

    void write(const QByteArray &bytes);
    // The baud rate the other side set on the line (a pty pair shares its termios on Linux),
    // 0 when it cannot be told, -1 for a rate outside the standard termios ones (55500, say).
    // Nothing paces a pty: this is only what the port was set to.
    qint32 lineBaudRate() const;

signals:
    void received(const QByteArray &bytes);
    void failed(const QString &reason);

private:
    void readMaster();
    void flush();
    void fail(const QString &reason);

    int m_master = -1;
    int m_slave = -1;
    QString m_linkPath;
    QString m_devicePath;
    QSocketNotifier *m_readNotifier = nullptr;
    QSocketNotifier *m_writeNotifier = nullptr;
    QByteArray m_outbox; // what the master could not take yet
};

} // namespace DriveDesk
