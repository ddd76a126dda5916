#pragma once

#include "client/Reply.h"
#include "client/RequestJob.h"
#include "link/ConnectionSettings.h"
#include "link/Link.h"
#include "parameters/DriveDescription.h"

#include <QFuture>
#include <QObject>

#include <atomic>
#include <optional>
#include <memory>

class QThread;

namespace DriveDesk {

class ClientWorker;

struct ClientOptions {
    int timeoutMs = 0;   // 0: derived from the baud rate and the longest telegram
    int retries = 3;     // on timeout, BCC/transmission/framing errors and busy (ack 6)
    int maxInFlight = 4; // HSP5 only (the drive's limit); DIN66019(II) is always 1
    // Once nothing was sent or received for this long, one cheap request checks that the drive
    // still answers, so that a silent drive is reported while nobody asks it anything. 0: never
    // (a command that ends when its work is done, and tests that count what goes on the line).
    int idleCheckMs = 0;
    // What the window sets: a drive frozen on an idle line is reported within 5 s
    // (idleSilenceLimitMs()) on every line docs/client.md lists.
    static constexpr int kInteractiveIdleCheckMs = 2000;
};

// Where a scan takes a drive's metadata from (core/parameters/MetadataCache).
enum class MetadataSource : quint8 {
    Drive,        // read it all from the drive; the cache is neither read nor written
    Cache,        // a drive of a cached kind: only values and its identification are read
    RefreshCache, // read it all from the drive and store it for the next connection
};

struct ScanOptions {
    bool values = true;       // read the value of every set
    bool plaintexts = true;   // services 7, 9, 12
    QList<quint8> groupPages; // empty: try every group address 00xxh..FFxxh
    bool parameters = true;   // false: groups only (services 10, 11)
    QList<quint16> onlyParameters; // non-empty: just these parameters of the groups found
    MetadataSource metadata = MetadataSource::Drive;
    QString cacheDirectory; // empty: MetadataCache::defaultDirectory()
    // An upload: the result is what a parameter list holds (ParameterList::fromScan), and no
    // value is read that a list does not read (excluded and write-only parameters).
    bool parameterList = false;
    // Service 13 function 1, the drive's identification text: DriveDesk's extension, which
    // seed 000 lacks and seed 003 marks reserved. Sent only when the user says the drive has it
    // (the connection's --hsp5-extensions sets it); otherwise the identification parameters.
    bool identificationText = false;
    // DIN66019(II): the drive on the bus to scan, where one client serves a bus's drives (a
    // plant's link); -1: the connection's drive (ConnectionSettings::driveAddress).
    int driveAddress = -1;
};

// A note on the wire for the telegram monitor.
struct TrafficRecord {
    enum class Kind : quint8 { Sent, Received, Error };
    Kind kind = Kind::Sent;
    qint64 msecsSinceEpoch = 0;
    QByteArray bytes;
    QString meaning; // describe(telegram) for logs, or the client's note on an error
    // The telegram the bytes hold, where they hold one. An answer the client matched to its
    // request is completed with the request's fields (completeAnswer()): address, set.
    std::optional<Telegram> telegram;
    // Received: the request (as sent) the answer answers; empty where it answers none.
    // Error: the request the note is about, e.g. the one that got no answer in time.
    std::optional<Telegram> request;
};

// The only way the rest of DriveDesk talks to a drive. The facade lives in the caller's
// thread; the protocol work happens in a worker QObject on its own QThread. Every method is
// thread-safe and returns at once; results arrive as QFutures (progress and cancel included).
class DriveClient : public QObject
{
    Q_OBJECT
public:
    enum class State : quint8 { Disconnected, Connecting, Connected, Lost };
    Q_ENUM(State)

    // `makeLink` gives the client its link on every connectToDrive(): the application chooses
    // which kinds of link there are (core/bus's everyLink(): serial, TCP, simulated).
    DriveClient(ConnectionSettings settings, LinkMaker makeLink, ClientOptions options = {},
                         QObject *parent = nullptr);
    ~DriveClient() override;

