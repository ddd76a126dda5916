#include "WriteChangesJob.h"

#include <algorithm>
#include <deque>

namespace DriveDesk {

// The job's requests on their way: at most kJobRequestWindow on the client's queue, the rest
// held here, writes ahead of read-backs, so that a write that others wait for is not stuck
// behind the read-backs of changes that no longer hold anything up.
class WriteChangesJob::RequestWindow : public RequestSink
{
public:
    // `idle` runs as the last thing the window does after it passed requests on, so that the
    // job may end (and be deleted) there.
    RequestWindow(RequestSink &sink, std::function<void()> idle)
        : m_sink(sink)
        , m_idle(std::move(idle))
    {}

    bool isPassing() const { return m_passing; }

    // While gathering, what is submitted is only held: the writes of the changes started
    // together then go on the line ahead of the read-backs that follow each of them.
    void gather() { m_gathering = true; }
    void release()
    {
        m_gathering = false;
        pass();
    }

    // Submitted and not finished, held here or on the client's queue.
    int outstanding() const { return m_onQueue + int(m_held.size()); }

    void submit(const Telegram &request, std::function<void(const Reply &)> done) override
    {
        Held held{request, std::move(done)};
        if (!request.isWrite())
            m_held.push_back(std::move(held));
        else
            m_held.insert(std::find_if(m_held.begin(), m_held.end(),
                                       [](const Held &h) { return !h.request.isWrite(); }),
                          std::move(held));
        pass();
    }
    void cancelPending() override { m_sink.cancelPending(); }
    bool supports(Service service, Access access) const override
    {
        return m_sink.supports(service, access);
    }
    quint64 lineErrors() const override { return m_sink.lineErrors(); }

private:
    struct Held
    {
        Telegram request;
        std::function<void(const Reply &)> done;
    };

    void pass()
    {
        // A request that cannot be sent answers at once, and its callback may submit more:
        // the outermost call passes those on too.
        if (m_passing || m_gathering)
            return;
        m_passing = true;
        while (m_onQueue < kJobRequestWindow && !m_held.empty()) {
            Held next = std::move(m_held.front());
            m_held.pop_front();
            ++m_onQueue;
            m_sink.submit(next.request, [this, done = std::move(next.done)](const Reply &reply) {
                --m_onQueue;
                pass();
                done(reply); // last: it may end the job
            });
        }
        m_passing = false;
        m_idle();
    }

    RequestSink &m_sink;
    const std::function<void()> m_idle;
    bool m_passing = false;
    bool m_gathering = false;
    int m_onQueue = 0;
    std::deque<Held> m_held;
};

WriteChangesJob::WriteChangesJob(Protocol protocol, QList<ValueChange> changes,
                                 QList<WriteOrder> order)
    : m_protocol(protocol)
    , m_changes(std::move(changes))
    , m_order(std::move(order))
    , m_released(m_changes.size())
{
    promise().setProgressRange(0, total());
}

WriteChangesJob::~WriteChangesJob() = default;

void WriteChangesJob::start()
{
    m_window = std::make_unique<RequestWindow>(sink(), [this] { endIfDone(); });
    sendMore();
}

void WriteChangesJob::resumed()
{
    if (!hasEnded())
        sendMore();
}

bool WriteChangesJob::mayStart(qsizetype index) const
{
    if (index >= m_released.load(std::memory_order_acquire))
        return false;
    if (m_onTheWay.isEmpty())
        return true;
    // Half duplex: one request at a time on the line anyway, and one change after the other
    // keeps the order of the writes the order of the list.
    if (m_protocol != Protocol::Hsp5 || m_window->outstanding() >= kJobRequestWindow)
        return false;
    // Read-backs may share the line with anything: a change waits only for the writes it
    // depends on to be answered. A retried write could otherwise reach the drive after one
    // sent later.
    const bool afterEarlier = m_order.value(index).afterEarlier;
    return std::none_of(m_onTheWay.begin(), m_onTheWay.end(), [&](qsizetype other) {
        if (m_changes.at(other).address == m_changes.at(index).address)
            return true;
        return m_writing.contains(other) && (afterEarlier || m_order.value(other).beforeLater);
    });
}

void WriteChangesJob::sendMore()
{
    // A change's callback may run at once (a request that cannot be sent answers at once, as
    // the window lets it go): the loop below then goes round again with what that callback
    // changed, and ends the job itself.
    if (m_sending) {
        m_sendAgain = true;
        return;
    }
    m_sending = true;
    do {
        m_sendAgain = false;
        m_window->gather();
        while (!isCancelled() && !isStopRequested() && !m_connectionFailed
               && m_next < m_changes.size() && mayStart(m_next)) {
            const qsizetype index = m_next++;
            m_onTheWay << index;
            m_writing << index;
            sendValueChange(
                *m_window, m_protocol, m_changes.at(index),
                [this, index](const WriteOutcome &outcome) { finished(index, outcome); },
                [this, index] {
                    m_writing.removeOne(index);
                    sendMore();
                });
        }
        m_window->release();
    } while (m_sendAgain);
    m_sending = false;
    endIfDone();
}

void WriteChangesJob::endIfDone()
{
    // Not from within a loop that still uses the job: end() may delete it.
    if (m_sending || m_window->isPassing() || !m_onTheWay.isEmpty())
        return;
    if (isCancelled() || isStopRequested() || m_connectionFailed || m_next >= m_changes.size())
        end();
}

void WriteChangesJob::finished(qsizetype index, const WriteOutcome &outcome)
{
    m_onTheWay.removeOne(index);
    m_writing.removeOne(index);
    if (!isCancelled()) {
        promise().addResult(outcome, int(index));
        promise().setProgressValue(++m_done);
    }
    m_connectionFailed = m_connectionFailed || outcome.connectionFailed;
    sendMore();
}

} // namespace DriveDesk
