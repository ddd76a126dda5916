#pragma once

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QThread>

#include <utility>

namespace DriveDesk {

// Runs `withResult(result)` in `context`'s thread once `future` has finished with a result, or
// `withoutResult()` when it ended without one (cancelled, or its job was dropped). Nothing runs
// once `context` is gone. Call it in `context`'s thread.
//
// This is the way a front end takes a client's answer, instead of QFuture::then(context, ...):
// in Qt 6.4 that continuation is kept after it ran, and a future that another thread finishes
// while the continuation is being attached runs it twice (once in setContinuation, which sees
// the future finished, and again from reportFinished's runContinuation). The second run meets
// the promise the first one moved away and crashes in reportStarted. A QFutureWatcher is told of
// the end once, by an event to its own thread.
template<typename T, typename WithResult, typename WithoutResult>
void whenFinished(const QFuture<T> &future, QObject *context, WithResult &&withResult,
                  WithoutResult &&withoutResult)
{
    Q_ASSERT(context && context->thread() == QThread::currentThread());
    auto *watcher = new QFutureWatcher<T>(context);
    QObject::connect(watcher, &QFutureWatcherBase::finished, context,
                     [watcher, withResult = std::forward<WithResult>(withResult),
                      withoutResult = std::forward<WithoutResult>(withoutResult)]() mutable {
                         watcher->deleteLater();
                         const QFuture<T> done = watcher->future();
                         if (done.resultCount() > 0)
                             withResult(done.result());
                         else
                             withoutResult();
                     });
    watcher->setFuture(future);
}

// The same where an answer that never comes needs nothing done: the request's own failure is a
// result (a Reply that says so), so only a dropped job ends without one.
template<typename T, typename WithResult>
void whenFinished(const QFuture<T> &future, QObject *context, WithResult &&withResult)
{
    whenFinished(future, context, std::forward<WithResult>(withResult), [] {});
}

} // namespace DriveDesk
