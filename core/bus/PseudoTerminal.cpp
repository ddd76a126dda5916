#include "PseudoTerminal.h"

#include <QFile>
#include <QFileInfo>
#include <QSocketNotifier>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace DriveDesk {

namespace {

QString systemError(const char *what)
{
    return QStringLiteral("%1: %2").arg(QLatin1String(what),
                                        QString::fromLocal8Bit(std::strerror(errno)));
}

} // namespace

PseudoTerminal::PseudoTerminal(QObject *parent)
    : QObject(parent)
{
}

PseudoTerminal::~PseudoTerminal()
{
    close();
}

bool PseudoTerminal::open(const QString &linkPath, QString *error)
{
    QString scratch;
    QString &message = error ? *error : scratch;
    close();
    if (linkPath.isEmpty()) {
        message = tr("no path given for the pseudo-terminal link");
        return false;
    }
    const QFileInfo existing(linkPath);
    if (existing.isSymLink() && !existing.exists()) {
        QFile::remove(linkPath); // left behind by a server that did not shut down cleanly
    } else if (existing.exists() || existing.isSymLink()) {
        message = tr("%1 already exists; choose another path or remove it").arg(linkPath);
        return false;
    }

    m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (m_master < 0) {
        message = systemError("posix_openpt");
        return false;
    }
    char name[128] = {};
    if (::grantpt(m_master) != 0 || ::unlockpt(m_master) != 0
        || ::ptsname_r(m_master, name, sizeof name) != 0) {
        message = systemError("pseudo-terminal setup");
        close();
        return false;
    }
    m_devicePath = QString::fromLocal8Bit(name);
    m_slave = ::open(name, O_RDWR | O_NOCTTY | O_NONBLOCK);
    termios attributes{};
    if (m_slave < 0 || ::tcgetattr(m_slave, &attributes) != 0) {
        message = systemError("opening the pseudo-terminal");
        close();
        return false;
    }
    ::cfmakeraw(&attributes);
    if (::tcsetattr(m_slave, TCSANOW, &attributes) != 0) {
        message = systemError("raw mode");
        close();
        return false;
    }
    ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    if (::symlink(name, QFile::encodeName(linkPath).constData()) != 0) {
        message = tr("cannot create the link %1: %2")
                      .arg(linkPath, QString::fromLocal8Bit(std::strerror(errno)));
        close();
        return false;
    }
    m_linkPath = linkPath;

    m_readNotifier = new QSocketNotifier(qintptr(m_master), QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &PseudoTerminal::readMaster);
    m_writeNotifier = new QSocketNotifier(qintptr(m_master), QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &PseudoTerminal::flush);
    return true;
}

void PseudoTerminal::close()
{
    // Possibly called from a notifier's own signal: disable now, delete later.
    for (QSocketNotifier *notifier : {m_readNotifier, m_writeNotifier}) {
        if (notifier) {
            notifier->setEnabled(false);
            notifier->deleteLater();
        }
    }
    m_readNotifier = nullptr;
    m_writeNotifier = nullptr;
    if (!m_linkPath.isEmpty()) {
        const QFileInfo link(m_linkPath);
        if (link.isSymLink() && link.symLinkTarget() == m_devicePath)
            QFile::remove(m_linkPath);
        m_linkPath.clear();
    }
    if (m_slave >= 0)
        ::close(m_slave);
    if (m_master >= 0)
        ::close(m_master);
    m_slave = -1;
    m_master = -1;
    m_devicePath.clear();
    m_outbox.clear();
}

qint32 PseudoTerminal::lineBaudRate() const
{
    termios attributes{};
    if (m_slave < 0 || ::tcgetattr(m_slave, &attributes) != 0)
        return 0;
    static const std::pair<speed_t, qint32> kRates[] = {
        {B50, 50},         {B75, 75},         {B110, 110},       {B134, 134},
        {B150, 150},       {B200, 200},       {B300, 300},       {B600, 600},
        {B1200, 1200},     {B1800, 1800},     {B2400, 2400},     {B4800, 4800},
        {B9600, 9600},     {B19200, 19200},   {B38400, 38400},   {B57600, 57600},
        {B115200, 115200}, {B230400, 230400}, {B460800, 460800}, {B500000, 500000},
        {B576000, 576000}, {B921600, 921600}, {B1000000, 1000000},
    };
    const speed_t speed = ::cfgetispeed(&attributes);
    for (const auto &[code, rate] : kRates) {
        if (code == speed)
            return rate;
    }
    return -1; // a rate of its own (BOTHER): none of the standard ones
}

void PseudoTerminal::write(const QByteArray &bytes)
{
    if (m_master < 0) {
        qWarning("DriveDesk: %d bytes not sent: the pseudo-terminal is closed", int(bytes.size()));
        return;
    }
    m_outbox += bytes;
    flush();
}

void PseudoTerminal::readMaster()
{
    char buffer[4096];
    QByteArray bytes;
    for (;;) {
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        if (n > 0) {
            bytes.append(buffer, qsizetype(n));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            break;
        if (!bytes.isEmpty())
            emit received(bytes);
        fail(n == 0 ? tr("the pseudo-terminal was closed")
                    : systemError("reading the pseudo-terminal"));
        return;
    }
    if (!bytes.isEmpty())
        emit received(bytes);
}

void PseudoTerminal::flush()
{
    while (!m_outbox.isEmpty() && m_master >= 0) {
        const ssize_t n = ::write(m_master, m_outbox.constData(), size_t(m_outbox.size()));
        if (n > 0) {
            m_outbox.remove(0, qsizetype(n));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            break;
        fail(systemError("writing the pseudo-terminal"));
        return;
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(!m_outbox.isEmpty());
}

void PseudoTerminal::fail(const QString &reason)
{
    const QString where = m_linkPath;
    close();
    emit failed(QStringLiteral("%1: %2").arg(where, reason));
}

} // namespace DriveDesk
