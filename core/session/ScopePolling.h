#pragma once

#include "client/RequestJob.h"
#include "scope/ScopeSample.h"

#include <QElapsedTimer>
#include <QList>
#include <QMetaType>
#include <QMutex>
#include <QString>

#include <map>
#include <memory>
#include <optional>


namespace DriveDesk {

class PreciseAlarm;

// One service-18 answer as it came: the drive's 16-bit timestamp, the four raw channels, and
// the host's clock when it arrived (for unwrapping across long gaps, ScopeClock).
struct ScopePoll
{
    quint16 timestamp = 0;
    qint64 hostMs = 0;
    std::array<qint32, 2> wide{};
    std::array<qint16, 2> narrow{};
};

// How the polls went so far.
struct ScopePollCounts
{
    qint64 answered = 0; // polls that brought a sample
    qint64 lost = 0;     // no valid answer after every attempt: the sample is missing
    qint64 failed = 0;   // refused by the drive
    QString lastProblem; // the latest lost or failed poll, in words
};

// Where the polling job leaves its samples for the thread that stores them: the job writes in
// the client's thread, the recorder takes them out in its own, in batches.
// Thread: every method, any thread.
class ScopeInbox
{
public:
    void put(const ScopePoll &poll);
    void count(const ScopePollCounts &counts);
    // Everything put since the last take, in poll order, and the counts now.
    QList<ScopePoll> take(ScopePollCounts *counts = nullptr);

private:
    mutable QMutex m_mutex;
    QList<ScopePoll> m_polls;
    ScopePollCounts m_counts;
};

struct ScopePollOptions
{
    // How many polls are on the way at a time: up to 4 over HSP5, which answers in full
    // duplex; DIN66019II carries one at a time whatever this says.
    int inFlight = 4;
    double maxRateHz = 0; // 0: as fast as the link allows
    // The drive's clock tick. Two polls that reach the drive within one tick may find the same
    // sample, and the second one's line time brings nothing: polls go one to a tick (further
    // apart while answers repeat samples all the same). 0: as the answers come.
    qint64 tickNs = 1'000'000;
    // Polls given up one after the other before the recording counts the drive as gone.
    int lostInARowLimit = 3;
};

// Why the polling ended.
struct ScopePollEnd
{
    ScopePollCounts counts;
    QString reason;     // empty when stopped on request; otherwise why, in words
    bool linkLost = false;
};

// Polls service 18 until stopped (requestStop() or cancel), leaving every sample in the inbox
// in the order the polls were sent, whatever order their answers came in. A poll the drive
// refuses or never answers is counted and the polling goes on; the link going away, or
// lostInARowLimit polls given up one after another, ends it. Runs in the client's thread.
class ScopePollJob : public RequestJob<ScopePollEnd>
{
public:
    ScopePollJob(std::shared_ptr<ScopeInbox> inbox, ScopePollOptions options = {});
    ~ScopePollJob() override;

private:
    void start() override;
    void stopping() override;
    void sendMore();
    void handle(qint64 sequence, const Reply &reply);
    void release();
    void learnSpacing(const ScopePoll &poll);
    void takeSlot(qint64 nowNs);
    qint64 waitBeforeNextNs(qint64 nowNs) const;
    void finish();

    const std::shared_ptr<ScopeInbox> m_inbox;
    const ScopePollOptions m_options;
    QElapsedTimer m_clock;
    // Made in the client's thread for the spacing and the rate limit, and given back to it: the
    // job itself may end in another thread, where the alarm's notifier cannot be taken down.
    struct DeleteLater
    {
        void operator()(PreciseAlarm *alarm) const;
    };
    std::unique_ptr<PreciseAlarm, DeleteLater> m_pace;
    qint64 m_sent = 0;
    qint64 m_nextDueNs = 0; // the rate limit's next poll, on m_clock
    // The polls' grid (ScopePolling.cpp): the next instant a poll may go, and the step.
    qint64 m_slotNs = 0;
    qint64 m_spacingNs = 0; // from options.tickNs, wider while samples repeat
    int m_distinctInARow = 1 << 16; // new samples since the last repeat, or the last narrowing
    std::optional<quint16> m_lastTimestamp; // of the poll released last, if it brought one
    qint64 m_nextRelease = 0;
    // Answers that came before an earlier poll's: held until that one is in.
    std::map<qint64, std::optional<ScopePoll>> m_waiting;
    int m_onTheWay = 0;
    int m_lostInARow = 0;
    ScopePollEnd m_end;
    bool m_stopping = false;
    bool m_sending = false;
};

} // namespace DriveDesk

Q_DECLARE_METATYPE(DriveDesk::ScopePollEnd)
