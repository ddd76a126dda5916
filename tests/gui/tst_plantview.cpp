#include "tst_mainwindow_support.h"
#include "tst_plantsupport.h"

#include "compare/CompareWindow.h"
#include "compare/ComparisonModel.h"
#include "frame/NoticeBar.h"
#include "plant/PlantDock.h"
#include "plant/PlantFeature.h"
#include "plant/PlantLinkDialog.h"
#include "plant/PlantModel.h"
#include "plant/PlantReportDialog.h"

#include "Translations.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QStatusBar>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTreeView>
#include <QTreeWidget>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

using PlantTest::kJobWaitMs;

bool writeText(const QString &path, const QString &text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && file.write(text.toUtf8()) == text.toUtf8().size();
}

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

SimulationOptions bus(QList<int> addresses)
{
    SimulationOptions options;
    options.driveAddresses = std::move(addresses);
    options.replyLatencyUs = 0;
    return options;
}

} // namespace

// The plant view in the window, against a DIN66019II bus of two drives and an HSP5 drive, each
// behind a TCP port as a device server serves them (one connection at a time).
class TestPlantView : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_dir;
    std::unique_ptr<ServedDrive> m_cabinet;
    std::unique_ptr<ServedDrive> m_hoist;
    std::unique_ptr<MainWindow> m_window;
    PlantDock *m_dock = nullptr;
    QString m_plantPath;

    PlantModel *model() const { return m_dock->model(); }

    // What the plant view shows in a column of a drive's row.
    QString shown(const QString &link, int address, int column) const
    {
        return model()->driveIndex(link, address).siblingAtColumn(column).data().toString();
    }

    bool runJob(QAction *action) { return PlantTest::runJob(*m_dock, action); }

    // Double-clicks the drive's row and waits until the window shows that drive.
    bool openDrive(const QString &link, int address, const QString &target)
    {
        const QModelIndex index = model()->driveIndex(link, address);
        QTreeView *view = m_dock->view();
        view->scrollTo(index);
        const QPoint centre = view->visualRect(index).center();
        // As a user does it: QTest's double click alone leaves the press without its release.
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, centre);
        QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, centre);
        return QTest::qWaitFor(
            [&] {
                return m_window->isReady() && m_window->session()->settings().target() == target
                    && (address < 0 || m_window->session()->settings().driveAddress == address);
            },
            kWaitMs);
    }

    bool disconnectWindow()
    {
        m_window->findChild<QAction *>(QStringLiteral("disconnectAction"))->trigger();
        return QTest::qWaitFor(
            [this] { return m_window->session()->state() == DriveClient::State::Disconnected; },
            kWaitMs);
    }