    const ConnectionSettings &settings() const { return m_settings; }
    State state() const { return m_state; }
    // Connected, but the drive stopped answering: a request was given up after every attempt
    // and nothing at all came from the drive since it was first sent. Clears by itself with
    // the next byte from the drive, and whenever the connection ends.
    bool isDriveSilent() const { return m_driveSilent; }

    void connectToDrive();
    void disconnectFromDrive();

    // Queues a request. Invoke ids and the DIN66019II selection are the client's business.
    QFuture<Reply> send(const Telegram &request);
    // Typed conveniences over send().
    QFuture<Reply> readValue(quint16 address, quint8 setMask);           // service 0
    QFuture<Reply> writeValue(quint16 address, qint32 value, quint8 setMask);
    QFuture<Reply> readValueStandard(quint16 address, quint8 set);      // service 1 (DIN66019: -1)
    QFuture<Reply> writeValueStandard(quint16 address, qint32 value, quint8 set);
    QFuture<Reply> resetToDefault(quint16 address, quint8 setMask);      // service 32 write
    QFuture<Reply> readScope();                                          // service 18

    // Discovers groups, parameters, metadata and values. Progress in 0..1000; cancellable.
    QFuture<DriveDescription> scan(ScanOptions options = {});
    // Ends the running scan with what it has read so far: its future gets the description,
    // incompleteReason "cancelled" (cancelling the future instead gives no result at all).
    void stopScan();
    // The parameter the idle line's check reads (ClientOptions::idleCheckMs): one the drive has,
    // once it is known, so that the check's answer is a value, not a refusal every few seconds
    // in the telegram monitor. Until then, and after a new connection, address 0000h.
    void setIdleCheckAddress(quint16 address);

    // Runs a job of many requests in the client's thread, on the client's queue, and returns
    // its future. Cancelling the future stops the job. `driveAddress` >= 0: on a DIN66019(II)
    // bus, the drive the job's requests go to (one client for every drive of a bus); -1: the
    // connection's drive.
    template<typename Job>
    QFuture<typename Job::ResultType> run(std::shared_ptr<Job> job, int driveAddress = -1)
    {
        QFuture<typename Job::ResultType> future = job->future();
        start(std::move(job), driveAddress);
        return future;
    }

    // Lets a running job look again at what it waits for (RequestJobBase::resumed()); nothing
    // when it has ended.
    void resume(const std::weak_ptr<RequestJobBase> &job);

    // Drops every queued and in-flight request (they finish as Cancelled).
    void cancelAll();

signals:
    void stateChanged(DriveDesk::DriveClient::State state);
    void connected();
    void connectionFailed(const QString &reason);
    void linkLost(const QString &reason);
    void driveSilentChanged(bool silent);
    // Serial with automaticBaudRate: the drive answered at this rate (settings() now has it),
    // before connected().
    void baudRateFound(qint32 baudRate);
    // The drive stopped answering altogether (docs/client.md, "A drive that stops answering"):
    // every request queued failed as Reply::Status::DriveSilent with `reason`, e.g. "no answer
    // to 16 requests in 1.9 s". Comes after driveSilentChanged(true).
    void driveStoppedAnswering(const QString &reason);
    void traffic(const DriveDesk::TrafficRecord &record);

private:
    void setState(State state);
    void setDriveSilent(bool silent);
    void onBaudRateFound(qint32 baudRate);
    void start(std::shared_ptr<RequestJobBase> job, int driveAddress);

    ConnectionSettings m_settings;
    ClientOptions m_options;
    LinkMaker m_makeLink;
    std::atomic<State> m_state = State::Disconnected; // read from any thread
    std::atomic<bool> m_driveSilent = false;          // read from any thread
    QThread *m_thread = nullptr; // owned; stopped and joined in the destructor
    ClientWorker *m_worker = nullptr; // owned by its thread, deleted on finished
};

} // namespace DriveDesk
