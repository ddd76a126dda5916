// When a ClientWorker decides that the drive stopped answering, and what it sends then.
//
// A drive behind an open link can fall silent (frozen, its device server's serial side gone).
// Each request would still spend every attempt, and a job of thousands of requests would run
// for many minutes. So once kUnansweredRequestsToStop requests in a row were given up with
// nothing from the drive since their last attempt, the drive has stopped answering: everything
// queued fails at once (Reply::Status::DriveSilent), and from then on one request at a time
// goes out, once, as the check whether the drive is back; the others fail at once. The first
// byte from the drive ends it.
//
// A drive nobody asks anything can freeze unnoticed. With ClientOptions::idleCheckMs, once
// nothing was sent or received for that long, one cheap request (the one the drive search asks)
// checks the drive; its timeout counts like any request's, so a silent drive is reported within
// idleSilenceLimitMs(). It goes out only when nothing is queued or in flight, so it never stands
// in front of a request of the user's: HSP5 sends one alongside it at once; on DIN66019(II),
// one request at a time, a request waits for the check's answer (milliseconds from a drive that
// answers).
#include "ClientWorker.h"

#include "ClientTiming.h"
#include "ValueRequests.h"

#include <QLocale>

#include <algorithm>

namespace DriveDesk {

void ClientWorker::noteSent(PendingRequest &request)
{
    request.receptionsAtAttempt = m_receptions;
    if (m_sentSinceLastByte == 0)
        m_firstUnansweredMs = m_clock.elapsed();
    ++m_sentSinceLastByte;
}

void ClientWorker::noteHeard()
{
    m_sentSinceLastByte = 0;
    m_unansweredInARow = 0;
    if (!m_driveStopped)
        return;
    m_driveStopped = false;
    record(TrafficRecord::Kind::Error, {},
           tr("the drive answers again: requests are sent as before"));
}

void ClientWorker::resetSilence()
{
    m_sentSinceLastByte = 0;
    m_unansweredInARow = 0;
    m_driveStopped = false;
}

QString ClientWorker::silenceText() const
{
    const double seconds = double(m_clock.elapsed() - m_firstUnansweredMs) / 1000.0;
    return tr("no answer to %n request(s) in %1 s", nullptr, m_sentSinceLastByte)
        .arg(QLocale().toString(seconds, 'f', 1));
}

void ClientWorker::noteUnanswered(const PendingRequest &request, Reply::Status *status,
                                  QString *detail)
{
    if (*status != Reply::Status::Timeout || request.options.probe || request.timeouts == 0
        || request.heard || request.receptionsAtAttempt != m_receptions
        || m_state != DriveClient::State::Connected)
        return;
    if (!m_driveStopped && ++m_unansweredInARow < kUnansweredRequestsToStop)
        return;
    *status = Reply::Status::DriveSilent;
    *detail = silenceText();
}

bool ClientWorker::failsWhileStopped(PendingRequest &request, QString *detail) const
{
    if (!m_driveStopped)
        return false;
    if (m_queue.empty() && m_inFlight.empty()) {
        request.maxAttempts = 1;
        return false;
    }
    *detail = silenceText();
    return true;
}

qint64 ClientWorker::idleMs() const
{
    return std::min({m_sinceLastByte.elapsed(), m_sinceLastSend.elapsed(),
                     m_sinceConnected.elapsed()});
}

void ClientWorker::armIdleCheck()
{
    if (!m_idleTimer)
        return;
    if (m_state != DriveClient::State::Connected || !m_queue.empty() || !m_inFlight.empty()) {
        m_idleTimer->stop(); // armed again when the line falls idle (pump() after the last)
        return;
    }
    m_idleTimer->start(int(std::max<qint64>(m_options.idleCheckMs - idleMs(), 0)));
}

void ClientWorker::checkIdleLine()
{
    if (m_state != DriveClient::State::Connected || !m_queue.empty() || !m_inFlight.empty())
        return;
    if (idleMs() < m_options.idleCheckMs)
        return armIdleCheck();
    // Its answer, or its silence, speaks through noteHeard() and complete(): nothing to do here.
    submitRequest(ValueRequests::presence(m_settings.protocol), {},
                  [](const Reply &, bool) {});
}

void ClientWorker::stopAnswering()
{
    if (m_driveStopped)
        return;
    m_driveStopped = true;
    const QString reason = silenceText();
    setDriveSilent(true);
    record(TrafficRecord::Kind::Error, {},
           tr("the drive stopped answering (%1): the requests queued fail, and one request at a "
              "time is sent once until the drive answers again")
               .arg(reason));
    emit driveStoppedAnswering(reason);
    failAll(Reply::Status::DriveSilent, reason);
    pump();
}

} // namespace DriveDesk
