// The facade's requests as QFutures: each holds its QPromise in the worker thread and watches
// its future, so that cancelling the future reaches the request.
#include "ClientWorker.h"

#include "DriveScanner.h"

#include <QFutureWatcher>
#include <QPointer>

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

void ClientWorker::scan(const ScanOptions &options,
                        std::shared_ptr<QPromise<DriveDescription>> promise)
{
    promise->setProgressRange(0, 1000);
    if (promise->future().isCanceled()) {
        promise->finish();
        return;
    }
    // The scanner keeps a reference to its sink: both live until the scan finished.
    auto sink = std::make_shared<OwnedSink>(*this);
    ScanOptions scanning = options;
    // The switch that says the drive has DriveDesk's services also lets the scan ask service 13.
    scanning.identificationText = scanning.identificationText || m_settings.hsp5Extensions;
    auto *scanner = new DriveScanner(*sink, scanning, m_settings.language, this);
    auto *watcher = new QFutureWatcher<DriveDescription>(scanner);
    const QPointer<DriveScanner> guard(scanner);
    connect(watcher, &QFutureWatcherBase::canceled, this, [guard] {
        if (guard)
            guard->cancel();
    });
    auto best = std::make_shared<int>(0);
    connect(scanner, &DriveScanner::progress, this,
            [promise, best](int done, int total, const QString &what) {
                // The total grows as the scan learns; the bar never runs backwards.
                const int value = total > 0 ? int(qint64(done) * 1000 / total) : 0;
                *best = std::max(*best, std::min(value, 999));
                promise->setProgressValueAndText(*best, what);
            });
    connect(scanner, &DriveScanner::finished, this,
            [this, promise, sink, scanner](const DriveDescription &found) {
                DriveDescription description = found;
                if (description.protocol.isEmpty())
                    description.protocol = protocolName(m_settings.protocol);
                if (description.connection.isEmpty())
                    description.connection = connectionDescription();
                if (description.driveAddress < 0 && isDin())
                    description.driveAddress = m_settings.driveAddress;
                promise->setProgressValueAndText(1000, description.incompleteReason);
                promise->addResult(description);
                promise->finish();
                scanner->deleteLater();
            });
    watcher->setFuture(promise->future());
    m_scanners.removeAll(QPointer<DriveScanner>()); // the finished ones
    m_scanners.append(scanner);
    scanner->start();
}

void ClientWorker::stopScans()
{
    const QList<QPointer<DriveScanner>> running = m_scanners;
    for (const QPointer<DriveScanner> &scanner : running) {
        if (scanner)
            scanner->cancel();
    }
}

void ClientWorker::runJob(std::shared_ptr<RequestJobBase> job)
{
    auto sink = std::make_shared<OwnedSink>(*this);
    auto *watcher = new QFutureWatcher<void>(this);
    const std::weak_ptr<RequestJobBase> weak = job;
    connect(watcher, &QFutureWatcherBase::canceled, this, [weak] {
        if (const auto running = weak.lock())
            running->cancel();
    });
    watcher->setFuture(job->untypedFuture());
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
