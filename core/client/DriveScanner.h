#pragma once

#include "client/DriveClient.h"
#include "client/RequestSink.h"
#include "client/ScanState.h"
#include "parameters/DriveIdentity.h"

#include <QObject>

#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace DriveDesk {

class MetadataCache;

// Discovers groups, parameters, metadata and values of a drive through a RequestSink.
// A state machine driven by the sink's `done` callbacks; it lives in the sink's thread.
// finished() is emitted exactly once; a receiver that wants the scanner gone uses deleteLater().
//
// It sends only what the drive can frame: service 13 (identification text) only where the user
// opted in (ScanOptions::identificationText) and the sink supports it. Once the line shows
// errors, every answer it keeps is confirmed by a second read that agrees (ScanConfirm.cpp).
// A drive of a kind the metadata cache knows (ScanOptions::metadata) costs only its
// identification and its values; a cold scan of a full drive refreshes the cache.
class DriveScanner : public QObject
{
    Q_OBJECT
public:
    DriveScanner(RequestSink &sink, ScanOptions options, Language language,
                 QObject *parent = nullptr);
    ~DriveScanner() override;

    void start();
    // Stops issuing requests, cancels the sink's pending ones and finishes at once with what
    // was read so far and incompleteReason "cancelled".
    void cancel();

signals:
    // Counts requests; total may grow (and settle) as the scan learns what the drive has.
    void progress(int done, int total, const QString &what);
    void finished(const DriveDesk::DriveDescription &description);

private:
    using Handler = std::function<void(const Reply &)>;

    // Why an answer cannot be true beyond what implausibleAnswer() sees (a value outside its
    // parameter's limits); empty when nothing speaks against it.
    using Check = std::function<QString(const Reply &)>;

    struct QueuedRequest {
        Telegram telegram;
        QString what; // for progress
        Handler handle;
        Check check;
        // On a line that showed errors an answer counts once two reads agree: the answers so
        // far, and how often it was read (answered or not).
        std::vector<Reply> answers;
        QStringList implausible;
        int reads = 0;
        bool recheck = false; // of an answer kept earlier: leads to nothing new
        bool secondRound = false;
        // Given up because its plausible answers never agreed (not for want of an answer).
        bool disagreed = false;
        // A read of this parameter's value (page, number): one the drive may change by itself.
        std::optional<std::pair<quint8, quint8>> valueOf;
    };
    using Queued = std::shared_ptr<QueuedRequest>;
    // A request left unsettled in the first round, with the failure it would be reported with.
    struct Unsettled {
        Queued request;
        Reply failure;
    };

    // An answer kept while the line was clean: read again once the line shows errors.
    struct Kept {
        Telegram telegram;
        QString what;
        Reply reply;
        std::optional<std::pair<quint8, quint8>> valueOf; // as QueuedRequest::valueOf
    };

    // The kind parameters of one cached kind, as the drive answers them.
    struct Probe {
        QList<quint16> addresses;
        DriveKind read;
        bool failed = false;
    };

    void enqueue(Service service, ServiceData data, QString what, Handler handle,
                 Check check = {});
    // A read about one existing parameter: a failure goes to its errors, prefixed by `label`.
    template<typename T>
    void readParameter(quint8 page, quint8 number, Service service, ServiceData data,
                       const QString &label, std::function<void(ScanParameter &, const T &)> apply);
    void submitQueued();
    void onReplied(const Reply &reply, const Queued &request);
    // Confirmation (ScanConfirm.cpp): hands an answer to its handler once it may be kept as the
    // drive's truth, or reads the request again.
    void settle(const Queued &request, const Reply &reply);
    void deliver(const QueuedRequest &request, const Reply &reply);
    void unsettled(const Queued &request, const Reply &failure);
    bool startSecondRound();
    void deliverUnsettled();
    void readAgain(const Queued &request);
    // Once the line shows errors, what was kept before is read once more to confirm it.
    void checkLine();
    // A value kept from `first` that the drive changes by itself: its sets read by `first`
    // lose the value and say why. False for any other parameter.
    bool leaveLiveValueUnconfirmed(quint8 page, quint8 number, const Reply &first);
    void finish(const QString &reason);
    DriveDescription result(const QString &reason);
    int total() const;

