#pragma once

#include "client/Reply.h"

#include <QFuture>
#include <QFutureWatcher>

#include <utility>

namespace DriveDesk {

// Hands a request's reply to `handle` in `owner`'s thread once it arrives, and never after
// `owner` is gone (the watcher is its child). A future that ends without a result, because it
// was cancelled before it was sent, reports a Cancelled reply.
template<typename Handler>
void whenReplied(QObject *owner, const QFuture<Reply> &future, Handler handle)
{
    auto *watcher = new QFutureWatcher<Reply>(owner);
    QObject::connect(watcher, &QFutureWatcherBase::finished, owner,
                     [watcher, handle = std::move(handle)]() mutable {
                         const QFuture<Reply> done = watcher->future();
                         Reply reply;
                         reply.status = Reply::Status::Cancelled;
                         if (!done.isCanceled() && done.resultCount() > 0)
                             reply = done.result();
                         watcher->deleteLater();
                         handle(reply);
                     });
    watcher->setFuture(future);
}

} // namespace DriveDesk
