#pragma once

#include "client/RequestJob.h"
#include "scope/ScopeChannel.h"
#include "scope/ScopeSample.h"

#include <QList>
#include <QString>

#include <memory>

namespace DriveDesk {

struct ConnectionSettings;

// The drive's offline scope records as read.
struct ScopeOfflineRecords
{
    // Record i at time i * periodMs: the drive gives no time for a record (seed 003 5.36: the
    // timestamp field of the answer carries the highest index), so the spacing is the caller's.
    QList<ScopeSample> samples;
    qint64 expected = 0; // records the drive said it holds
    // Records whose channel 3 or 4 did not fit the 16 bits a sample keeps for them: stored
    // at the nearest 16-bit value, and said so.
    qint64 clipped = 0;
    QString error; // why reading stopped early, in words; empty when every record was read
};

struct ScopeRecording;

// The records as a recording to view or export: `channels` as they are assigned now (the drive
// does not say what they were when it recorded), `connection` named with the millisecond
// spacing assumed.
std::unique_ptr<ScopeRecording> offlineRecording(const ScopeOfflineRecords &records,
                                                 const ScopeChannels &channels,
                                                 const QString &connection);

// Reads the offline records of service 21 (DIN66019II; over HSP5 only with DriveDesk's
// extensions), record 0 first, whose answer says how many there are, then the rest with
// progress. requestStop() ends it with what was read; a cancel drops it.
class ScopeOfflineJob : public RequestJob<ScopeOfflineRecords>
{
public:
    explicit ScopeOfflineJob(qint64 periodMs = 1);

    // Whether the connection carries service 21, so that reading the records is worth
    // offering: the codec the client speaks with decides, as it does when the job runs.
    static bool isCarriedBy(const ConnectionSettings &settings);

private:
    void start() override;
    void stopping() override;
    void request(quint16 index);
    void handle(quint16 index, const Reply &reply);
    void finish();

    const qint64 m_periodMs;
    ScopeOfflineRecords m_result;
    quint16 m_next = 0;
};

} // namespace DriveDesk
