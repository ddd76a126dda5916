#pragma once

#include "client/DriveClient.h"
#include "client/PendingRequest.h"
#include "client/RequestSink.h"
#include "link/Link.h"
#include "protocol/Codec.h"

#include <QElapsedTimer>
#include <QList>
#include <QPointer>
#include <QPromise>

#include <array>
#include <functional>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

class QTimer;

namespace DriveDesk {

class BaudRateSearch;

// The protocol work of a DriveClient: the link, the request queue with timeouts and retries,
// invoke ids, the DIN66019II drive selection, and the check of every answer against its
// request. Thread: lives in the client's own thread; the facade reaches it only through queued
// calls, and every callback (RequestSink::submit's `done`, Completion) runs in this thread.
class ClientWorker : public QObject, public RequestSink
{
    Q_OBJECT
public:
    ClientWorker(ConnectionSettings settings, ClientOptions options, LinkMaker makeLink,
                 QObject *parent = nullptr);
    ~ClientWorker() override;

    // Runs once the thread started.
    void init();
    void connectToDrive();
    void disconnectFromDrive();
    // Every queued and in-flight request finishes as Cancelled.
    void cancelAll();
    void setIdleCheckAddress(quint16 address) { m_idleCheckAddress = address; }

    void submit(const Telegram &request, std::function<void(const Reply &)> done) override;
    void cancelPending() override { cancelAll(); }
    bool supports(Service service, Access access) const override
    {
        return m_codec->supports(service, access);
    }
    quint64 lineErrors() const override { return m_lineErrors; }
    // Asked before each record whether anyone listens to traffic() (it is called in this
    // worker's thread). Without a listener the records are not made: describing every telegram
    // costs line time between an answer and the next request, and each record would wake the
    // listener's thread for nothing. Unset: always recorded.
    void setTrafficWanted(std::function<bool()> wanted) { m_trafficWanted = std::move(wanted); }

    // The facade's requests: the result goes to the promise; cancelling its future drops the
    // request from the queue, or has its answer ignored when it is already on the wire.
    void submitForFuture(const Telegram &request, std::shared_ptr<QPromise<Reply>> promise);
    // Every running job that can ends now with what it has (RequestJobBase::finishEarly): a
    // scan with what it read, unlike a cancelled future, which drops the result.
    void finishJobsEarly();
    // A job of many requests on a sink of its own, so that its cancel drops only its requests.
    // `driveAddress` >= 0: on a DIN66019(II) bus, the drive its requests go to where they name
    // none (one client serves every drive of a bus); -1: the connection's drive.
    void runJob(std::shared_ptr<RequestJobBase> job, int driveAddress = -1);

    // For jobs in this thread. Returns the request's ticket; `done` may run before it returns
    // (a request that cannot be sent, or no connection).
    quint64 submitRequest(const Telegram &request, RequestOptions options, Completion done);
    // A probe (RequestSink::probe) of `owner`: no retries, a wait as short as the line allows.
    quint64 submitProbe(const Telegram &request, quint64 owner, Completion done);
    void cancelOwner(quint64 owner);
    quint64 newOwner() { return m_nextOwner++; }

    const ConnectionSettings &settings() const { return m_settings; }
    const ProtocolCodec &codec() const { return *m_codec; }
    int answerTimeoutMs() const { return m_answerTimeoutMs; }
    QString connectionDescription() const;

signals:
    void stateChanged(DriveDesk::DriveClient::State state);
    void connected();
    void connectionFailed(const QString &reason);
    void linkLost(const QString &reason);
    void driveSilentChanged(bool silent);
    // Serial with automaticBaudRate: the drive answered at this rate, before connected().
    void baudRateFound(qint32 baudRate);
    // The drive stopped answering altogether: everything queued failed with `reason`.
    void driveStoppedAnswering(const QString &reason);
    void traffic(const DriveDesk::TrafficRecord &record);

private:
    using Request = std::unique_ptr<PendingRequest>;

