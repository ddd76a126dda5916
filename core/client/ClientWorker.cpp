#include "ClientWorker.h"

#include "BaudRateSearch.h"
#include "ClientTiming.h"
#include "ReplyCheck.h"

#include <QDateTime>
#include <QTimer>

#include <algorithm>

namespace DriveDesk {

namespace {

// HSP5 allows at most 4 requests outstanding to the inverter.
constexpr int kMaxInFlight = 4;
constexpr int kInvokeIdCount = 15;
constexpr int kLastDriveAddress = 239;
constexpr int kBroadcastAddress = 255;

} // namespace

ClientWorker::ClientWorker(ConnectionSettings settings, ClientOptions options,
                           LinkMaker makeLink, QObject *parent)
    : QObject(parent)
    , m_settings(std::move(settings))
    , m_options(options)
    , m_makeLink(std::move(makeLink))
    , m_answerTimeoutMs(DriveDesk::answerTimeoutMs(m_settings, m_options))
    , m_codec(makeCodec(m_settings.protocol, CodecOptions{m_settings.hsp5Extensions}))
    , m_decoder(m_codec->makeDecoder(Role::Operator))
    , m_quietLineMs(quietLineMs(m_settings))
{}

ClientWorker::~ClientWorker()
{
    // No signals from here on: the facade is going away.
    blockSignals(true);
    m_state = DriveClient::State::Disconnected;
    failAll(Reply::Status::Cancelled, tr("the client was closed"));
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
    }
}

void ClientWorker::init()
{
    m_deadlineTimer = new QTimer(this);
    m_deadlineTimer->setSingleShot(true);
    m_deadlineTimer->setTimerType(Qt::PreciseTimer);
    connect(m_deadlineTimer, &QTimer::timeout, this, &ClientWorker::onDeadline);
    m_quietTimer = new QTimer(this);
    m_quietTimer->setSingleShot(true);
    connect(m_quietTimer, &QTimer::timeout, this, &ClientWorker::pump);
    if (m_options.idleCheckMs > 0) {
        m_idleTimer = new QTimer(this);
        m_idleTimer->setSingleShot(true);
        connect(m_idleTimer, &QTimer::timeout, this, &ClientWorker::checkIdleLine);
    }
    m_sinceLastByte.start();
    m_sinceLastAnswer.start();
    m_sinceLastSend.start();
    m_sinceConnected.start();
    m_clock.start();
}

QString ClientWorker::connectionDescription() const
{
    return m_link ? m_link->description() : m_settings.displayName();
}

void ClientWorker::submit(const Telegram &request, std::function<void(const Reply &)> done)
{
    submitRequest(request, {}, [done = std::move(done)](const Reply &reply, bool) { done(reply); });
}

quint64 ClientWorker::submitRequest(const Telegram &request, RequestOptions options,
                                    Completion done)
{
    auto pending = std::make_unique<PendingRequest>();
    pending->ticket = m_nextTicket++;
    pending->options = options;
    pending->request = request;
    pending->done = std::move(done);
    const quint64 ticket = pending->ticket;

    Reply rejection;
    if (!prepare(*pending, &rejection)) {
        complete(*pending, rejection.status, nullptr, rejection.detail);
        return ticket;
    }
    if (m_state != DriveClient::State::Connecting && m_state != DriveClient::State::Connected) {
        const QString why = m_state == DriveClient::State::Lost ? tr("the link was lost")
                                                                : QString();
        complete(*pending, Reply::Status::NotConnected, nullptr, why);
        return ticket;
    }
    QString silence;
    if (failsWhileStopped(*pending, &silence)) {
        complete(*pending, Reply::Status::DriveSilent, nullptr, silence);
        return ticket;
    }
    m_queue.push_back(std::move(pending));
    pump();
    return ticket;
}

quint64 ClientWorker::submitProbe(const Telegram &request, quint64 owner, Completion done)
{
    // The longest answer a probe may get (DIN66019II service 0: STX G IID 8 digits ETX BCC),
    // on top of the request itself.
    constexpr int kProbeAnswerCharacters = 13;
    Telegram onTheWire = request; // as it will be sent, for its length
    onTheWire.operatorInvoke = 1;
    if (!isDin())
        onTheWire.driveAddress = -1;
    const int requestCharacters = int(m_codec->encode(onTheWire).size());
    RequestOptions options;
    options.owner = owner;
    options.retries = 0;
    options.probe = true;
    options.timeoutMs = std::min(probeTimeoutMs(m_settings, m_options,
                                                requestCharacters + kProbeAnswerCharacters),
                                 m_answerTimeoutMs);
    return submitRequest(request, options, std::move(done));
}