    // Cold: everything from the drive (DriveScanner.cpp).
    void scanGroups();
    void probeGroup(quint8 page);
    void onGroupProperties(quint8 page, const Reply &reply);
    void askNames(quint8 page);
    void askName(quint8 page, quint8 number);
    void onParameterName(quint8 page, quint8 number, const Reply &reply);
    void readMetadata(quint8 page, quint8 number);
    void readLimits(quint8 page, quint8 number);
    void readDefault(quint8 page, quint8 number);
    void readScaling(quint8 page, quint8 number);
    // Plaintexts (ScanPlaintexts.cpp): each index's texts once, handed to every parameter that
    // names it when the last of them has arrived.
    using PlaintextKey = std::pair<quint16, int>;
    void readPlaintexts(quint8 page, quint8 number, const PlaintextIndicesData &indices);
    void readPlaintextTable(const PlaintextKey &key, const QString &what);
    void onPlaintextDefinition(const PlaintextKey &key, quint8 definition, const Reply &reply,
                               const QString &what);
    void plaintextAnswered(const PlaintextKey &key);
    void deliverPlaintexts(const ScanPlaintextTable &table, quint8 page, quint8 number);
    void deliverUnfinishedPlaintexts();
    // Values (ScanValues.cpp): one read for a value that is not set-programmable; for one
    // that is, all sets in one read, split in halves where the drive says they differ.
    void readValues(quint8 page, quint8 number, bool setProgrammable);
    void readSetValues(quint8 page, quint8 number, quint8 setMask);
    bool wantsValue(quint8 page, quint8 number) const;
    QString parameterWhat(quint8 page, quint8 number, const QString &detail = {}) const;
    // A value or default outside the parameter's limits, where they are known.
    QString implausibleRead(quint8 page, quint8 number, const Reply &reply) const;
    QString failure(const QString &label, const Reply &reply) const;
    // Records a failed read about a parameter or a plaintext table (both have errors and
    // unanswered): the drive's refusal is its word, anything else leaves the item unread.
    template<typename Item> void fail(Item &item, const QString &label, const Reply &reply) const
    {
        item.errors.append(failure(label, reply));
        if (reply.ok() || !reply.isAnswer())
            ++item.unanswered;
    }
    // A value's failed read: as fail(), except that a value the drive changes by itself (a live
    // value, a counter) cannot be confirmed by reading it again on a line with errors. Left
    // without a value and saying so, it does not leave the drive unread: it is no setting.
    void failValue(ScanParameter &parameter, const QString &label, const Reply &reply) const;

    // The metadata cache (ScanCache.cpp).
    bool probeCache();
    void onProbed();
    void adoptCached(const DriveDescription &cached);
    void readVariableMetadata(quint8 page, const ParameterDescription &parameter);
    bool mayStore() const;
    void store(const DriveDescription &drive);

    RequestSink &m_sink;
    const ScanOptions m_options;
    const Language m_language;
    std::unique_ptr<MetadataCache> m_cache; // null when the scan neither reads nor writes it
    ScanState m_state;
    std::deque<Queued> m_queue; // not yet handed to the sink
    quint64 m_lineErrorsAtStart = 0;  // RequestSink::lineErrors() when the scan started
    bool m_lineShowedErrors = false;
    std::vector<Kept> m_kept;         // answers kept unconfirmed while the line was clean
    // Unsettled once: asked again after everything else, when a burst of noise has passed.
    std::vector<Unsettled> m_later;
    std::vector<Probe> m_probes;
    int m_probesPending = 0;
    std::optional<DriveKind> m_cachedKind; // the kind whose cached metadata is used
    QStringList m_warnings;
    int m_submitted = 0;                // handed to the sink, `done` not yet run
    int m_enqueued = 0;
    int m_done = 0;
    // What the answers to properties and plaintext indices brought so far: the reads of
    // values and of plaintexts each one led to, for the estimate of those still to come.
    struct FollowUps {
        int asked = 0;    // properties (or plaintext indices) requests enqueued
        int answered = 0; // ... and answered
        int reads = 0;    // value (or plaintext) reads enqueued
        double perAnswer(double guess) const { return answered ? double(reads) / answered : guess; }
    };
    FollowUps m_values;
    FollowUps m_plaintexts;
    bool m_started = false;
    bool m_finished = false;
    bool m_submitting = false; // a sink may run `done` inside submit()
};

} // namespace DriveDesk