    void setState(DriveClient::State state);
    void setDriveSilent(bool silent);
    void onLinkOpened();
    void onLinkFailed(const QString &reason);
    void dropLink();
    // What the link reports (bytes, a line error, its failure) is handled at once, in the pass
    // of the event loop that brought it; said from inside send(), it waits until the worker is
    // out of it, and what follows waits behind it.
    void fromLink(quint64 generation, std::function<void()> report);
    void runLinkReportsLater();
    void sendToLink(const QByteArray &bytes);
    // Opens the link at m_settings' baud rate; connectToDrive() after the rate is known.
    void openLink();
    // The drive answered at `baudRate`: the line's timing follows it.
    void onBaudRateFound(qint32 baudRate);
    void onReceived(const QByteArray &bytes);
    void onAnswer(const Telegram &answer);
    void onDecodeError(const DecodeError &error);
    void onLineError(const QString &reason);
    void onDeadline();
    // onDeadline()'s judgement, once what the link held when it fired has been handed on.
    void judgeDeadlines();
    void answerInverterRequest(const Telegram &request);

    // Validates and resolves a new request; false and *rejection when it cannot be sent.
    bool prepare(PendingRequest &request, Reply *rejection) const;
    void pump();
    int capacity() const;
    void transmit(PendingRequest &request);
    quint8 nextInvokeId();
    bool expectsAnswer(const PendingRequest &request) const;
    // Another attempt, or the end with Timeout when every attempt is spent.
    void retryOrGiveUp(PendingRequest &request);
    void cancelTicket(quint64 ticket);
    // Finishes every request with this status (link lost, connection failed, closing).
    void failAll(Reply::Status status, const QString &detail);

    PendingRequest *awaitingAnswer(quint8 operatorInvoke);
    Request takeInFlight(quint64 ticket);
    // ClientSilence.cpp: whether a drive stopped answering, and what then goes on the line.
    // A request given up with Timeout: what its attempts got counts toward the stop (or, as
    // from a line with errors, starts the count anew), and once the drive has stopped, it ends
    // as DriveSilent (status and detail are changed).
    void noteUnanswered(PendingRequest &request, Reply::Status *status, QString *detail);
    void stopAnswering();
    void noteSent(PendingRequest &request);
    // Bytes came (onReceived): the drive is there, though not necessarily answering.
    void noteHeard(const QByteArray &bytes);
    // An answer matched its request (even a refusal): the drive answers.
    void noteAnswered();
    // Garbage came: what the oldest attempt waiting for its answer got, unless something came
    // for it before.
    void noteGarbage(Garbage kind);
    static Garbage garbageOf(const DecodeError &error);
    // The end of the latest attempt of `request`: what it was answered with is counted.
    void closeAttempt(PendingRequest &request) const;
    // An answer that matched no open request: to an earlier one (stale), or to none at all.
    Garbage unmatchedAnswer(const Telegram &answer) const;
    // An attempt of `request` timed out: what the decoder still holds of it, if anything.
    void notePartialAnswer(const PendingRequest &request);
    void resetSilence();
    // While stopped, one request at a time goes out, once: the check whether the drive is back.
    // Whether `request` fails at once instead (*detail says why).
    bool failsWhileStopped(PendingRequest &request, QString *detail) const;
    // What the run of requests given up got instead of answers, mostly.
    Garbage runAnsweredWith() const;
    QString silenceText() const;
    // With ClientOptions::idleCheckMs: the timer runs out once the line has been idle that
    // long, and checkIdleLine() then sends the check (ValueRequests::presence).
    void armIdleCheck();
    void checkIdleLine();
    // Since anything was sent or answered, or the connection opened: garbage without end does
    // not keep the line busy.
    qint64 idleMs() const;

    // Runs the request's completion; the request itself stays where it is.
    void complete(PendingRequest &request, Reply::Status status, const Telegram *answer = nullptr,
                  const QString &detail = {});
    QString transportDetail(const PendingRequest &request, Reply::Status status) const;
    void armDeadlineTimer();
    // HSP5: no request in flight was answered. The drive may have lost its step (a service it
    // cannot frame, line noise, a gateway's hiccup): one request at a time, each after a quiet
    // line, until an answer matches again.
    void startRecovery();
    // Recovery: how long the next request still waits for a quiet line (0: it goes now).
    qint64 quietLineWaitMs();
    // Puts a request back into the queue in the order it was submitted.
    void requeue(Request request);
    bool tracing() const { return !m_trafficWanted || m_trafficWanted(); }
    void record(TrafficRecord::Kind kind, const QByteArray &bytes, const QString &meaning,
                const Telegram *telegram = nullptr, const Telegram *request = nullptr);
    // An attempt that got no answer in time, and whether it is asked again.
    void recordTimeout(const PendingRequest &request);
    bool isDin() const { return m_settings.protocol != Protocol::Hsp5; }

