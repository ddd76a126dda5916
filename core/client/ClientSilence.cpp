// When a ClientWorker decides that the drive stopped answering, and what it sends then.
//
// A drive behind an open link can fall silent (frozen, its device server's serial side gone),
// or answer only with garbage (a wrong baud rate or character format on a device server, a
// gateway that cuts or repeats telegrams, a stream from something that is not a drive). Each
// request would still spend every attempt, and a job of thousands of requests would run for
// many minutes. So once kUnansweredRequestsToStop requests in a row (and at least
// kUnansweredAttemptsToStop attempts) were given up without a valid answer (one matched to its request, even a refusal), the drive has stopped answering:
// everything queued fails at once (Reply::Status::DriveSilent), and from then on one request at
// a time goes out, once, as the check whether the drive is back; the others fail at once. The
// first valid answer ends it. The reason says what came instead: nothing, or the kind of
// garbage most of the run's requests got (Garbage).
//
// A drive nobody asks anything can freeze unnoticed. With ClientOptions::idleCheckMs, once
// nothing was sent or received for that long, one cheap request (a read of the parameter
// DriveClient::setIdleCheckAddress() names, else the drive search's)
// checks the drive; its timeout counts like any request's, so a silent drive is reported within
// idleSilenceLimitMs(). It goes out only when nothing is queued or in flight, so it never stands
// in front of a request of the user's: HSP5 sends one alongside it at once; on DIN66019(II),
// one request at a time, a request waits for the check's answer (milliseconds from a drive that
// answers).
#include "ClientWorker.h"

#include "ClientTiming.h"
#include "ReplyCheck.h"
#include "ValueRequests.h"
#include "protocol/din/DinCharacters.h"

#include <QLocale>

#include <algorithm>
#include <utility>

