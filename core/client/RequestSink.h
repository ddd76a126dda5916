#pragma once

#include "client/Reply.h"

#include <functional>

namespace DriveDesk {

// How many requests a job keeps on the client's queue at a time: enough to keep the drive's
// four HSP5 requests on the wire, few enough that a write the user asks for meanwhile is not
// stuck behind hundreds of a job's reads.
inline constexpr int kJobRequestWindow = 8;

// Where the drive scan and other multi-step jobs put their requests. The client worker is
// one; a test can put a simulated drive behind another.
// Thread: submit() and `done` both run in the sink's thread.
class RequestSink
{
public:
    virtual ~RequestSink() = default;
    // Queues a request; `done` runs once when it finished in any way (ok, refused, failed,
    // cancelled). The sink keeps at most as many in flight as the protocol allows.
    virtual void submit(const Telegram &request, std::function<void(const Reply &)> done) = 0;
    // Queues a probe: does a drive answer at all? One attempt with a short wait (the time the
    // request and a short answer take on the line); `heard` says that something came back, even
    // a garbled answer. A sink without probes of its own sends an ordinary request.
    virtual void probe(const Telegram &request,
                       std::function<void(const Reply &reply, bool heard)> done)
    {
        submit(request, [done = std::move(done)](const Reply &reply) { done(reply, false); });
    }
    // Cancels every request this sink still holds; their `done` run with Cancelled.
    virtual void cancelPending() = 0;
    // Whether the protocol, as this connection is set up, can carry the request at all. A job
    // asks before it sends anything beyond what every drive knows (HSP5: seed 000's services).
    virtual bool supports(Service service, Access access) const = 0;
    // Errors the connection has noted on the line since it was made: checksum and framing
    // errors, timeouts, answers that did not match their request. A job compares two readings
    // to learn whether the line showed errors in between. A sink that cannot tell says 0.
    virtual quint64 lineErrors() const { return 0; }
};

} // namespace DriveDesk
