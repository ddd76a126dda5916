#include "tst_mainwindow_support.h"
#include "tst_plantsupport.h"

#include "../history/GitTestHome.h"

#include "compare/CompareWindow.h"
#include "compare/ComparisonModel.h"
#include "history/BackupCommit.h"
#include "plant/PlantDock.h"
#include "plant/PlantFeature.h"
#include "plant/PlantHistoryWindow.h"
#include "plant/PlantModel.h"
#include "plant/PlantReportDialog.h"

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTreeWidget>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

using GitTest::git;
using PlantTest::kJobWaitMs;

QStringList listed(const QListWidget *list)
{
    QStringList lines;
    for (int row = 0; row < list->count(); ++row)
        lines << list->item(row)->text();
    return lines;
}

} // namespace

// The plant view's History against a bus of two simulated drives behind a TCP port: backups
// committed as `plant backup --commit` commits them (core's BackupCommit), the revisions and
// their changes read off the window's thread, two side by side in the compare window, and the
// older restored through Download All's last look.
class TestPlantHistory : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_dir;
    QTemporaryDir m_home;
    std::unique_ptr<ServedDrive> m_cabinet;
    std::unique_ptr<MainWindow> m_window;
    PlantDock *m_dock = nullptr;
    qint32 m_before = 0;

    // Back Up All, then the files saved committed as `plant backup --commit` does.
    bool backUpAndCommit(const QString &message)
    {
        if (!PlantTest::runJob(*m_dock, m_dock->backupAction()))
            return false;
        QString error;
        auto repository = BackupRepository::open(m_dock->backupFolder(), true, &error);
        BackupCommit backup;
        backup.plantName = QStringLiteral("Line 3");
        backup.message = message;
        backup.saved = {QStringLiteral("cabinet-2.json"), QStringLiteral("cabinet-5.json")};
        const auto outcome = repository ? backup.commit(*repository, &error) : std::nullopt;
        if (!outcome || !outcome->committed)
            qWarning() << "not committed:" << error;
        return outcome && outcome->committed;
    }

    ConnectionSettings cabinet(int address) const
    {
        return m_dock->model()->plant().links.first().settings(address);
    }

    // The value of op.20 set 0 on cabinet-5, read in the window's editor, which lets go after.
    std::optional<qint32> fixedSpeedOf5(std::optional<qint32> write = std::nullopt)
    {
        if (!connectAndRead(*m_window, cabinet(5)))
            return std::nullopt;
        DriveClient *client = m_window->session()->client();
        if (write && (!m_window->model()->requestWrite(kFixedSpeed1, 0x01, *write)
                      || !QTest::qWaitFor(
                          [&] { return driveValue(client, kFixedSpeed1) == *write; }, kWaitMs)))
            return std::nullopt;
        const std::optional<qint32> value = driveValue(client, kFixedSpeed1);
        // The editor lets go of the bus: its gateway serves one connection, the plant's jobs.
        m_window->findChild<QAction *>(QStringLiteral("disconnectAction"))->trigger();
        const bool gone = QTest::qWaitFor(
            [this] { return m_window->session()->state() == DriveClient::State::Disconnected; },
            kWaitMs);
        return gone ? value : std::nullopt;
    }

    // The revision at `row` alone selected, cabinet-5 the drive to compare, and `button` of the
    // history window clicked; false when it was not enabled.
    bool clickForRevision(int row, const char *button)
    {
        PlantHistoryWindow *history = m_dock->historyWindow();
        history->revisionList()->clearSelection();
        history->revisionList()->setCurrentItem(history->revisionList()->topLevelItem(row));
        history->compareDrive()->setCurrentText(QStringLiteral("cabinet-5"));
        auto *clicked = history->findChild<QPushButton *>(QLatin1String(button));
        if (history->selectedRevisions().size() != 1 || !clicked->isEnabled())
            return false;
        clicked->click();
        return true;
    }

    PlantHistoryWindow *openHistory()
    {
        m_window->findChild<QAction *>(QStringLiteral("plantHistoryMenuAction"))->trigger();
        PlantHistoryWindow *history = m_dock->historyWindow();
        if (!history || !history->isVisible()
            || !QTest::qWaitFor([history] { return !history->isBusy(); }, kJobWaitMs))
            return nullptr;
        return history;
    }