private slots:
    void initTestCase()
    {
        // The screenshot in docs/plant.md shows the texts as a user reads them.
        if (qEnvironmentVariableIsSet("DRIVEDESK_PLANT_SCREENSHOT")) {
            QVERIFY(installTranslations(
                qEnvironmentVariable("DRIVEDESK_PLANT_SCREENSHOT_LANGUAGE", QStringLiteral("en"))));
        }
        m_settings.clear();
        QVERIFY(m_dir.isValid());
        m_cabinet = std::make_unique<ServedDrive>(Protocol::Din66019II, bus({ 2, 5 }));
        m_hoist = std::make_unique<ServedDrive>(Protocol::Hsp5, bus({ 1 }));
        QString error;
        QVERIFY2(m_cabinet->listen(0, &error), qPrintable(error));
        QVERIFY2(m_hoist->listen(0, &error), qPrintable(error));
        m_plantPath = m_dir.filePath(QStringLiteral("line3.json"));
        Plant plant;
        plant.name = QStringLiteral("Line 3");
        PlantLink cabinet;
        cabinet.name = QStringLiteral("cabinet");
        cabinet.connect = QStringLiteral("tcp:127.0.0.1:%1").arg(m_cabinet->port());
        cabinet.protocol = Protocol::Din66019II;
        PlantLink hoist;
        hoist.name = QStringLiteral("hoist");
        hoist.connect = QStringLiteral("tcp:127.0.0.1:%1").arg(m_hoist->port());
        hoist.protocol = Protocol::Hsp5;
        plant.links = { cabinet, hoist };
        QVERIFY(PlantFile::save(m_plantPath, plant, &error));

        m_window = std::make_unique<MainWindow>();
        m_window->resize(1300, 860);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        auto *feature = m_window->findChild<PlantFeature *>();
        QVERIFY(feature);
        m_dock = feature->dock();
        ClientOptions options;
        options.timeoutMs = 30; // a short wait per address no drive answers: a quick search
        m_dock->setClientOptions(options);
        QVERIFY(feature->openPlant(m_plantPath));
        QVERIFY(m_dock->isVisible());
        QCOMPARE(PlantFeature::recentPlants(),
                 QStringList { QFileInfo(m_plantPath).absoluteFilePath() });
    }

    void cleanupTestCase()
    {
        m_window.reset();
        m_cabinet.reset();
        m_hoist.reset();
    }

    void aBadPlantFileIsNamedWithLineAndColumn()
    {
        const QString bad = m_dir.filePath(QStringLiteral("bad.json"));
        QVERIFY(writeText(
            bad,
            readText(m_plantPath).replace(QStringLiteral("\"hsp5\""), QStringLiteral("\"hsp6\""))));
        auto *feature = m_window->findChild<PlantFeature *>();
        QVERIFY(!feature->openPlant(bad));
        QMessageBox *box = nullptr;
        QVERIFY(QTest::qWaitFor([&] {
            box = m_window->findChild<QMessageBox *>(QStringLiteral("plantProblemBox"));
            return box && box->isVisible();
        }));
        QVERIFY2(box->text().contains(QStringLiteral("bad.json"))
                     && box->text().contains(QStringLiteral("links[1].protocol"))
                     && box->text().contains(
                         QRegularExpression(QStringLiteral("line \\d+, column \\d+"))),
                 qPrintable(box->text()));
        box->close();
        QCOMPARE(m_dock->plantPath(), QFileInfo(m_plantPath).absoluteFilePath()); // unchanged
    }

    void aLinkIsAddedAsThePlantFileAllowsIt()
    {
        PlantLinkDialog dialog(model()->plant(), false);
        dialog.nameEdit()->setText(QStringLiteral("hoist"));
        dialog.connectEdit()->setText(QStringLiteral("sim"));
        dialog.accept();
        QVERIFY2(dialog.problem().contains(QStringLiteral("also the name of links[1]")),
                 qPrintable(dialog.problem()));
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
    }

    void findListsEveryDrive()
    {
        QAbstractItemModelTester tester(model());
        QCOMPARE(model()->index(0, PlantModel::StateColumn).data().toString(),
                 QStringLiteral("not searched"));
        // While the search goes on, each drive found fits its name ("cabinet-5", not "cab...").
        QTreeView *view = m_dock->view();
        QStringList cut;
        const QMetaObject::Connection watching = connect(
            model(), &QAbstractItemModel::rowsInserted, this, [&](const QModelIndex &parent) {
                const int needed = static_cast<QAbstractItemView *>(view)->sizeHintForColumn(
                    PlantModel::NameColumn);
                if (view->columnWidth(PlantModel::NameColumn) < needed)
                    cut << parent.data().toString();
            });
        QVERIFY(runJob(m_dock->findAction()));
        disconnect(watching);
        QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QLatin1Char(','))));
        for (const auto &[link, address] : { std::pair { QStringLiteral("cabinet"), 2 },
                                             std::pair { QStringLiteral("cabinet"), 5 },
                                             std::pair { QStringLiteral("hoist"), -1 } }) {
            QCOMPARE(shown(link, address, PlantModel::StateColumn), QStringLiteral("answering"));
            QVERIFY2(shown(link, address, PlantModel::IdentificationColumn)
                         .contains(QStringLiteral("software")),
                     qPrintable(shown(link, address, PlantModel::IdentificationColumn)));
        }
        QCOMPARE(model()->rowCount(model()->index(0, 0)), 2);
        // The addresses found are in the plant file now, and the dock says so in sentences,
        // once: not again in the window's status bar.
        QVERIFY2(readText(m_plantPath).contains(QStringLiteral("\"addresses\": [2, 5]")),
                 qPrintable(readText(m_plantPath)));
        const QString said = m_dock->findChild<QLabel *>(QStringLiteral("plantStatus"))->text();
        QVERIFY2(said.startsWith(QStringLiteral("3 of 3 drive"))
                     && said.contains(QStringLiteral(" found. The addresses found were written to ")),
                 qPrintable(said));
        QVERIFY2(!m_window->statusBar()->currentMessage().contains(QStringLiteral("found")),
                 qPrintable(m_window->statusBar()->currentMessage()));
    }

    void backUpAllSavesEveryDrive()
    {
        QCOMPARE(shown(QStringLiteral("hoist"), -1, PlantModel::BackupColumn),
                 QStringLiteral("none"));
        m_dock->backupAction()->trigger();
        // Each drive at work shows its own progress.
        QVERIFY(QTest::qWaitFor([this] {
            const QModelIndex hoist = model()->driveIndex(QStringLiteral("hoist"), -1);
            return hoist.siblingAtColumn(PlantModel::ProgressColumn)
                       .data(PlantModel::ProgressRole)
                       .toInt()
                > 0;
        }));
        const QString screenshot = qEnvironmentVariable("DRIVEDESK_PLANT_PROGRESS_SHOT");
        if (!screenshot.isEmpty())
            QVERIFY(m_dock->grab().save(screenshot));
        QVERIFY(QTest::qWaitFor([this] { return m_dock->job() == PlantDock::Job::None; },
                                kJobWaitMs));
        const QDir backups(m_dock->backupFolder());
        QCOMPARE(backups.entryList(QDir::Files, QDir::Name),
                 QStringList({ QStringLiteral("cabinet-2.json"), QStringLiteral("cabinet-5.json"),
                               QStringLiteral("hoist.json") }));
        for (const auto &[link, address] : { std::pair { QStringLiteral("cabinet"), 2 },
                                             std::pair { QStringLiteral("cabinet"), 5 },
                                             std::pair { QStringLiteral("hoist"), -1 } }) {
            QVERIFY2(shown(link, address, PlantModel::ResultColumn)
                         .startsWith(QStringLiteral("saved, ")),
                     qPrintable(shown(link, address, PlantModel::ResultColumn)));
            QVERIFY(shown(link, address, PlantModel::BackupColumn) != QStringLiteral("none"));
        }
    }

    // A drive opens in the editor with a double click; the window's session is its own, so the
    // editor goes on while the plant's other links are backed up.
    void editingWhileAnotherLinkIsBackedUp()
    {
        QVERIFY(openDrive(QStringLiteral("hoist"), -1,
                          QStringLiteral("tcp:127.0.0.1:%1").arg(m_hoist->port())));
        // The metadata of a kind of drive already read comes from the cache.
        QVERIFY(m_window->findChild<QLabel *>(QStringLiteral("metadataSource"))->isVisible());

        const QString backups = m_dock->backupFolder();
        m_dock->setBackupFolder(m_dir.filePath(QStringLiteral("second")));
        QVERIFY(m_dock->backupAction()->isEnabled());
        m_dock->backupAction()->trigger();
        QVERIFY(m_dock->job() == PlantDock::Job::Backup);
        const qint32 before = m_window->model()->state()->value(kDemoPeriod, 0).value_or(0);
        QVERIFY(m_window->model()->requestWrite(kDemoPeriod, 0x01, 1234));
        QVERIFY(QTest::qWaitFor(
            [this] { return driveValue(m_window->session()->client(), kDemoPeriod) == 1234; },
            kWaitMs));
        QVERIFY(
            QTest::qWaitFor([this] { return m_dock->job() == PlantDock::Job::None; }, kJobWaitMs));
        QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("second/cabinet-2.json"))));
        QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("second/cabinet-5.json"))));
        // The hoist's device server serves one connection, the editor's: the hoist alone is
        // not saved, and says why.
        QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("second/hoist.json"))));
        const QString hoist = shown(QStringLiteral("hoist"), -1, PlantModel::ResultColumn);
        QVERIFY2(hoist.startsWith(QStringLiteral("failed: "))
                     || hoist.startsWith(QStringLiteral("unreachable: ")),
                 qPrintable(hoist));
        // It says what to do about it: the editor holds that line.
        QVERIFY2(hoist.contains(QStringLiteral("the editor is connected to this line"))
                     && hoist.contains(QStringLiteral("Disconnect")),
                 qPrintable(hoist));
        QVERIFY(m_window->isReady());
        m_dock->setBackupFolder(backups);
        // The hoist keeps its setting as backed up: the edit goes back.
        QVERIFY(m_window->model()->requestWrite(kDemoPeriod, 0x01, before));
        QVERIFY(QTest::qWaitFor(
            [&] { return driveValue(m_window->session()->client(), kDemoPeriod) == before; },
            kWaitMs));
    }

    void verifyAllShowsTheDriveThatDiffers()
    {
        QVERIFY(openDrive(QStringLiteral("cabinet"), 5,
                          QStringLiteral("tcp:127.0.0.1:%1").arg(m_cabinet->port())));
        QVERIFY(m_window->windowTitle().contains(QStringLiteral("DriveDesk")));
        const qint32 before = m_window->model()->state()->value(kFixedSpeed1, 0).value_or(0);
        QVERIFY(m_window->model()->requestWrite(kFixedSpeed1, 0x01, before + 17));
        QVERIFY(QTest::qWaitFor(
            [&] { return driveValue(m_window->session()->client(), kFixedSpeed1) == before + 17; },
            kWaitMs));
        // The editor lets go of the bus: its gateway serves one connection.
        QVERIFY(disconnectWindow());

        QVERIFY(runJob(m_dock->verifyAction()));
        QCOMPARE(shown(QStringLiteral("cabinet"), 2, PlantModel::ResultColumn),
                 QStringLiteral("equal"));
        QCOMPARE(shown(QStringLiteral("hoist"), -1, PlantModel::ResultColumn),
                 QStringLiteral("equal"));
        QVERIFY2(shown(QStringLiteral("cabinet"), 5, PlantModel::ResultColumn)
                     .startsWith(QStringLiteral("differs from its file: 1 setting")),
                 qPrintable(shown(QStringLiteral("cabinet"), 5, PlantModel::ResultColumn)));
        const QString tip = model()
                                ->driveIndex(QStringLiteral("cabinet"), 5)
                                .siblingAtColumn(PlantModel::ResultColumn)
                                .data(Qt::ToolTipRole)
                                .toString();
        QVERIFY2(tip.contains(QStringLiteral("op.20")), qPrintable(tip));
        const QString screenshot = qEnvironmentVariable("DRIVEDESK_PLANT_SCREENSHOT");
        if (!screenshot.isEmpty()) {
            m_window->resizeDocks({ m_dock }, { 330 }, Qt::Vertical);
            m_dock->view()->setCurrentIndex(model()->driveIndex(QStringLiteral("cabinet"), 5));
            QTest::qWait(300);
            QVERIFY(m_window->grab().save(screenshot));
        }
    }

    void twoDrivesAreComparedSideBySide()
    {
        QItemSelectionModel *selection = m_dock->view()->selectionModel();
        selection->clearSelection();
        for (int address : { 2, 5 })
            selection->select(model()->driveIndex(QStringLiteral("cabinet"), address),
                              QItemSelectionModel::Select | QItemSelectionModel::Rows);
        QVERIFY(m_dock->compareAction()->isEnabled());
        QVERIFY(runJob(m_dock->compareAction()));
        CompareWindow *compare = nullptr;
        QVERIFY(QTest::qWaitFor([&] {
            compare = m_window->findChild<CompareWindow *>();
            return compare && compare->isVisible();
        }));
        const ComparisonTable &table = compare->comparisonModel()->comparison();
        const auto changed
            = std::find_if(table.rows.cbegin(), table.rows.cend(), [](const ComparisonRow &row) {
                  return row.address == kFixedSpeed1 && row.setA == 0;
              });
        QVERIFY(changed != table.rows.cend());
        QCOMPARE(changed->state, ComparisonRow::State::Different);
        QVERIFY2(compare->message().contains(QStringLiteral("value")),
                 qPrintable(compare->message()));
        // Each side is a reading of its drive in a file of its own: writing into it would
        // change neither the drive nor its backup, so no write is offered.
        for (const char *name : {"writeToAButton", "writeToBButton"}) {
            auto *write = compare->findChild<QPushButton *>(QString::fromLatin1(name));
            QVERIFY(write);
            QVERIFY2(!write->isVisibleTo(compare), name);
        }
        QVERIFY2(compare->message().contains(QStringLiteral("cabinet-2 as read at"))
                     && compare->message().contains(QStringLiteral("open the drive in the editor")),
                 qPrintable(compare->message()));
        compare->close();
    }

    void downloadAllShowsALastLookThenOneReport()
    {
        QVERIFY(runJob(m_dock->downloadAction()));
        PlantReportDialog *look = m_dock->reportDialog();
        QVERIFY(look && look->isVisible());
        QVERIFY2(look->summary().startsWith(QStringLiteral("1 drive")),
                 qPrintable(look->summary()));
        const QList<QTreeWidgetItem *> cabinet5
            = look->list()->findItems(QStringLiteral("cabinet-5"), Qt::MatchExactly);
        QCOMPARE(cabinet5.size(), 1);
        QVERIFY2(cabinet5.first()->text(1).startsWith(QStringLiteral("dry run: ")),
                 qPrintable(cabinet5.first()->text(1)));
        QCOMPARE(
            look->list()->findItems(QStringLiteral("cabinet-2"), Qt::MatchExactly).first()->text(1),
            PlantDrive::outcomeText(PlantDrive::Outcome::Unchanged));
        QVERIFY(cabinet5.first()->childCount() > 0); // what it would get
        look->findChild<QPushButton *>(QStringLiteral("plantWriteButton"))->click();
        QVERIFY(m_dock->job() == PlantDock::Job::Download);
        QVERIFY(
            QTest::qWaitFor([this] { return m_dock->job() == PlantDock::Job::None; }, kJobWaitMs));
        PlantReportDialog *report = m_dock->reportDialog();
        QVERIFY(report && report->isVisible() && report != look);
        QVERIFY2(report->summary().startsWith(QStringLiteral("3 of 3 drive")),
                 qPrintable(report->summary()));
        QCOMPARE(report->list()
                     ->findItems(QStringLiteral("cabinet-5"), Qt::MatchExactly)
                     .first()
                     ->text(1),
                 QStringLiteral("written"));
        report->close();
        QVERIFY(runJob(m_dock->verifyAction()));
        QCOMPARE(shown(QStringLiteral("cabinet"), 5, PlantModel::ResultColumn),
                 QStringLiteral("equal"));
    }

    void stopEndsEveryLinkAndSavesNothingHalfRead()
    {
        const QString backups = m_dock->backupFolder();
        m_dock->setBackupFolder(m_dir.filePath(QStringLiteral("stopped")));
        m_dock->backupAction()->trigger();
        QVERIFY(m_dock->stopAction()->isEnabled());
        m_dock->stopAction()->trigger();
        QVERIFY(QTest::qWaitFor([this] { return m_dock->job() == PlantDock::Job::None; },
                                kJobWaitMs));
        QVERIFY(!m_dock->stopAction()->isEnabled());
        for (const auto &[link, address] : {std::pair{QStringLiteral("cabinet"), 2},
                                            std::pair{QStringLiteral("cabinet"), 5},
                                            std::pair{QStringLiteral("hoist"), -1}}) {
            const QString result = shown(link, address, PlantModel::ResultColumn);
            QVERIFY2(result.startsWith(QStringLiteral("stopped: ")), qPrintable(result));
        }
        QVERIFY(QDir(m_dir.filePath(QStringLiteral("stopped"))).entryList(QDir::Files).isEmpty());
        m_dock->setBackupFolder(backups);
    }

    void aNewPlantIsSavedAndShown()
    {
        m_window->findChild<QAction *>(QStringLiteral("newPlantAction"))->trigger();
        PlantLinkDialog *form = nullptr;
        QVERIFY(QTest::qWaitFor([&] {
            form = m_window->findChild<PlantLinkDialog *>();
            return form && form->isVisible();
        }));
        form->machineEdit()->setText(QStringLiteral("Press 2"));
        form->nameEdit()->setText(QStringLiteral("press"));
        form->connectEdit()->setText(QStringLiteral("sim"));
        form->addressesEdit()->setText(QStringLiteral("3"));
        form->accept(); // addresses on an HSP5 link: refused, the form stays
        QVERIFY2(form->problem().contains(QStringLiteral("links[0].addresses")),
                 qPrintable(form->problem()));
        form->addressesEdit()->clear();
        form->accept();
        QFileDialog *files = nullptr;
        QVERIFY(QTest::qWaitFor([&] {
            files = m_window->findChild<QFileDialog *>(QStringLiteral("parameterFileDialog"));
            return files && files->isVisible();
        }));
        const QString path = m_dir.filePath(QStringLiteral("press2.json"));
        files->selectFile(path);
        static_cast<QDialog *>(files)->accept(); // QFileDialog::accept() is protected
        QVERIFY(QTest::qWaitFor([&] { return m_dock->plantPath() == path; }));
        QVERIFY2(readText(path).contains(QStringLiteral("\"name\": \"Press 2\"")), qPrintable(readText(path)));
        QCOMPARE(PlantFeature::recentPlants().value(0), path);
        QCOMPARE(shown(QStringLiteral("press"), -1, PlantModel::StateColumn),
                 QStringLiteral("not searched"));
    }

    // A link whose drives all stopped answering is no longer shown answering.
    void aLinkWhoseDrivesAllFailIsUnreachable()
    {
        QString error;
        QVERIFY2(m_dock->openPlant(m_plantPath, &error), qPrintable(error));
        QVERIFY(runJob(m_dock->findAction()));
        const QModelIndex cabinet = model()->index(0, PlantModel::StateColumn);
        QCOMPARE(cabinet.siblingAtColumn(PlantModel::NameColumn).data().toString(),
                 QStringLiteral("cabinet"));
        QCOMPARE(cabinet.data().toString(), QStringLiteral("answering"));
        // The device server gone: the link cannot be opened, none of its drives reached.
        const quint16 port = m_cabinet->port();
        m_cabinet->close();
        QVERIFY(runJob(m_dock->verifyAction()));
        QVERIFY2(m_cabinet->listen(port, &error), qPrintable(error));
        for (const int address : {2, 5}) {
            QCOMPARE(shown(QStringLiteral("cabinet"), address, PlantModel::StateColumn),
                     QStringLiteral("unreachable"));
        }
        QCOMPARE(model()->index(0, PlantModel::StateColumn).data().toString(),
                 QStringLiteral("unreachable"));
        QCOMPARE(shown(QStringLiteral("hoist"), -1, PlantModel::StateColumn),
                 QStringLiteral("answering"));
    }

    // Another plant whose links carry the same names (every machine has its "cabinet") shows
    // none of what the jobs on the plant before found: its drives were never contacted.
    void anotherPlantWithTheSameLinkNamesStartsClean()
    {
        QString error;
        QVERIFY2(m_dock->openPlant(m_plantPath, &error), qPrintable(error));
        QVERIFY(runJob(m_dock->findAction()));
        QCOMPARE(shown(QStringLiteral("hoist"), -1, PlantModel::StateColumn),
                 QStringLiteral("answering"));
        const QString other = m_dir.filePath(QStringLiteral("line4.json"));
        QFile file(other);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(readText(m_plantPath).toUtf8());
        file.close();
        QVERIFY2(m_dock->openPlant(other, &error), qPrintable(error));
        for (const auto &[link, address] : {std::pair{QStringLiteral("cabinet"), 2},
                                            std::pair{QStringLiteral("cabinet"), 5},
                                            std::pair{QStringLiteral("hoist"), -1}}) {
            QCOMPARE(shown(link, address, PlantModel::StateColumn), QStringLiteral("not searched"));
            QCOMPARE(shown(link, address, PlantModel::IdentificationColumn), QString());
            QCOMPARE(shown(link, address, PlantModel::ResultColumn), QString());
        }
    }
};

QTEST_MAIN(TestPlantView)
#include "tst_plantview.moc"
