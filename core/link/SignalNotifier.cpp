#include "SignalNotifier.h"

#include <QSocketNotifier>

#include <csignal>
#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

namespace DriveDesk {

namespace {

// [0]: written by the handler; [1]: read in the event loop.
int g_sockets[2] = {-1, -1};

void onSignal(int signalNumber)
{
    const char byte = char(signalNumber);
    [[maybe_unused]] const ssize_t written = ::write(g_sockets[0], &byte, 1);
}

} // namespace

SignalNotifier::~SignalNotifier()
{
    for (int signalNumber : std::as_const(m_signals))
        ::signal(signalNumber, SIG_DFL);
    if (!m_notifier)
        return;
    delete m_notifier;
    for (int &socket : g_sockets) {
        ::close(socket);
        socket = -1;
    }
}

bool SignalNotifier::watch(std::initializer_list<int> signalNumbers)
{
    if (!m_notifier) {
        if (g_sockets[0] >= 0 || ::socketpair(AF_UNIX, SOCK_STREAM, 0, g_sockets) != 0)
            return false;
        // A signal handler must never block, even if signals pile up.
        ::fcntl(g_sockets[0], F_SETFL, ::fcntl(g_sockets[0], F_GETFL) | O_NONBLOCK);
        m_notifier = new QSocketNotifier(qintptr(g_sockets[1]), QSocketNotifier::Read, this);
        connect(m_notifier, &QSocketNotifier::activated, this, [this] {
            char byte = 0;
            if (::read(g_sockets[1], &byte, 1) == 1)
                emit caught(int(byte));
        });
    }
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (int signalNumber : signalNumbers) {
        ::sigaction(signalNumber, &action, nullptr);
        m_signals.append(signalNumber);
    }
    return true;
}

} // namespace DriveDesk