    ConnectionSettings m_settings; // baudRate: the rate found, with automaticBaudRate
    const ClientOptions m_options;
    const LinkMaker m_makeLink;
    int m_answerTimeoutMs = 0;
    std::unique_ptr<ProtocolCodec> m_codec;
    std::unique_ptr<FrameDecoder> m_decoder;
    std::unique_ptr<Link> m_link;
    std::unique_ptr<BaudRateSearch> m_baudSearch; // while connecting with automaticBaudRate
    DriveClient::State m_state = DriveClient::State::Disconnected;
    std::deque<Request> m_queue;
    std::vector<Request> m_inFlight; // on the wire or between attempts
    QTimer *m_deadlineTimer = nullptr;
    QTimer *m_quietTimer = nullptr; // recovery: wakes the queue once the line is quiet
    QTimer *m_idleTimer = nullptr;  // the idle line's check; none without idleCheckMs
    quint16 m_idleCheckAddress = 0; // what it reads
    QElapsedTimer m_sinceLastByte;
    QElapsedTimer m_sinceLastAnswer; // valid: matched to its request
    QElapsedTimer m_sinceLastSend;
    QElapsedTimer m_sinceConnected; // the idle line's check waits from the connection too
    int m_quietLineMs = 0;
    quint64 m_answersMatched = 0;
    quint64 m_receptions = 0; // chunks of bytes received from the drive
    quint64 m_lineErrors = 0; // error notes recorded (RequestSink::lineErrors)
    std::function<bool()> m_trafficWanted;
    bool m_driveSilent = false;
    // Silence: telegrams sent since the last valid answer, when the first of them went out (on
    // m_clock), the requests given up in a row without a valid answer, and whether the drive
    // counts as stopped.
    QElapsedTimer m_clock;
    int m_sentSinceAnswer = 0;
    qint64 m_firstUnansweredMs = 0;
    int m_unansweredInARow = 0;
    int m_unansweredAttempts = 0; // the attempts those requests spent
    int m_givenUpInARow = 0; // requests given up since the last valid answer, whatever they got
    bool m_driveStopped = false;
    // The run's requests by what they got instead of answers.
    std::array<int, kGarbageKinds> m_runGarbage{};
    std::deque<Telegram> m_sentRecently; // the latest attempts: what a stale answer answers
    QByteArray m_recentBytes; // the tail of what came: the part the decoder still holds
    quint8 m_receivedXor = 0; // of every byte received: HSP5's BCC over what an attempt got
    QElapsedTimer m_busyLineSince; // recovery: since when the next request waits on the drive
    std::vector<std::weak_ptr<RequestJobBase>> m_jobs; // running
    bool m_recovering = false;
    quint8 m_lastInvokeId = 0;
    int m_selectedDrive = -1; // DIN66019(II): the drive the last EOT selected, -1 unknown
    quint64 m_linkGeneration = 0; // which link's reports still count
    bool m_inSend = false;
    std::vector<std::function<void()>> m_linkReportsLater;
    quint64 m_nextTicket = 1;
    quint64 m_nextOwner = 1;
    bool m_pumping = false;
    bool m_pumpAgain = false;
    bool m_draining = false;
    bool m_staleAnswers = false; // DIN: a request went out while decoded items were pending
};

// The RequestSink a drive scan gets: the client's queue, where cancelPending() drops only the
// scan's own requests and leaves everybody else's alone.
class OwnedSink : public RequestSink
{
public:
    explicit OwnedSink(ClientWorker &worker, int driveAddress = -1)
        : m_worker(worker)
        , m_owner(worker.newOwner())
        , m_driveAddress(driveAddress)
    {}

    void submit(const Telegram &request, std::function<void(const Reply &)> done) override;
    void probe(const Telegram &request,
               std::function<void(const Reply &reply, bool heard)> done) override
    {
        m_worker.submitProbe(addressed(request), m_owner, std::move(done));
    }
    void cancelPending() override { m_worker.cancelOwner(m_owner); }
    bool supports(Service service, Access access) const override
    {
        return m_worker.supports(service, access);
    }
    quint64 lineErrors() const override { return m_worker.lineErrors(); }

private:
    Telegram addressed(const Telegram &request) const
    {
        Telegram to = request;
        if (to.driveAddress < 0)
            to.driveAddress = m_driveAddress;
        return to;
    }

    ClientWorker &m_worker;
    const quint64 m_owner;
    const int m_driveAddress;
};

} // namespace DriveDesk
