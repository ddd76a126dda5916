#include "client/WhenFinished.h"

#include <QFutureInterface>
#include <QPromise>
#include <QSignalSpy>
#include <QTest>

#include <atomic>
#include <thread>

using namespace DriveDesk;

namespace {

// A future's end as the client's thread reports it: reportFinished() sets the state first and
// runs the continuation after, and this lets a test stop between the two.
class SteppedFuture : public QFutureInterface<int>
{
public:
    void markFinished() { QFutureInterfaceBase::reportFinished(); }
    void runContinuationNow() const { runContinuation(); }
};

} // namespace

class WhenFinishedTest : public QObject
{
    Q_OBJECT
private slots:
    void attachedWhileTheFutureFinishesItRunsOnce();
    void attachedWhileAnotherThreadFinishesItRunsOnceEveryTime();
    void aFutureWithoutResultRunsTheOtherBranch();
    void nothingRunsOnceTheContextIsGone();
};

// The window's crash: attached in the moment between the state and the continuation, Qt 6.4's
// then(context, ...) ran twice and crashed in reportStarted.
void WhenFinishedTest::attachedWhileTheFutureFinishesItRunsOnce()
{
    QObject context;
    SteppedFuture future;
    future.reportStarted();
    future.reportResult(7);
    future.markFinished();
    QList<int> results;
    whenFinished(future.future(), &context, [&results](int value) { results << value; });
    future.runContinuationNow();
    QTRY_COMPARE(results, QList<int>{7});
    QTest::qWait(20);
    QCOMPARE(results, QList<int>{7});
}

void WhenFinishedTest::attachedWhileAnotherThreadFinishesItRunsOnceEveryTime()
{
    QObject context;
    constexpr int kRounds = 3000;
    int runs = 0;
    int last = -1;
    for (int round = 0; round < kRounds; ++round) {
        QPromise<int> promise;
        promise.start();
        std::atomic<bool> go = false;
        std::thread finisher([&] {
            while (!go.load())
                std::this_thread::yield();
            promise.addResult(round);
            promise.finish();
        });
        go = true;
        whenFinished(promise.future(), &context, [&runs, &last](int value) {
            ++runs;
            last = value;
        });
        finisher.join();
        QTRY_COMPARE(runs, round + 1);
        QCOMPARE(last, round);
    }
    QCoreApplication::processEvents();
    QCOMPARE(runs, kRounds);
}

void WhenFinishedTest::aFutureWithoutResultRunsTheOtherBranch()
{
    QObject context;
    QPromise<int> promise;
    promise.start();
    bool withResult = false;
    bool withoutResult = false;
    whenFinished(
        promise.future(), &context, [&withResult](int) { withResult = true; },
        [&withoutResult] { withoutResult = true; });
    promise.future().cancel();
    promise.finish();
    QTRY_VERIFY(withoutResult);
    QVERIFY(!withResult);
}

void WhenFinishedTest::nothingRunsOnceTheContextIsGone()
{
    auto context = std::make_unique<QObject>();
    QPromise<int> promise;
    promise.start();
    bool ran = false;
    whenFinished(promise.future(), context.get(), [&ran](int) { ran = true; });
    context.reset();
    promise.addResult(1);
    promise.finish();
    QTest::qWait(20);
    QVERIFY(!ran);
}

QTEST_GUILESS_MAIN(WhenFinishedTest)
#include "tst_whenfinished.moc"