namespace DriveDesk {

namespace {

// The attempts an answer to an earlier request may still come from: HSP5 uses 15 invoke ids.
constexpr qsizetype kRememberedAttempts = 16;
// Enough of the stream's tail to hold whatever the decoder still waits on.
constexpr qsizetype kRememberedBytes = 512;

} // namespace

void ClientWorker::noteSent(PendingRequest &request)
{
    request.receptionsAtAttempt = m_receptions;
    request.receivedXorAtAttempt = m_receivedXor;
    if (m_sentSinceAnswer == 0)
        m_firstUnansweredMs = m_clock.elapsed();
    ++m_sentSinceAnswer;
    m_sentRecently.push_back(request.wire);
    if (qsizetype(m_sentRecently.size()) > kRememberedAttempts)
        m_sentRecently.pop_front();
}

void ClientWorker::noteHeard(const QByteArray &bytes)
{
    for (const char byte : bytes)
        m_receivedXor ^= quint8(byte);
    m_recentBytes.append(bytes);
    if (m_recentBytes.size() > kRememberedBytes)
        m_recentBytes.remove(0, m_recentBytes.size() - kRememberedBytes);
    // Whatever came, the drive is there; once it has stopped answering, only an answer counts:
    // a stream of garbage would end the stop with every byte.
    if (!m_driveStopped)
        setDriveSilent(false);
}

void ClientWorker::noteAnswered()
{
    m_sinceLastAnswer.restart();
    m_sentSinceAnswer = 0;
    m_unansweredInARow = 0;
    m_unansweredAttempts = 0;
    m_givenUpInARow = 0;
    m_runGarbage.fill(0);
    if (m_driveStopped) {
        m_driveStopped = false;
        record(TrafficRecord::Kind::Error, {},
               tr("the drive answers again: requests are sent as before"));
    }
    setDriveSilent(false);
}

void ClientWorker::noteGarbage(Garbage kind)
{
    // The drive answers in order: this stands where the oldest answer still missing would.
    for (const Request &request : m_inFlight) {
        if (request->stage == PendingRequest::Stage::AwaitingAnswer && !request->attemptGarbage) {
            request->attemptGarbage = kind;
            return;
        }
    }
}

void ClientWorker::closeAttempt(PendingRequest &request) const
{
    const std::optional<Garbage> came = std::exchange(request.attemptGarbage, std::nullopt);
    if (request.answersBefore != m_answersMatched) {
        ++request.overtakenAttempts;
        return;
    }
    // Bytes without a complete item yet: the decoder holds them still.
    Garbage got = came.value_or(request.receptionsAtAttempt != m_receptions ? Garbage::Unframed
                                                                            : Garbage::Nothing);
    // HSP5's BCC makes a telegram's bytes XOR to 0. A wrong BCC where everything the attempt
    // got does XOR to 0 is a frame read at the length its service gives, but sent longer or
    // shorter with its BCC right; a bit flipped on the line leaves the XOR off.
    if (got == Garbage::Checksum && !isDin() && request.receivedXorAtAttempt == m_receivedXor)
        got = Garbage::WrongLength;
    if (request.firstAttemptGot)
        ++request.laterAttemptsGot[int(got)];
    else
        request.firstAttemptGot = got;
}

Garbage ClientWorker::garbageOf(const DecodeError &error)
{
    switch (error.kind) {
    case DecodeError::Kind::ChecksumMismatch:
        return Garbage::Checksum;
    case DecodeError::Kind::Framing:
        return Garbage::WrongLength;
    case DecodeError::Kind::UnknownService:
    case DecodeError::Kind::UnexpectedByte:
        break;
    }
    return Garbage::Unframed;
}

Garbage ClientWorker::unmatchedAnswer(const Telegram &answer) const
{
    const auto answers = [&](const Telegram &sent) {
        return replyMismatch(m_settings.protocol, sent, answer).isEmpty();
    };
    return std::any_of(m_sentRecently.begin(), m_sentRecently.end(), answers)
        ? Garbage::StaleAnswer
        : Garbage::ForeignAnswer;
}

void ClientWorker::notePartialAnswer(const PendingRequest &request)
{
    const qsizetype held = m_decoder->buffered();
    if (held == 0)
        return;
    // A telegram begun and never finished is one of the wrong length: DIN66019(II) frames
    // start with STX; an HSP5 answer with its request's invoke id (INV-ID-FU 0).
    const QByteArray partial = m_recentBytes.right(held);
    const bool begun = isDin() ? partial.contains(DinControl::Stx)
                               : partial.startsWith(char(request.wire.operatorInvoke << 4));
    noteGarbage(begun ? Garbage::WrongLength : Garbage::Unframed);
}

void ClientWorker::resetSilence()
{
    m_sentSinceAnswer = 0;
    m_unansweredInARow = 0;
    m_unansweredAttempts = 0;
    m_givenUpInARow = 0;
    m_driveStopped = false;
    m_runGarbage.fill(0);
    m_sentRecently.clear();
    m_recentBytes.clear();
}

Garbage ClientWorker::runAnsweredWith() const
{
    // The first of equally frequent kinds: the more telling one (Garbage's order).
    const auto most = std::max_element(m_runGarbage.begin(), m_runGarbage.end());
    return *most == 0 ? Garbage::Nothing : Garbage(most - m_runGarbage.begin());
}

QString ClientWorker::silenceText() const
{
    const int sent = m_sentSinceAnswer;
    const Garbage answeredWith = runAnsweredWith();
    if (answeredWith == Garbage::Nothing) {
        const double seconds = double(m_clock.elapsed() - m_firstUnansweredMs) / 1000.0;
        return tr("no answer to %n request(s) in %1 s", nullptr, sent)
            .arg(QLocale().toString(seconds, 'f', 1));
    }
    switch (answeredWith) {
    case Garbage::StaleAnswer:
        return tr("%n request(s) in a row answered only with answers to an earlier request",
                  nullptr, sent);
    case Garbage::WrongLength:
        return tr("%n request(s) in a row answered only with frames of the wrong length", nullptr,
                  sent);
    case Garbage::Checksum:
        return tr("%n request(s) in a row answered only with frames with a wrong checksum", nullptr,
                  sent);
    case Garbage::ForeignAnswer:
        return tr("%n request(s) in a row answered only with answers to no request sent", nullptr,
                  sent);
    case Garbage::LineError:
        return tr("%n request(s) in a row answered only with characters the line flagged as "
                  "broken", nullptr, sent);
    case Garbage::Unframed:
    case Garbage::Nothing:
        break;
    }
    return tr("%n request(s) in a row answered only with bytes that never made a telegram", nullptr,
              sent);
}

void ClientWorker::noteUnanswered(PendingRequest &request, Reply::Status *status, QString *detail)
{
    if (*status != Reply::Status::Timeout || request.options.probe
        || m_state != DriveClient::State::Connected)
        return;
    closeAttempt(request);
    // Another request was answered while it waited (HSP5 has several on the wire): the drive
    // answers. Only one attempt may have seen that, as a request sent just before the drive fell
    // silent does.
    if ((request.overtakenAttempts > 1 || !request.firstAttemptGot) && !m_driveStopped)
        return;
    // A line with errors spoils some answers' checksums and others otherwise (a byte lost, a
    // start taken for another); its drive answers, if not this time. A link that does not
    // answer spoils each answer alike: a checksum always wrong, a frame always cut. The first
    // attempt may differ (what went wrong may have begun during it, or it shared the wire with
    // others), and so may one that got nothing (its garbage may have come late).
    std::array<int, kGarbageKinds> got = request.laterAttemptsGot;
    got[int(Garbage::Nothing)] = 0;
    const auto kinds = std::count_if(got.begin(), got.end(), [](int n) { return n > 0; });
    const bool lineWithErrors = kinds > 1 && got[int(Garbage::Checksum)] > 0;
    const bool tooManyGivenUp = ++m_givenUpInARow >= kGivenUpRequestsToStop;
    if (lineWithErrors && !tooManyGivenUp && !m_driveStopped) {
        m_unansweredInARow = 0;
        m_unansweredAttempts = 0;
        m_runGarbage.fill(0);
        return;
    }
    // What it got, mostly: bytes that never made a telegram are often what the decoder skipped
    // after a broken one, and a tie goes to the kind that says more (Garbage's order).
    got = request.laterAttemptsGot;
    ++got[int(request.firstAttemptGot.value_or(Garbage::Nothing))];
    ++m_runGarbage[int(std::max_element(got.begin(), got.end()) - got.begin())];
    m_unansweredAttempts += request.attempts;
    const bool enoughUnanswered = ++m_unansweredInARow >= kUnansweredRequestsToStop
        && m_unansweredAttempts >= kUnansweredAttemptsToStop;
    if (!m_driveStopped && !enoughUnanswered && !tooManyGivenUp)
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
    return std::min(
        { m_sinceLastAnswer.elapsed(), m_sinceLastSend.elapsed(), m_sinceConnected.elapsed() });
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
    // Its answer, or its silence, speaks through noteAnswered() and complete(): nothing to do
    // here.
    submitRequest(ValueRequests::presence(m_settings.protocol, m_idleCheckAddress), {},
                  [](const Reply &, bool) {});
}

void ClientWorker::stopAnswering()
{
    if (m_driveStopped)
        return;
    m_driveStopped = true;
    const QString reason = silenceText();
    if (runAnsweredWith() == Garbage::Nothing) {
        setDriveSilent(true);
    } else if (!m_driveSilent) {
        // setDriveSilent() would note that nothing came; much came, and the note below says what.
        m_driveSilent = true;
        emit driveSilentChanged(true);
    }
    record(TrafficRecord::Kind::Error, {},
           tr("the drive stopped answering (%1): the requests queued fail, and one request at a "
              "time is sent once until the drive answers again")
               .arg(reason));
    emit driveStoppedAnswering(reason);
    failAll(Reply::Status::DriveSilent, reason);
    pump();
}

} // namespace DriveDesk
