// How answers, decode errors, deadlines and cancels move the requests of a ClientWorker
// on, and how each one ends.
#include "ClientWorker.h"

#include "ReplyCheck.h"

#include <QStringList>

#include <algorithm>

namespace DriveDesk {

namespace {

// The drive said busy: give it this much more time per attempt before asking again.
constexpr int kBusyBackoffMs = 5;
// A partial telegram older than this, when an answer timed out, is a remnant: drop it.
constexpr int kIdleGapMs = 10;

} // namespace

void ClientWorker::onReceived(const QByteArray &bytes)
{
    if (m_state != DriveClient::State::Connected)
        return;
    m_sinceLastByte.restart();
    if (!bytes.isEmpty()) {
        ++m_receptions;
        noteHeard(bytes);
    }
    m_decoder->feed(bytes);
    if (m_draining)
        return;
    m_draining = true;
    while (std::optional<Decoded> item = m_decoder->next()) {
        if (m_staleAnswers) {
            const auto *telegram = std::get_if<Telegram>(&*item);
            noteGarbage(telegram ? unmatchedAnswer(*telegram)
                                 : garbageOf(std::get<DecodeError>(*item)));
            record(TrafficRecord::Kind::Error,
                   telegram ? m_codec->encode(*telegram) : std::get<DecodeError>(*item).bytes,
                   tr("arrived before the open request was sent, ignored: %1")
                       .arg(telegram ? describe(*telegram) : std::get<DecodeError>(*item).detail));
            continue;
        }
        if (const auto *telegram = std::get_if<Telegram>(&*item))
            onAnswer(*telegram);
        else
            onDecodeError(std::get<DecodeError>(*item));
    }
    m_draining = false;
    m_staleAnswers = false;
    pump();
}

PendingRequest *ClientWorker::awaitingAnswer(quint8 operatorInvoke)
{
    for (const Request &request : m_inFlight) {
        if (request->stage != PendingRequest::Stage::AwaitingAnswer)
            continue;
        // DIN66019(II) has one request on the wire; which answer is its answer is checked later.
        if (isDin() || request->wire.operatorInvoke == operatorInvoke)
            return request.get();
    }
    return nullptr;
}

void ClientWorker::onAnswer(const Telegram &answer)
{
    if (!answer.isResponse()) {
        if (m_settings.protocol == Protocol::Hsp5 && answer.operatorInvoke == 0
            && answer.inverterInvoke != 0) {
            answerInverterRequest(answer);
        } else {
            noteGarbage(Garbage::ForeignAnswer);
            record(TrafficRecord::Kind::Error, m_codec->encode(answer),
                   tr("a request where answers are expected, ignored: %1").arg(describe(answer)));
        }
        return;
    }
    PendingRequest *request = awaitingAnswer(answer.operatorInvoke);
    const QString mismatch
        = request ? replyMismatch(m_settings.protocol, request->wire, answer) : QString();
    if (tracing()) {
        // The monitor shows an answer with the request it answers, named as that request names
        // it.
        const bool matched = request && mismatch.isEmpty();
        const Telegram shown = matched ? completeAnswer(request->wire, answer) : answer;
        record(TrafficRecord::Kind::Received, m_codec->encode(answer), describe(shown), &shown,
               matched ? &request->wire : nullptr);
    }
    if (!request || !mismatch.isEmpty())
        noteGarbage(unmatchedAnswer(answer));
    if (!request) {
        record(TrafficRecord::Kind::Error, {},
               tr("the answer with invoke id %1 belongs to no open request, ignored")
                   .arg(answer.operatorInvoke));
        return;
    }
    request->heard = true;
    // A negative answer to a read ends with EOT: the drive dropped the selection, whichever
    // request the answer belongs to.
    const bool endsWithEot = answer.service == Service::Unspecified
                             && answer.access == Access::Read && answer.ack != Ack::Ok;
    if (isDin() && (endsWithEot || (answer.ack != Ack::Ok && !request->wire.isWrite())))
        m_selectedDrive = -1;
    if (!mismatch.isEmpty()) {
        record(TrafficRecord::Kind::Error, {},
               tr("the answer does not match its request (%1), not accepted").arg(mismatch));
        const bool lateAnswer = isDin()
                                && carriesInvokeId(m_settings.protocol, request->wire.service)
                                && answer.operatorInvoke != request->wire.operatorInvoke;
        if (lateAnswer)
            return; // to an earlier attempt: this attempt's own answer may still come
        ++request->mismatches;
        retryOrGiveUp(*request);
        return;
    }
    ++m_answersMatched;
    m_recovering = false; // in step: the drive answers what it was asked
    noteAnswered();
    if (request->completed()) {
        takeInFlight(request->ticket); // cancelled: its answer is ignored
        return;
    }
    if (answer.ack != Ack::Ok && isTransient(answer.ack)
        && request->attempts < request->maxAttempts) {
        ++request->transientAcks;
        request->lastTransientAck = answer.ack;
        if (answer.ack == Ack::Busy) {
            request->stage = PendingRequest::Stage::Backoff;
            request->deadline = QDeadlineTimer(kBusyBackoffMs * request->attempts,
                                               Qt::PreciseTimer);
            armDeadlineTimer();
        } else {
            transmit(*request);
        }
        return;
    }
    Request owned = takeInFlight(request->ticket);
    // What was queued behind it goes out before the answer is handled: it never depended on
    // the answer, and on a half-duplex line the drive would wait for the handling.
    pump();
    complete(*owned, answer.ack == Ack::Ok ? Reply::Status::Ok : Reply::Status::Refused, &answer);
}

void ClientWorker::onDecodeError(const DecodeError &error)
{
    record(TrafficRecord::Kind::Error, error.bytes,
           QStringLiteral("%1: %2").arg(decodeErrorKindName(error.kind), error.detail));
    noteGarbage(garbageOf(error));
    PendingRequest *request = nullptr;
    if (isDin()) {
        // Skipped garbage may be the tail of an earlier answer: the timeout decides then.
        request = awaitingAnswer(0);
        const bool ownInvokeId = !request || error.operatorInvoke == 0
                                 || error.operatorInvoke == request->wire.operatorInvoke;
        if (error.kind == DecodeError::Kind::UnexpectedByte || !ownInvokeId)
            request = nullptr;
    } else if (error.operatorInvoke != 0) {
        request = awaitingAnswer(error.operatorInvoke);
    }
    if (!request)
        return;
    request->heard = true;
    if (error.kind == DecodeError::Kind::ChecksumMismatch)
        ++request->checksumErrors;
    else
        ++request->otherDecodeErrors;
    if (isDin())
        m_selectedDrive = -1;
    retryOrGiveUp(*request);
}

// The UART flagged a character of what is arriving: that telegram is broken. The drive answers
// in order, so it belongs to the oldest request still waiting; ask again at once rather than
// wait for its timeout. A late answer to the earlier attempt is then an answer to no one.
void ClientWorker::onLineError(const QString &reason)
{
    if (m_state != DriveClient::State::Connected)
        return;
    m_decoder->reset();
    noteGarbage(Garbage::LineError);
    record(TrafficRecord::Kind::Error, {}, tr("line error: %1").arg(reason));
    PendingRequest *oldest = nullptr;
    for (const Request &request : m_inFlight) {
        if (request->stage == PendingRequest::Stage::AwaitingAnswer) {
            oldest = request.get();
            break;
        }
    }
    if (!oldest)
        return;
    ++oldest->lineErrors;
    if (isDin())
        m_selectedDrive = -1;
    retryOrGiveUp(*oldest);
    pump();
}

void ClientWorker::onDeadline()
{
    // On a busy machine this thread may wake for the deadline with the answer already in, or
    // with it read but still queued for onReceived(): the link is asked for what it holds, and
    // the judgement queued behind all of it, so that an answer that came in time counts.
    if (m_link)
        m_link->readWaiting();
    QMetaObject::invokeMethod(this, &ClientWorker::judgeDeadlines, Qt::QueuedConnection);
}

void ClientWorker::judgeDeadlines()
{
    std::vector<quint64> expired;
    for (const Request &request : m_inFlight) {
        if (request->stage != PendingRequest::Stage::Queued && request->deadline.hasExpired())
            expired.push_back(request->ticket);
    }
    for (quint64 ticket : expired) {
        auto it = std::find_if(m_inFlight.begin(), m_inFlight.end(),
                               [ticket](const Request &r) { return r->ticket == ticket; });
        if (it == m_inFlight.end())
            continue;
        PendingRequest &request = **it;
        if (request.stage == PendingRequest::Stage::Backoff) {
            transmit(request);
            continue;
        }
        ++request.timeouts;
        recordTimeout(request);
        notePartialAnswer(request);
        if (isDin()) {
            m_selectedDrive = -1; // the drive may have dropped it, or another took the line
            retryOrGiveUp(request);
            continue;
        }
        if (m_decoder->buffered() > 0 && m_sinceLastByte.elapsed() >= kIdleGapMs)
            m_decoder->reset();
        // Nothing answered since this request went out: whatever was in flight behind it is
        // lost too, and the drive may be out of step.
        if (request.answersBefore == m_answersMatched)
            startRecovery();
        if (!m_recovering) {
            retryOrGiveUp(request);
            continue;
        }
        Request owned = takeInFlight(ticket);
        if (owned->completed())
            continue;
        if (owned->attempts < owned->maxAttempts)
            requeue(std::move(owned));
        else
            complete(*owned, Reply::Status::Timeout);
    }
    pump();
}

void ClientWorker::retryOrGiveUp(PendingRequest &request)
{
    if (request.completed()) {
        takeInFlight(request.ticket);
        pump();
        return;
    }
    if (request.attempts < request.maxAttempts) {
        transmit(request);
        return;
    }
    Request owned = takeInFlight(request.ticket);
    complete(*owned, Reply::Status::Timeout);
    pump();
}

void ClientWorker::cancelTicket(quint64 ticket)
{
    for (auto it = m_queue.begin(); it != m_queue.end(); ++it) {
        if ((*it)->ticket == ticket) {
            Request owned = std::move(*it);
            m_queue.erase(it);
            complete(*owned, Reply::Status::Cancelled);
            return;
        }
    }
    auto it = std::find_if(m_inFlight.begin(), m_inFlight.end(),
                           [ticket](const Request &r) { return r->ticket == ticket; });
    if (it == m_inFlight.end() || (*it)->completed())
        return;
    if ((*it)->stage == PendingRequest::Stage::AwaitingAnswer) {
        complete(**it, Reply::Status::Cancelled); // stays until its answer or timeout
        return;
    }
    Request owned = takeInFlight(ticket);
    complete(*owned, Reply::Status::Cancelled);
    pump();
}

void ClientWorker::cancelOwner(quint64 owner)
{
    std::vector<quint64> tickets;
    for (const Request &request : m_queue) {
        if (request->options.owner == owner)
            tickets.push_back(request->ticket);
    }
    for (const Request &request : m_inFlight) {
        if (request->options.owner == owner)
            tickets.push_back(request->ticket);
    }
    for (quint64 ticket : tickets)
        cancelTicket(ticket);
}

void ClientWorker::cancelAll()
{
    std::vector<quint64> tickets;
    for (const Request &request : m_queue)
        tickets.push_back(request->ticket);
    for (const Request &request : m_inFlight)
        tickets.push_back(request->ticket);
    for (quint64 ticket : tickets)
        cancelTicket(ticket);
}

ClientWorker::Request ClientWorker::takeInFlight(quint64 ticket)
{
    auto it = std::find_if(m_inFlight.begin(), m_inFlight.end(),
                           [ticket](const Request &r) { return r->ticket == ticket; });
    Q_ASSERT(it != m_inFlight.end());
    Request owned = std::move(*it);
    m_inFlight.erase(it);
    return owned;
}

void ClientWorker::complete(PendingRequest &request, Reply::Status status, const Telegram *answer,
                            const QString &detail)
{
    Reply reply;
    reply.status = status;
    reply.request = request.attempts > 0 ? request.wire : request.request;
    if (answer)
        reply.response = completeAnswer(request.wire, *answer);
    reply.attempts = request.attempts;
    reply.detail = detail.isEmpty() ? transportDetail(request, status) : detail;
    // Every attempt timed out and not a byte came since the first went out: the drive is silent.
    if (status == Reply::Status::Timeout && m_state == DriveClient::State::Connected
        && !request.options.probe && request.timeouts > 0
        && !request.heard && request.receptionsBefore == m_receptions)
        setDriveSilent(true);
    noteUnanswered(request, &reply.status, &reply.detail);
    const bool stops = reply.status == Reply::Status::DriveSilent && !m_driveStopped;
    const Completion done = std::move(request.done);
    request.done = nullptr;
    const bool heard = request.heard;
    // The news that the drive stopped answering goes out before any request's failure says so:
    // whoever waits on both (the command line: its scan and the reason) hears them in order.
    if (stops)
        stopAnswering();
    done(reply, heard);
}

QString ClientWorker::transportDetail(const PendingRequest &request, Reply::Status status) const
{
    QStringList parts;
    if (request.timeouts > 0)
        parts << tr("%n timeout(s)", nullptr, request.timeouts);
    if (request.checksumErrors > 0)
        parts << tr("%n answer(s) with a wrong BCC", nullptr, request.checksumErrors);
    if (request.lineErrors > 0)
        parts << tr("%n line error(s)", nullptr, request.lineErrors);
    if (request.otherDecodeErrors > 0)
        parts << tr("%n unreadable answer(s)", nullptr, request.otherDecodeErrors);
    if (request.mismatches > 0)
        parts << tr("%n answer(s) that did not match the request", nullptr, request.mismatches);
    if (request.transientAcks > 0) {
        parts << tr("%n transient refusal(s) (%1)", nullptr, request.transientAcks)
                     .arg(ackText(request.lastTransientAck));
    }
    // A list of counts, not a sentence: the separators need no translation.
    QString text = parts.join(QStringLiteral(", "));
    if (status == Reply::Status::Timeout) {
        const QString timeout = tr("timeout %1 ms").arg(request.timeoutMs);
        text = text.isEmpty() ? timeout : QStringLiteral("%1; %2").arg(text, timeout);
    }
    return text;
}

} // namespace DriveDesk