bool ClientWorker::prepare(PendingRequest &pending, Reply *rejection) const
{
    rejection->status = Reply::Status::Unsupported;
    const Telegram &request = pending.request;
    if (request.isResponse()) {
        rejection->detail = tr("only requests can be sent, this is an answer");
        return false;
    }
    if (!m_codec->supports(request.service, request.access)) {
        rejection->detail = tr("%1 has no %2 of %3")
                                .arg(protocolName(m_settings.protocol),
                                     request.isWrite() ? tr("write") : tr("read"),
                                     serviceName(request.service));
        return false;
    }
    if (isDin()) {
        pending.target = request.driveAddress >= 0 ? request.driveAddress : m_settings.driveAddress;
        if (pending.target < 0 || pending.target > kBroadcastAddress) {
            rejection->detail = tr("drive address %1 is outside 0..239 (240..255: groups and "
                                   "broadcast)").arg(pending.target);
            return false;
        }
        if (pending.target > kLastDriveAddress && !request.isWrite()) {
            rejection->detail = tr("address %1 is a group or broadcast address: no drive answers "
                                   "there, so it takes writes only").arg(pending.target);
            return false;
        }
    }
    Telegram trial = request;
    trial.operatorInvoke = carriesInvokeId(m_settings.protocol, request.service) ? 1 : 0;
    trial.inverterInvoke = 0;
    trial.driveAddress = isDin() ? pending.target : -1;
    QString error;
    if (m_codec->encode(trial, &error).isEmpty()) {
        rejection->detail = error.isEmpty() ? tr("the codec cannot encode it") : error;
        return false;
    }
    pending.timeoutMs = pending.options.timeoutMs > 0 ? pending.options.timeoutMs
                                                      : m_answerTimeoutMs;
    const int retries = pending.options.retries >= 0 ? pending.options.retries : m_options.retries;
    pending.maxAttempts = 1 + std::max(retries, 0);
    return true;
}

int ClientWorker::capacity() const
{
    if (isDin() || m_recovering)
        return 1;
    return std::clamp(m_options.maxInFlight, 1, kMaxInFlight);
}

void ClientWorker::pump()
{
    if (m_pumping) {
        m_pumpAgain = true;
        return;
    }
    m_pumping = true;
    do {
        m_pumpAgain = false;
        while (m_state == DriveClient::State::Connected && !m_queue.empty()
               && int(m_inFlight.size()) < capacity()) {
            if (const qint64 wait = m_recovering ? quietLineWaitMs() : 0; wait > 0) {
                m_quietTimer->start(int(wait));
                break;
            }
            Request next = std::move(m_queue.front());
            m_queue.pop_front();
            PendingRequest &request = *next;
            m_inFlight.push_back(std::move(next));
            transmit(request);
        }
    } while (m_pumpAgain);
    m_pumping = false;
    armDeadlineTimer();
    armIdleCheck();
}

quint8 ClientWorker::nextInvokeId()
{
    for (int tries = 0; tries < kInvokeIdCount; ++tries) {
        m_lastInvokeId = quint8(m_lastInvokeId % kInvokeIdCount + 1);
        const auto holdsIt = [this](const Request &r) {
            return r->stage != PendingRequest::Stage::Queued
                   && r->wire.operatorInvoke == m_lastInvokeId;
        };
        const bool taken = std::any_of(m_inFlight.begin(), m_inFlight.end(), holdsIt);
        if (!taken)
            break;
    }
    return m_lastInvokeId;
}

bool ClientWorker::expectsAnswer(const PendingRequest &request) const
{
    return !(isDin() && request.target > kLastDriveAddress);
}

void ClientWorker::transmit(PendingRequest &request)
{
    if (request.attempts == 0)
        request.receptionsBefore = m_receptions;
    else
        closeAttempt(request); // the one before this
    ++request.attempts;
    request.wire = request.request;
    request.wire.direction = Direction::Request;
    request.wire.inverterInvoke = 0;
    request.wire.operatorInvoke = 0;
    request.stage = PendingRequest::Stage::Queued; // its old invoke id is free again
    if (carriesInvokeId(m_settings.protocol, request.request.service))
        request.wire.operatorInvoke = nextInvokeId();
    request.wire.driveAddress = -1;
    if (isDin() && m_selectedDrive != request.target)
        request.wire.driveAddress = request.target;

    QString error;
    const QByteArray bytes = m_codec->encode(request.wire, &error);
    if (bytes.isEmpty()) {
        Request owned = takeInFlight(request.ticket);
        if (!owned->completed())
            complete(*owned, Reply::Status::Unsupported, nullptr, error);
        pump();
        return;
    }
    if (isDin()) {
        m_selectedDrive = request.target;
        // Half duplex, one request at a time: nothing that came before can answer this one.
        m_decoder->reset();
        m_staleAnswers = m_draining;
    }
    request.stage = PendingRequest::Stage::AwaitingAnswer;
    request.deadline = QDeadlineTimer(request.timeoutMs, Qt::PreciseTimer);
    request.answersBefore = m_answersMatched;
    m_sinceLastSend.restart();
    m_busyLineSince.invalidate();
    noteSent(request);
    sendToLink(bytes);
    if (tracing()) {
        QString meaning = describe(request.wire);
        if (request.wire.driveAddress >= 0)
            meaning = tr("to drive %1: %2").arg(request.wire.driveAddress).arg(meaning);
        record(TrafficRecord::Kind::Sent, bytes, meaning, &request.wire);
    }

    if (!expectsAnswer(request)) {
        Request owned = takeInFlight(request.ticket);
        if (!owned->completed())
            complete(*owned, Reply::Status::NoReply);
        pump();
    }
}

