#include "ScopePolling.h"

#include "link/PreciseAlarm.h"

#include <QCoreApplication>
#include <QMutexLocker>

#include <algorithm>
#include <cmath>

namespace DriveDesk {

namespace {

// How the polls' grid follows the drive (ScopePollJob::learnSpacing()).
constexpr int kShiftDivisor = 8;  // a repeated sample moves the grid an eighth of a tick earlier
constexpr int kRepeatsClose = 32; // a repeat within this many polls of the last one...
constexpr int kWidenDivisor = 8;  // ...widens the grid by an eighth of a tick,
constexpr qint64 kMostTicks = 2;  // up to two ticks;
constexpr int kDistinctBeforeNarrowing = 128; // a run of new samples narrows it again,
constexpr int kNarrowDivisor = 32;            // by a thirty-second, down to one tick
constexpr int kNearSlotDivisor = 4; // a grid instant nearer than a quarter step is skipped

} // namespace

void ScopeInbox::put(const ScopePoll &poll)
{
    const QMutexLocker locker(&m_mutex);
    m_polls.append(poll);
}

void ScopeInbox::count(const ScopePollCounts &counts)
{
    const QMutexLocker locker(&m_mutex);
    m_counts = counts;
}

QList<ScopePoll> ScopeInbox::take(ScopePollCounts *counts)
{
    const QMutexLocker locker(&m_mutex);
    if (counts)
        *counts = m_counts;
    QList<ScopePoll> polls;
    polls.swap(m_polls);
    return polls;
}

ScopePollJob::ScopePollJob(std::shared_ptr<ScopeInbox> inbox, ScopePollOptions options)
    : m_inbox(std::move(inbox))
    , m_options(options)
{
}

ScopePollJob::~ScopePollJob() = default;

void ScopePollJob::DeleteLater::operator()(PreciseAlarm *alarm) const
{
    alarm->deleteLater();
}

void ScopePollJob::start()
{
    if (!sink().supports(Service::Scope, Access::Read)) {
        m_end.reason = QCoreApplication::translate(
            "ScopePollJob", "This connection cannot carry scope data (service 18).");
        return finish();
    }
    m_clock.start();
    m_spacingNs = std::max<qint64>(m_options.tickNs, 0);
    m_pace.reset(new PreciseAlarm);
    QObject::connect(m_pace.get(), &PreciseAlarm::timeout, [this] { sendMore(); });
    sendMore();
}

void ScopePollJob::stopping()
{
    // Polls change nothing on the drive: the queued ones can go.
    m_stopping = true;
    sink().cancelPending();
    sendMore();
}

void ScopePollJob::sendMore()
{
    // A request that cannot be sent answers at once, from within submit(): no recursion.
    if (m_sending || hasEnded())
        return;
    m_sending = true;
    m_stopping = m_stopping || isCancelled() || isStopRequested();
    const int inFlight = std::max(1, m_options.inFlight);
    while (!m_stopping && m_onTheWay < inFlight) {
        const qint64 nowNs = m_clock.nsecsElapsed();
        if (const qint64 waitNs = waitBeforeNextNs(nowNs); waitNs > 0) {
            if (!m_pace->isActive())
                m_pace->start(waitNs);
            break;
        }
        if (m_options.maxRateHz > 0) {
            // A late timer may make up one period, no more: after a stall the polls go on at
            // the rate, not in a burst that would exceed it.
            const auto periodNs = qint64(1e9 / m_options.maxRateHz);
            m_nextDueNs = std::max(m_nextDueNs, nowNs - periodNs) + periodNs;
        }
        takeSlot(nowNs);
        const qint64 sequence = m_sent++;
        ++m_onTheWay;
        sink().submit(Telegram::request(Service::Scope, Access::Read, ScopeData{}),
                      [this, sequence](const Reply &reply) { handle(sequence, reply); });
    }
    m_sending = false;
    // A stop asked for from another thread is noticed with the next answer or the pace timer:
    // one of them is always pending while the job runs.
    if (m_stopping && m_onTheWay == 0)
        finish();
}

qint64 ScopePollJob::waitBeforeNextNs(qint64 nowNs) const
{
    qint64 waitNs = 0;
    if (m_options.maxRateHz > 0)
        waitNs = m_nextDueNs - nowNs;
    if (m_sent > 0 && m_spacingNs > 0)
        waitNs = std::max(waitNs, m_slotNs - nowNs);
    return waitNs;
}

// The polls go on a grid of one tick (or more, learnSpacing()): a poll sent now takes the slot
// it falls in, and the next may go at the grid's next instant. A grid keeps its place against
// the drive's clock, where spacing each poll from the one before would add every late wake-up
// to the step. A poll sent between two instants (when an answer freed its place) makes the
// next instant wait a step when it is too near to be sure of a tick of its own.
void ScopePollJob::takeSlot(qint64 nowNs)
{
    if (m_spacingNs <= 0)
        return;
    if (m_sent == 0)
        m_slotNs = nowNs;
    if (nowNs >= m_slotNs)
        m_slotNs += ((nowNs - m_slotNs) / m_spacingNs + 1) * m_spacingNs;
    if (m_slotNs - nowNs < m_spacingNs / kNearSlotDivisor)
        m_slotNs += m_spacingNs;
}

void ScopePollJob::handle(qint64 sequence, const Reply &reply)
{
    --m_onTheWay;
    std::optional<ScopePoll> poll;
    if (const auto *data = reply.data<ScopeData>()) {
        poll = ScopePoll{data->timestamp, m_clock.elapsed(), data->wide, data->narrow};
        ++m_end.counts.answered;
        m_lostInARow = 0;
    } else if (reply.isConnectionFailure()) {
        if (!isCancelled() && !m_stopping) {
            m_end.reason = reply.message();
            m_end.linkLost = true;
        }
        m_stopping = true;
    } else if (reply.status == Reply::Status::Refused) {
        ++m_end.counts.failed;
        m_end.counts.lastProblem = reply.message();
    } else {
        ++m_end.counts.lost;
        m_end.counts.lastProblem = reply.message();
        if (++m_lostInARow >= std::max(1, m_options.lostInARowLimit) && !m_stopping) {
            m_end.reason = QCoreApplication::translate(
                               "ScopePollJob", "The drive stopped answering: %1")
                               .arg(reply.message());
            m_end.linkLost = true;
            m_stopping = true;
        }
    }
    m_waiting.emplace(sequence, poll);
    release();
    sendMore();
}

void ScopePollJob::release()
{
    bool any = false;
    for (auto it = m_waiting.begin(); it != m_waiting.end() && it->first == m_nextRelease;
         it = m_waiting.erase(it)) {
        ++m_nextRelease;
        if (it->second) {
            learnSpacing(*it->second);
            m_inbox->put(*it->second);
        } else {
            m_lastTimestamp.reset();
        }
        any = true;
    }
    if (any)
        m_inbox->count(m_end.counts);
}

// Two polls in a row that found the same tick of the drive's clock: the first reached the drive
// late in its tick, and a late wake-up pushed it into the next one's. The grid moves earlier in
// the tick. Repeats that keep coming say the polls reach the drive less evenly than they leave
// (a line or an adapter that bunches them): the grid's step widens, and narrows again after a
// long run without.
void ScopePollJob::learnSpacing(const ScopePoll &poll)
{
    const bool repeated = m_lastTimestamp == poll.timestamp;
    m_lastTimestamp = poll.timestamp;
    const qint64 tickNs = m_options.tickNs;
    if (tickNs <= 0)
        return;
    if (repeated) {
        m_slotNs -= tickNs / kShiftDivisor;
        if (m_distinctInARow < kRepeatsClose)
            m_spacingNs = std::min(m_spacingNs + tickNs / kWidenDivisor, kMostTicks * tickNs);
        m_distinctInARow = 0;
    } else if (++m_distinctInARow >= kDistinctBeforeNarrowing) {
        m_spacingNs = std::max(m_spacingNs - tickNs / kNarrowDivisor, tickNs);
        // Counted on from past "close": a repeat after a narrowing is not a close one.
        m_distinctInARow = kRepeatsClose;
    }
}

void ScopePollJob::finish()
{
    if (hasEnded())
        return;
    if (m_pace)
        m_pace->stop();
    // Whatever is still held waits for an answer that will not come: let it out in order.
    for (const auto &[sequence, poll] : m_waiting) {
        if (poll)
            m_inbox->put(*poll);
    }
    m_waiting.clear();
    m_inbox->count(m_end.counts);
    promise().addResult(m_end);
    end();
}

} // namespace DriveDesk
