#pragma once

#include "client/DriveClient.h"
#include "client/RequestSink.h"
#include "client/ScanState.h"

#include <QObject>

#include <deque>
#include <functional>

namespace DriveDesk {

// Discovers groups, parameters, metadata and values of a drive through a RequestSink.
// A state machine driven by the sink's `done` callbacks; it lives in the sink's thread.
// finished() is emitted exactly once; a receiver that wants the scanner gone uses deleteLater().
class DriveScanner : public QObject
{
    Q_OBJECT
public:
    DriveScanner(RequestSink &sink, ScanOptions options, Language language,
                 QObject *parent = nullptr);

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

    struct QueuedRequest {
        Telegram telegram;
        QString what; // for progress
        Handler handle;
    };

    void enqueue(Service service, ServiceData data, QString what, Handler handle);
    // A read about one existing parameter: a failure goes to its errors, prefixed by `label`.
    template<typename T>
    void readParameter(quint8 page, quint8 number, Service service, ServiceData data,
                       const QString &label, std::function<void(ScanParameter &, const T &)> apply);
    void submitQueued();
    void onReplied(const Reply &reply, const QString &what, const Handler &handle);
    void finish(const QString &reason);
    int total() const;

    void probeGroup(quint8 page);
    void onGroupProperties(quint8 page, const Reply &reply);
    void askNames(quint8 page);
    void askName(quint8 page, quint8 number);
    void onParameterName(quint8 page, quint8 number, const Reply &reply);
    void readMetadata(quint8 page, quint8 number);
    void readValues(quint8 page, quint8 number, bool setProgrammable);
    void readPlaintexts(quint8 page, quint8 number, const PlaintextIndicesData &indices);
    void readPlaintextEntries(quint8 page, quint8 number, quint16 index, quint8 definition,
                              int count);
    QString parameterWhat(quint8 page, quint8 number, const QString &detail = {}) const;
    QString failure(const QString &label, const Reply &reply) const;

    RequestSink &m_sink;
    const ScanOptions m_options;
    const Language m_language;
    ScanState m_state;
    std::deque<QueuedRequest> m_queue; // not yet handed to the sink
    int m_submitted = 0;                // handed to the sink, `done` not yet run
    int m_enqueued = 0;
    int m_done = 0;
    bool m_started = false;
    bool m_finished = false;
    bool m_submitting = false; // a sink may run `done` inside submit()
};

} // namespace DriveDesk
