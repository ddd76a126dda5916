#include "tst_editsupport.h"

#include "edit/PollingController.h"

#include <QTimer>

using namespace DriveDesk;
using namespace DriveDesk::EditTest;

namespace {

// Waits while `intervals` polling intervals pass on a timer of its own, started now: a polling
// timer left running, started before it, would have ticked by then.
bool waitIntervals(const PollingController &polling, int intervals)
{
    QTimer clock;
    clock.setTimerType(Qt::PreciseTimer);
    QSignalSpy ticks(&clock, &QTimer::timeout);
    clock.start(polling.intervalMs());
    return QTest::qWaitFor([&ticks, intervals] { return ticks.size() >= intervals; }, kWaitMs);
}

} // namespace

// Live values: the run display re-read while polling is on, one round at a time, and nothing
// more once it is off or the connection is gone.
class TestPolling : public QObject
{
    Q_OBJECT
private slots:
    void followsTheMotorWhileEnabled()
    {
        SimulatedDrive drive;
        QVERIFY(drive.start());
        PollingController polling(&drive.client, drive.model.state());
        QCOMPARE(polling.group(), QStringLiteral("ru"));
        QVERIFY(!polling.isEnabled());
        QSignalSpy enabled(&polling, &PollingController::enabledChanged);
        QSignalSpy changed(&drive.model, &QAbstractItemModel::dataChanged);

        const std::optional<qint32> first = drive.model.state()->value(kActualFrequency, 0);
        QVERIFY(first);
        polling.setIntervalMs(100);
        polling.setEnabled(true);
        QVERIFY(polling.isEnabled());
        QCOMPARE(enabled.size(), 1);
        // The demo cycle starts the motor a second after the drive's clock began.
        QTRY_VERIFY_WITH_TIMEOUT(drive.model.state()->value(kActualFrequency, 0) != first, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(polling.roundsCompleted() >= 3, kWaitMs);
        const QModelIndex frequency = drive.model.valueIndex(kActualFrequency, 0);
        bool announced = false;
        for (const QList<QVariant> &arguments : changed) {
            const QModelIndex from = arguments.at(0).toModelIndex();
            const QModelIndex to = arguments.at(1).toModelIndex();
            announced = announced
                || (from.parent() == frequency.parent() && from.row() <= frequency.row()
                    && to.row() >= frequency.row() && from.column() <= frequency.column()
                    && to.column() >= frequency.column());
        }
        QVERIFY(announced);
        // Only the group's values: operator parameters are never read.
        QCOMPARE(drive.state(kMaxSpeedForward), EditState::None);
    }

    void stopsWhenDisabled()
    {
        SimulatedDrive drive;
        QVERIFY(drive.start());
        PollingController polling(&drive.client, drive.model.state());
        polling.setIntervalMs(PollingController::kMinimumIntervalMs);
        polling.setEnabled(true);
        QTRY_VERIFY_WITH_TIMEOUT(polling.roundsCompleted() >= 2, kWaitMs);

        // The records of what polling sent so far come in as queued signals: take them in
        // before listening, or a loaded machine counts them as sent after the stop.
        QCoreApplication::processEvents();
        QSignalSpy traffic(&drive.client, &DriveClient::traffic);
        polling.setEnabled(false);
        QVERIFY(!polling.isEnabled());
        const int rounds = polling.roundsCompleted();
        // Nothing new is sent: at most the rest of the round under way goes out (the stop
        // reaches the client's thread a moment later, after what it sent meanwhile), and the
        // line stays quiet while two rounds would have been due. Each later read is one
        // request of the test's own.
        QVERIFY(drive.answerToALaterRead());
        const int settled = records(traffic, TrafficRecord::Kind::Sent) - 1;
        const DriveDescription shown = drive.model.state()->description();
        const GroupDescription *run = shown.findGroup(QStringLiteral("ru"));
        QVERIFY(run);
        QVERIFY2(settled <= int(run->parameters.size()), qPrintable(QString::number(settled)));
        QVERIFY(waitIntervals(polling, 2));
        QVERIFY(drive.answerToALaterRead());
        QCOMPARE(records(traffic, TrafficRecord::Kind::Sent) - 2, settled);
        QCOMPARE(polling.roundsCompleted(), rounds);
    }

    void skipsATickWhileARoundIsOnItsWay()
    {
        SimulatedDrive drive(20000); // 20 ms per answer: a round outlasts the interval
        QVERIFY(drive.start({ 0x02 })); // the run display alone, or the scan takes long
        PollingController polling(&drive.client, drive.model.state());
        QSignalSpy rounds(&polling, &PollingController::roundFinished);
        polling.setIntervalMs(PollingController::kMinimumIntervalMs);
        polling.setEnabled(true);
        QTRY_VERIFY_WITH_TIMEOUT(polling.roundsSkipped() >= 2 && rounds.size() >= 2, kWaitMs);
        polling.setEnabled(false);
    }

    void stopsWhenTheConnectionGoes()
    {
        SimulatedDrive drive;
        QVERIFY(drive.start());
        PollingController polling(&drive.client, drive.model.state());
        QSignalSpy enabled(&polling, &PollingController::enabledChanged);
        QSignalSpy messages(&polling, &PollingController::message);
        polling.setIntervalMs(100);
        polling.setEnabled(true);
        QTRY_VERIFY_WITH_TIMEOUT(polling.roundsCompleted() >= 1, kWaitMs);

        drive.client.disconnectFromDrive();
        QTRY_VERIFY_WITH_TIMEOUT(!polling.isEnabled(), kWaitMs);
        QCOMPARE(enabled.size(), 2);
        QCOMPARE(enabled.constLast().at(0).toBool(), false);
        QVERIFY(
            texts(messages).join(QLatin1Char('\n')).contains(QStringLiteral("Polling stopped")));
    }

    void aGroupTheDriveLacksIsSaidOnce()
    {
        SimulatedDrive drive;
        QVERIFY(drive.start());
        PollingController polling(&drive.client, drive.model.state());
        QSignalSpy messages(&polling, &PollingController::message);
        polling.setGroup(QStringLiteral("zz"));
        polling.setIntervalMs(PollingController::kMinimumIntervalMs);
        polling.setEnabled(true);
        QTRY_COMPARE(messages.size(), 1);
        QVERIFY(messages.constFirst().at(0).toString().contains(QStringLiteral("zz")));
        QVERIFY(waitIntervals(polling, 2));
        QCOMPARE(messages.size(), 1);
        QCOMPARE(polling.roundsCompleted(), 0);
    }

    void intervalStaysWithinBounds()
    {
        SimulatedDrive drive;
        PollingController polling(&drive.client, drive.model.state());
        polling.setIntervalMs(0);
        QCOMPARE(polling.intervalMs(), PollingController::kMinimumIntervalMs);
        polling.setIntervalMs(1'000'000);
        QCOMPARE(polling.intervalMs(), PollingController::kMaximumIntervalMs);
        polling.setIntervalMs(500);
        QCOMPARE(polling.intervalMs(), 500);
    }
};

QTEST_MAIN(TestPolling)
#include "tst_polling.moc"
