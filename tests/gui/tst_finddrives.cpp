#include "tst_mainwindow_support.h"

#include "main/ConnectionDialog.h"
#include "frame/DriveSession.h"
#include "main/FindDrivesDialog.h"
#include "monitor/TelegramMonitor.h"
#include "monitor/TrafficModel.h"

#include <QAction>
#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

// A DIN66019II bus with drives 1, 5 and 17, as in the user's report.
ConnectionSettings busWithThreeDrives()
{
    ConnectionSettings bus = simulated(Protocol::Din66019II);
    bus.simulation.driveAddresses = { 1, 5, 17 };
    bus.driveAddress = 1;
    return bus;
}

QListWidget *driveList(QWidget &dialog)
{
    return dialog.findChild<QListWidget *>(QStringLiteral("foundDrives"));
}

QPushButton *connectButton(QWidget &dialog)
{
    return dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
}

// Whether the monitor shows a telegram whose meaning holds `text` (it shows them in batches).
bool monitorShows(const TelegramMonitor *monitor, const QString &text)
{
    for (int row = 0; row < monitor->model()->rowCount(); ++row) {
        if (monitor->model()->entry(row).record.meaning.contains(text))
            return true;
    }
    return false;
}

} // namespace

// Finding drives on a DIN66019II bus: drives listed as they answer, kept when the search is
// stopped, with what they are and which one the window is connected to; the search's telegrams
// in the telegram monitor.
class TestFindDrives : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;