void ClientWorker::armDeadlineTimer()
{
    if (!m_deadlineTimer)
        return;
    qint64 earliest = -1;
    for (const Request &request : m_inFlight) {
        if (request->stage == PendingRequest::Stage::Queued)
            continue;
        const qint64 remaining = request->deadline.remainingTime();
        if (earliest < 0 || remaining < earliest)
            earliest = remaining;
    }
    if (earliest < 0)
        m_deadlineTimer->stop();
    else
        m_deadlineTimer->start(int(std::max<qint64>(earliest, 0)));
}

// The drive takes a byte as a telegram's start again only after a quiet line of its input:
// that much is always waited after sending. The drive's own output is waited out only for a
// while: a line that never falls quiet (a stream of garbage) must not hold every request forever.
qint64 ClientWorker::quietLineWaitMs()
{
    const qint64 sending = m_quietLineMs - m_sinceLastSend.elapsed();
    qint64 receiving = m_quietLineMs - m_sinceLastByte.elapsed();
    if (receiving > 0) {
        if (!m_busyLineSince.isValid())
            m_busyLineSince.start();
        receiving = std::min(receiving, 2 * m_quietLineMs - m_busyLineSince.elapsed());
    }
    return std::max({sending, receiving, qint64(0)});
}

void ClientWorker::startRecovery()
{
    if (m_recovering)
        return;
    m_recovering = true;
    record(TrafficRecord::Kind::Error, {},
           tr("no request in flight was answered: one request at a time, each after %n ms of "
              "quiet line, until the drive answers again",
              nullptr, m_quietLineMs));
}

void ClientWorker::requeue(Request request)
{
    request->stage = PendingRequest::Stage::Queued;
    const quint64 ticket = request->ticket;
    const auto later = std::find_if(m_queue.begin(), m_queue.end(),
                                    [ticket](const Request &r) { return r->ticket > ticket; });
    m_queue.insert(later, std::move(request));
}

void ClientWorker::record(TrafficRecord::Kind kind, const QByteArray &bytes, const QString &meaning,
                          const Telegram *telegram, const Telegram *request)
{
    if (kind == TrafficRecord::Kind::Error)
        ++m_lineErrors;
    if (!tracing())
        return;
    TrafficRecord entry;
    entry.kind = kind;
    entry.msecsSinceEpoch = QDateTime::currentMSecsSinceEpoch();
    entry.bytes = bytes;
    entry.meaning = meaning;
    if (telegram)
        entry.telegram = *telegram;
    if (request)
        entry.request = *request;
    emit traffic(entry);
}

void ClientWorker::recordTimeout(const PendingRequest &request)
{
    const bool again = !request.completed() && request.attempts < request.maxAttempts;
    const QString note
        = again ? tr("no answer within %1 ms (attempt %2 of %3), asking again")
                      .arg(request.timeoutMs)
                      .arg(request.attempts)
                      .arg(request.maxAttempts)
                : tr("no answer within %1 ms (attempt %2 of %3), given up")
                      .arg(request.timeoutMs)
                      .arg(request.attempts)
                      .arg(request.maxAttempts);
    record(TrafficRecord::Kind::Error, {}, note, nullptr, &request.wire);
}

void ClientWorker::answerInverterRequest(const Telegram &request)
{
    record(TrafficRecord::Kind::Received, m_codec->encode(request),
           tr("inverter request: %1").arg(describe(request)), &request);
    const Telegram answer = request.response(Ack::ServiceNotAvailable);
    QString error;
    const QByteArray bytes = m_codec->encode(answer, &error);
    if (bytes.isEmpty()) {
        record(TrafficRecord::Kind::Error, {},
               tr("cannot answer the inverter's request: %1").arg(error));
        return;
    }
    record(TrafficRecord::Kind::Sent, bytes, describe(answer), &answer, &request);
    sendToLink(bytes);
}

void OwnedSink::submit(const Telegram &request, std::function<void(const Reply &)> done)
{
    RequestOptions options;
    options.owner = m_owner;
    m_worker.submitRequest(addressed(request), options,
                           [done = std::move(done)](const Reply &reply, bool) { done(reply); });
}

} // namespace DriveDesk
