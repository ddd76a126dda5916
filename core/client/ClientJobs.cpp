// The facade's requests as QFutures: each holds its QPromise in the worker thread and watches
// its future, so that cancelling the future reaches the request.
#include "ClientWorker.h"

#include <QFutureWatcher>

namespace DriveDesk {

void ClientWorker::submitForFuture(const Telegram &request,
                                   std::shared_ptr<QPromise<Reply>> promise)
{
    if (promise->future().isCanceled()) {
        promise->finish();
        return;
    }
    auto *watcher = new QFutureWatcher<Reply>(this);
    const quint64 ticket = submitRequest(request, {}, [promise, watcher](const Reply &reply, bool) {
        promise->addResult(reply);
        promise->finish();
        watcher->deleteLater();
    });
    connect(watcher, &QFutureWatcherBase::canceled, this, [this, ticket] { cancelTicket(ticket); });
    watcher->setFuture(promise->future());
}

void ClientWorker::finishJobsEarly()
{
    const std::vector<std::weak_ptr<RequestJobBase>> running = m_jobs;
    for (const std::weak_ptr<RequestJobBase> &weak : running) {
        if (const auto job = weak.lock())
            job->finishEarly();
    }
}

void ClientWorker::runJob(std::shared_ptr<RequestJobBase> job, int driveAddress)
{
    auto sink = std::make_shared<OwnedSink>(*this, isDin() ? driveAddress : -1);
    auto *watcher = new QFutureWatcher<void>(this);
    const std::weak_ptr<RequestJobBase> weak = job;
    connect(watcher, &QFutureWatcherBase::canceled, this, [weak] {
        if (const auto running = weak.lock())
            running->cancel();
    });
    watcher->setFuture(job->untypedFuture());
    std::erase_if(m_jobs, [](const std::weak_ptr<RequestJobBase> &j) { return j.expired(); });
    m_jobs.push_back(job);
    RequestJobBase *const raw = job.get();
    raw->begin(*sink, [this, job, sink, watcher]() mutable {
        watcher->deleteLater();
        // The job may still be on its own stack (it ended from a reply's callback): release it
        // once that has unwound.
        QMetaObject::invokeMethod(
            this, [job = std::move(job), sink = std::move(sink)] {}, Qt::QueuedConnection);
    });
}

} // namespace DriveDesk