private slots:
    void init() { m_settings.clear(); }

    void drivesAppearAsTheyAnswerAndSurviveStop()
    {
        FindDrivesDialog dialog(busWithThreeDrives());
        auto *list = driveList(dialog);
        auto *progress = dialog.findChild<QProgressBar *>(QStringLiteral("searchProgress"));
        // Where the search was when each drive appeared.
        QList<bool> searchingWhenListed;
        connect(list->model(), &QAbstractItemModel::rowsInserted, this,
                [&] { searchingWhenListed.append(dialog.isSearching()); });

        QTRY_COMPARE_WITH_TIMEOUT(list->count(), 3, kWaitMs);
        QCOMPARE(searchingWhenListed, (QList<bool> { true, true, true }));
        QVERIFY(dialog.isSearching());
        QSignalSpy finished(&dialog, &FindDrivesDialog::searchFinished);
        QTest::mouseClick(dialog.findChild<QPushButton *>(QStringLiteral("stopSearch")),
                          Qt::LeftButton);
        QVERIFY(finished.wait(kWaitMs));

        QVERIFY(!dialog.isSearching());
        QCOMPARE(dialog.foundAddresses(), (QList<int> { 1, 5, 17 }));
        const QString status = dialog.findChild<QLabel *>(QStringLiteral("searchStatus"))->text();
        QVERIFY2(status.startsWith(QStringLiteral("Stopped after ")), qPrintable(status));
        QVERIFY2(status.contains(QStringLiteral("3 drive")), qPrintable(status));
        QVERIFY(progress->value() < progress->maximum());
        QVERIFY(status.contains(QString::number(progress->value())));

        // Connect stays possible for a selected drive.
        QVERIFY(list->currentItem());
        QVERIFY(connectButton(dialog)->isEnabled());
        list->setCurrentRow(1);
        QVERIFY(connectButton(dialog)->isEnabled());
        dialog.accept();
        QCOMPARE(dialog.chosenAddress(), 5);
    }

    void foundDrivesShowTheirIdentification()
    {
        FindDrivesDialog dialog(busWithThreeDrives());
        auto *list = driveList(dialog);
        QTRY_VERIFY_WITH_TIMEOUT(list->count() >= 1, kWaitMs);
        const QListWidgetItem *first = list->item(0);
        QCOMPARE(first->data(FindDrivesDialog::AddressRole).toInt(), 1);
        const QString identification = first->data(FindDrivesDialog::IdentificationRole).toString();
        // Sy.02 and In.06 as the simulated F5 shows them.
        QVERIFY2(identification.contains(QStringLiteral("inverter identifier 0F51h")),
                 qPrintable(identification));
        QVERIFY2(identification.contains(QStringLiteral("software 1.82")),
                 qPrintable(identification));
        QVERIFY(first->text().contains(identification));
        // Searching through a connection of its own: no drive is connected now.
        QVERIFY(!first->data(FindDrivesDialog::ConnectedRole).toBool());
        dialog.reject();
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.isSearching(), kWaitMs);
    }

    void theConnectedDriveIsMarked()
    {
        MainWindow window;
        ConnectionSettings bus = busWithThreeDrives();
        bus.driveAddress = 5;
        QVERIFY(connectAndRead(window, bus));

        window.findChild<QAction *>(QStringLiteral("findDrivesAction"))->trigger();
        QPointer<FindDrivesDialog> dialog;
        QTRY_VERIFY_WITH_TIMEOUT(
            (dialog = qobject_cast<FindDrivesDialog *>(QApplication::activeModalWidget())),
            kWaitMs);
        auto *list = driveList(*dialog);
        QTRY_VERIFY_WITH_TIMEOUT(list->count() >= 2, kWaitMs);
        const QListWidgetItem *one = list->item(0);
        const QListWidgetItem *five = list->item(1);
        QCOMPARE(five->data(FindDrivesDialog::AddressRole).toInt(), 5);
        QVERIFY(five->data(FindDrivesDialog::ConnectedRole).toBool());
        QVERIFY2(five->text().contains(QStringLiteral("connected now")), qPrintable(five->text()));
        QVERIFY(five->font().bold());
        QVERIFY(!one->data(FindDrivesDialog::ConnectedRole).toBool());
        QVERIFY(!one->text().contains(QStringLiteral("connected now")));
        dialog->reject();
        QTRY_VERIFY_WITH_TIMEOUT(dialog.isNull(), kWaitMs);
    }

    void searchTelegramsReachTheMonitorWhileDisconnected()
    {
        MainWindow window;
        QVERIFY(!window.session());
        auto *monitor = window.findChild<TelegramMonitor *>();
        QVERIFY(monitor);
        ConnectionDialog *connection = window.openConnectionDialog();
        connection->setSettings(busWithThreeDrives());
        connection->findDrives();
        auto *search = connection->findChild<FindDrivesDialog *>();
        QVERIFY(search);
        QTRY_VERIFY_WITH_TIMEOUT(driveList(*search)->count() >= 1, kWaitMs);
        QVERIFY(!window.session());

        // The probes of addresses 0 and 1 as they were sent, read as DIN66019II.
        QTRY_VERIFY_WITH_TIMEOUT(monitorShows(monitor, QStringLiteral("to drive 0")), kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(monitorShows(monitor, QStringLiteral("to drive 1")), kWaitMs);
        for (int row = 0; row < monitor->model()->rowCount(); ++row)
            QCOMPARE(monitor->model()->entry(row).protocol, Protocol::Din66019II);
        search->reject();
        connection->reject();
    }

    void searchTelegramsReachTheMonitorWhileConnected()
    {
        MainWindow window;
        QVERIFY(connectAndRead(window, busWithThreeDrives()));
        auto *monitor = window.findChild<TelegramMonitor *>();
        monitor->clear();
        window.findChild<QAction *>(QStringLiteral("findDrivesAction"))->trigger();
        QPointer<FindDrivesDialog> dialog;
        QTRY_VERIFY_WITH_TIMEOUT(
            (dialog = qobject_cast<FindDrivesDialog *>(QApplication::activeModalWidget())),
            kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(driveList(*dialog)->count() >= 2, kWaitMs);
        // The probe of address 5 went through the window's connection.
        QTRY_VERIFY_WITH_TIMEOUT(monitorShows(monitor, QStringLiteral("to drive 5")), kWaitMs);
        dialog->reject();
    }
};

QTEST_MAIN(TestFindDrives)
#include "tst_finddrives.moc"
