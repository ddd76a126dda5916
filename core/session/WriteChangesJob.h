#pragma once

#include "client/RequestJob.h"
#include "session/ValueChange.h"

#include <QList>

#include <atomic>
#include <memory>

namespace DriveDesk {

// How a change's writes depend on the other changes' writes of a list. A write that was not
// answered may be sent again, so "after" means after the other's answer.
struct WriteOrder
{
    bool afterEarlier = true; // its writes wait for every earlier write (it follows from them)
    bool beforeLater = true;  // every later write waits for its writes (it selects them)
};

// Writes a list of changes, each read back; result i is the outcome of changes[i]. Over HSP5
// changes to different parameters go on their way together, up to kJobRequestWindow requests,
// so that the drive's pipeline stays full, as far as each change's WriteOrder lets them (the
// read-backs go on meanwhile, each change's right behind its writes: sendValueChange()); the
// writes of changes started together go out ahead of their read-backs. DIN66019II (half
// duplex) writes one change after the other. A lost connection stops the job. requestStop()
// sends nothing more and still reports every change on its way, so that every change without
// a result was never sent. Copying a set and downloading a parameter file both write this way.
class WriteChangesJob : public RequestJob<WriteOutcome>
{
public:
    // `order[i]` for changes[i]; a list shorter than `changes` gives the rest WriteOrder{}, so
    // that by default one change follows the other.
    WriteChangesJob(Protocol protocol, QList<ValueChange> changes, QList<WriteOrder> order = {});
    ~WriteChangesJob() override;

    int total() const { return int(m_changes.size()); }

    // Only the changes before `count` may be sent (all of them unless told otherwise): a caller
    // that journals the rest while the first ones are written lets them go when their entries
    // are stored, then DriveClient::resume()s the job. Thread: any.
    void release(qsizetype count) { m_released.store(count, std::memory_order_release); }

private:
    class RequestWindow;

    void start() override;
    void resumed() override;
    void sendMore();
    void endIfDone();
    bool mayStart(qsizetype index) const;
    void finished(qsizetype index, const WriteOutcome &outcome);

    const Protocol m_protocol;
    const QList<ValueChange> m_changes;
    const QList<WriteOrder> m_order;
    std::unique_ptr<RequestWindow> m_window;
    qsizetype m_next = 0;
    QList<qsizetype> m_onTheWay; // indices of the changes sent and not yet finished
    QList<qsizetype> m_writing;  // of those, the ones whose writes are not all answered yet
    std::atomic<qsizetype> m_released;
    int m_done = 0;
    bool m_connectionFailed = false;
    bool m_sending = false;
    bool m_sendAgain = false; // a callback asked for more while the loop was sending
};

} // namespace DriveDesk
