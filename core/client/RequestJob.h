#pragma once

#include "client/RequestSink.h"

#include <QFuture>
#include <QPromise>

#include <atomic>
#include <functional>
#include <memory>

namespace DriveDesk {

// A job of many requests (reading a batch of values, a write with its read-back, copying a
// set) that runs in the client's thread on the client's queue, as the drive scan does, and
// reports through a QFuture: results as they come, progress, and cancel.
// Thread: made anywhere, handed to DriveClient::run(); from then on every call is in the
// client's thread. The client keeps the job alive until it ended.
class RequestJobBase
{
public:
    virtual ~RequestJobBase() = default;

    // The future's untyped view, so that the client can watch it for a cancel.
    virtual QFuture<void> untypedFuture() const = 0;

    // Starts the job on `sink`; `ended` runs once, right after the job finished its future.
    void begin(RequestSink &sink, std::function<void()> ended);
    // The future was cancelled: the job sends nothing more and ends once what it has on the
    // way is back; what comes back then is no longer reported.
    void cancel();
    // Asks the job to send nothing more but to report what it has on the way before it ends,
    // for a job whose every result matters once its request was sent (a write that took effect
    // must reach the undo history). Thread: any.
    void requestStop() { m_stopRequested = true; }
    // Ends the job now with what it has, for a job whose partial result is worth having (a scan:
    // what it read, incompleteReason "cancelled"); others go on. Thread: the client's.
    virtual void finishEarly() {}
    // Something the job waits for outside the client changed (DriveClient::resume()): a job
    // that holds requests back until another thread lets them go looks again. Thread: the
    // client's.
    virtual void resumed() {}

protected:
    virtual void start() = 0;
    // Called once on a cancel; a job whose requests may be dropped drops them here.
    virtual void stopping() {}

    RequestSink &sink() const { return *m_sink; }
    bool isCancelled() const { return m_cancelled; }
    bool isStopRequested() const { return m_stopRequested; }
    bool hasEnded() const { return m_ended; }
    // Finishes the future and lets the client release the job. Only the first call counts.
    void end();

private:
    virtual void finishFuture() = 0;

    RequestSink *m_sink = nullptr;
    std::function<void()> m_onEnded;
    bool m_cancelled = false;
    bool m_ended = false;
    std::atomic<bool> m_stopRequested = false;
};

// The typed half: the promise behind the job's future.
template<typename Result>
class RequestJob : public RequestJobBase
{
public:
    using ResultType = Result;

    RequestJob() { m_promise.start(); }
    QFuture<Result> future() { return m_promise.future(); }
    QFuture<void> untypedFuture() const override { return QFuture<void>(m_future); }

protected:
    QPromise<Result> &promise() { return m_promise; }

private:
    void finishFuture() override { m_promise.finish(); }

    QPromise<Result> m_promise;
    const QFuture<Result> m_future = m_promise.future();
};

inline void RequestJobBase::begin(RequestSink &sink, std::function<void()> ended)
{
    m_sink = &sink;
    m_onEnded = std::move(ended);
    if (untypedFuture().isCanceled()) {
        m_cancelled = true;
        end();
        return;
    }
    start();
}

inline void RequestJobBase::cancel()
{
    if (m_cancelled || m_ended)
        return;
    m_cancelled = true;
    stopping();
}

inline void RequestJobBase::end()
{
    if (m_ended)
        return;
    m_ended = true;
    finishFuture();
    // The callback holds the last reference to this job: call it from a moved-out copy.
    const std::function<void()> ended = std::move(m_onEnded);
    m_onEnded = nullptr;
    if (ended)
        ended();
}

} // namespace DriveDesk