private slots:
    void initTestCase()
    {
        // git's configuration of our own: an author, nothing of the user running the tests.
        QVERIFY(GitTest::useHome(m_home));

        m_settings.clear();
        QVERIFY(m_dir.isValid());
        SimulationOptions bus;
        bus.driveAddresses = {2, 5};
        bus.replyLatencyUs = 0;
        m_cabinet = std::make_unique<ServedDrive>(Protocol::Din66019II, bus);
        QString error;
        QVERIFY2(m_cabinet->listen(0, &error), qPrintable(error));
        Plant plant;
        plant.name = QStringLiteral("Line 3");
        PlantLink link;
        link.name = QStringLiteral("cabinet");
        link.connect = QStringLiteral("tcp:127.0.0.1:%1").arg(m_cabinet->port());
        link.protocol = Protocol::Din66019II;
        link.addresses = {2, 5};
        plant.links = {link};
        const QString path = m_dir.filePath(QStringLiteral("line3.json"));
        QVERIFY(PlantFile::save(path, plant, &error));

        m_window = std::make_unique<MainWindow>();
        m_window->resize(1300, 860);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        auto *feature = m_window->findChild<PlantFeature *>();
        m_dock = feature->dock();
        QVERIFY(feature->openPlant(path));
    }

    void cleanupTestCase()
    {
        m_window.reset();
        m_cabinet.reset();
    }

    void aFolderThatIsNoRepositoryIsNamed()
    {
        QVERIFY(QDir().mkpath(m_dock->backupFolder()));
        PlantHistoryWindow *history = openHistory();
        QVERIFY(history);
        QCOMPARE(history->revisionList()->topLevelItemCount(), 0);
        QVERIFY2(history->message().startsWith(QStringLiteral("No history to show: "))
                     && history->message().contains(QStringLiteral("is not a git repository")),
                 qPrintable(history->message()));
        QVERIFY(!history->findChild<QPushButton *>(QStringLiteral("historyRestore"))->isEnabled());
        history->close();
    }

    void aRepositoryWithoutRevisionsSaysSo()
    {
        git(m_dock->backupFolder(), {QStringLiteral("init"), QStringLiteral("-q")});
        PlantHistoryWindow *history = openHistory();
        QVERIFY(history);
        QCOMPARE(history->revisionList()->topLevelItemCount(), 0);
        QVERIFY2(history->message().contains(QStringLiteral("has no revisions yet")),
                 qPrintable(history->message()));
        history->close();
    }

    void theRevisionsAndTheirChangesAreShown()
    {
        QVERIFY(backUpAndCommit({}));
        const std::optional<qint32> before = fixedSpeedOf5();
        QVERIFY(before);
        m_before = *before;
        QCOMPARE(fixedSpeedOf5(m_before + 17), m_before + 17);
        QVERIFY(backUpAndCommit(QStringLiteral("Fixed speed for the new gear")));

        PlantHistoryWindow *history = openHistory();
        QVERIFY(history);
        QTreeWidget *revisions = history->revisionList();
        QCOMPARE(revisions->topLevelItemCount(), 2);
        QVERIFY2(history->message().startsWith(QStringLiteral("Revisions: 2, newest first")),
                 qPrintable(history->message()));
        const QTreeWidgetItem *newer = revisions->topLevelItem(0);
        QCOMPARE(newer->text(3), QStringLiteral("Fixed speed for the new gear"));
        QCOMPARE(newer->text(2), QStringLiteral("Test Engineer"));
        QCOMPARE(newer->text(4), QStringLiteral("1"));
        QCOMPARE(revisions->topLevelItem(1)->text(4), QStringLiteral("2")); // both drives added
        // The newest is selected; its change in the words `plant history` prints.
        const QStringList changes = listed(history->changeList());
        QCOMPARE(changes.size(), 1);
        QVERIFY2(changes.first().startsWith(QStringLiteral("cabinet-5 op.20 set 0: "))
                     && changes.first().contains(QStringLiteral(" -> ")),
                 qPrintable(changes.first()));
        QCOMPARE(history->compareDrive()->currentText(), QStringLiteral("cabinet-5"));
        // docs/plant-history.png
        const QString screenshot = qEnvironmentVariable("DRIVEDESK_PLANT_HISTORY_SCREENSHOT");
        if (!screenshot.isEmpty()) {
            history->resize(860, 420);
            QTest::qWait(300);
            QVERIFY(history->grab().save(screenshot));
        }

        // The filters as `plant history --drive/--parameter`.
        history->driveFilter()->setCurrentText(QStringLiteral("cabinet-2"));
        history->refresh();
        QVERIFY(QTest::qWaitFor([history] { return !history->isBusy(); }, kJobWaitMs));
        QCOMPARE(revisions->topLevelItemCount(), 1); // only the first, which added it
        history->driveFilter()->setCurrentText(QString());
        history->parameterFilter()->setText(QStringLiteral("OP.020"));
        history->refresh();
        QVERIFY(QTest::qWaitFor([history] { return !history->isBusy(); }, kJobWaitMs));
        QCOMPARE(revisions->topLevelItemCount(), 1);
        QCOMPARE(revisions->topLevelItem(0)->text(3), QStringLiteral("Fixed speed for the new gear"));
        history->parameterFilter()->setText(QStringLiteral("op.21"));
        history->refresh();
        QVERIFY(QTest::qWaitFor([history] { return !history->isBusy(); }, kJobWaitMs));
        QCOMPARE(revisions->topLevelItemCount(), 0);
        QVERIFY2(history->message().startsWith(QStringLiteral("No revision changed")),
                 qPrintable(history->message()));
        history->parameterFilter()->clear();
        history->refresh();
        QVERIFY(QTest::qWaitFor([history] { return !history->isBusy(); }, kJobWaitMs));
        QCOMPARE(revisions->topLevelItemCount(), 2);
    }

    void twoRevisionsAreComparedSideBySide()
    {
        PlantHistoryWindow *history = m_dock->historyWindow();
        QTreeWidget *revisions = history->revisionList();
        revisions->selectAll();
        QCOMPARE(history->selectedRevisions().size(), 2);
        history->compareDrive()->setCurrentText(QStringLiteral("cabinet-5"));
        auto *button = history->findChild<QPushButton *>(QStringLiteral("historyCompare"));
        QVERIFY(button->isEnabled());
        button->click();
        CompareWindow *compare = nullptr;
        QVERIFY(QTest::qWaitFor([&] {
            compare = m_window->findChild<CompareWindow *>();
            return compare && compare->isVisible();
        }));
        const ComparisonTable &table = compare->comparisonModel()->comparison();
        qsizetype different = 0;
        for (const ComparisonRow &row : table.rows) {
            if (row.state == ComparisonRow::State::Different) {
                ++different;
                QCOMPARE(row.address, kFixedSpeed1);
                QCOMPARE(row.setA, 0);
            }
        }
        QCOMPARE(different, 1);
        QVERIFY2(compare->message().contains(QStringLiteral("cabinet-5 at ")),
                 qPrintable(compare->message()));
        compare->close();
    }

    void theOlderRevisionIsRestoredThroughTheLastLook()
    {
        const QString older = m_dock->historyWindow()->revisionList()->topLevelItem(1)->data(
            0, Qt::UserRole).toString();
        QVERIFY(clickForRevision(1, "historyRestore"));
        // The files read, the drives read and planned: the last look, nothing written yet.
        PlantReportDialog *look = nullptr;
        QVERIFY(QTest::qWaitFor(
            [&] {
                look = m_dock->reportDialog();
                return look && look->isVisible() && m_dock->job() == PlantDock::Job::None;
            },
            kJobWaitMs));
        QVERIFY2(look->windowTitle().contains(older.left(12)), qPrintable(look->windowTitle()));
        QVERIFY2(look->summary().startsWith(QStringLiteral("1 drive")), qPrintable(look->summary()));
        QCOMPARE(fixedSpeedOf5(), m_before + 17);
        look->findChild<QPushButton *>(QStringLiteral("plantWriteButton"))->click();
        QVERIFY(m_dock->job() == PlantDock::Job::Download);
        QVERIFY(
            QTest::qWaitFor([this] { return m_dock->job() == PlantDock::Job::None; }, kJobWaitMs));
        PlantReportDialog *report = m_dock->reportDialog();
        QVERIFY(report && report != look);
        QVERIFY2(report->summary().startsWith(QStringLiteral("2 of 2 drive")),
                 qPrintable(report->summary()));
        report->close();
        QCOMPARE(fixedSpeedOf5(), m_before);
        // The backup folder and its repository stay as they were.
        QCOMPARE(git(m_dock->backupFolder(), {QStringLiteral("status"), QStringLiteral("--porcelain")}),
                 QString());
    }

    // Restored, the drive holds what the older revision holds: the newer differs from it.
    void aRevisionIsComparedWithTheDrive()
    {
        QVERIFY(clickForRevision(0, "historyAgainstDrive"));
        CompareWindow *compare = nullptr;
        QVERIFY(QTest::qWaitFor(
            [&] {
                compare = m_window->findChild<CompareWindow *>();
                return compare && compare->isVisible()
                    && compare->message().contains(QStringLiteral("cabinet-5 as read at"));
            },
            kJobWaitMs));
        const ComparisonTable &table = compare->comparisonModel()->comparison();
        const auto different = std::count_if(table.rows.cbegin(), table.rows.cend(),
                                             [](const ComparisonRow &row) {
                                                 return row.state == ComparisonRow::State::Different;
                                             });
        QCOMPARE(different, 1);
        compare->close();
    }

    void theColumnsAndSizeAreRemembered()
    {
        PlantHistoryWindow *history = openHistory();
        QVERIFY(history);
        history->revisionList()->setColumnWidth(1, 222);
        history->resize(777, 444);
        history->close();
        delete history; // the next History makes a window anew, as the next start does
        history = openHistory();
        QVERIFY(history);
        QCOMPARE(history->revisionList()->columnWidth(1), 222);
        QCOMPARE(history->size(), QSize(777, 444));
        history->close();
    }

    void backUpAllCommitsWhenAsked()
    {
        const QString folder = m_dock->backupFolder();
        const auto revisions = [&folder] {
            return git(folder, {QStringLiteral("rev-list"), QStringLiteral("--count"),
                                QStringLiteral("HEAD")})
                .trimmed()
                .toInt();
        };
        const auto said = [this] {
            return m_dock->findChild<QLabel *>(QStringLiteral("plantStatus"))->text();
        };
        const auto backUp = [this] {
            return PlantTest::runJob(*m_dock, m_dock->backupAction())
                   && QTest::qWaitFor([this] { return !m_dock->isCommitting(); }, kJobWaitMs);
        };
        const int before = revisions();
        QVERIFY(before >= 2);
        // Unchecked (as a first start has it): a backup is no revision.
        QVERIFY(!m_dock->commitAction()->isChecked());
        QVERIFY(backUp());
        QCOMPARE(revisions(), before);

        const std::optional<qint32> now = fixedSpeedOf5();
        QVERIFY(now);
        QCOMPARE(fixedSpeedOf5(*now + 3), *now + 3);
        m_dock->commitAction()->setChecked(true);
        QVERIFY(backUp());
        QCOMPARE(revisions(), before + 1);
        QVERIFY2(said().contains(QStringLiteral("Committed "))
                     && said().endsWith(QStringLiteral(": Line 3: backup, cabinet-5 changed")),
                 qPrintable(said()));
        const QString subject
            = git(folder, {QStringLiteral("log"), QStringLiteral("-1"), QStringLiteral("--format=%B")});
        QVERIFY2(subject.contains(QStringLiteral("cabinet-5 op.20 set 0: ")), qPrintable(subject));

        // Nothing changed: no revision, and the view says so.
        QVERIFY(backUp());
        QCOMPARE(revisions(), before + 1);
        QVERIFY2(said().endsWith(
                     QStringLiteral("No setting changed since the last revision: nothing committed.")),
                 qPrintable(said()));
        m_dock->commitAction()->setChecked(false);
    }
};

QTEST_MAIN(TestPlantHistory)
#include "tst_planthistory.moc"
