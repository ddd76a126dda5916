#include "ScopePolling.h"

#include <QCoreApplication>
#include <QMutexLocker>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace DriveDesk {

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

void ScopePollJob::start()
{
    if (!sink().supports(Service::Scope, Access::Read)) {
        m_end.reason = QCoreApplication::translate(
            "ScopePollJob", "This connection cannot carry scope data (service 18).");
        return finish();
    }
    m_clock.start();
    m_pace = std::make_unique<QTimer>();
    m_pace->setSingleShot(true);
    m_pace->setTimerType(Qt::PreciseTimer);
    QObject::connect(m_pace.get(), &QTimer::timeout, [this] { sendMore(); });
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
        if (m_options.maxRateHz > 0) {
            const auto periodNs = qint64(1e9 / m_options.maxRateHz);
            const qint64 nowNs = m_clock.nsecsElapsed();
            const qint64 waitNs = m_nextDueNs - nowNs;
            if (waitNs > 0) {
                if (!m_pace->isActive())
                    m_pace->start(int(std::ceil(double(waitNs) / 1e6)));
                break;
            }
            // A late timer may make up one period, no more: after a stall the polls go on at
            // the rate, not in a burst that would exceed it.
            m_nextDueNs = std::max(m_nextDueNs, nowNs - periodNs) + periodNs;
        }
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
        if (it->second)
            m_inbox->put(*it->second);
        any = true;
    }
    if (any)
        m_inbox->count(m_end.counts);
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
