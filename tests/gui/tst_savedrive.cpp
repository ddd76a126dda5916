#include "tst_mainwindow_support.h"

#include "frame/NoticeBar.h"
#include "parameters/ParameterDocument.h"

#include <QAction>
#include <QFileDialog>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>

#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

// File > Save Drive to File: a backup of the drive as it is, read afresh, whatever the table
// shows (a scan cancelled halfway, values gone stale), or no backup at all.
class TestSaveDrive : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;

    QString path(const QString &name) const { return m_dir.filePath(name); }
    SaveDriveFeature *saveDrive() const { return m_window->findChild<SaveDriveFeature *>(); }

    QAction *saveDriveAction() const
    {
        return m_window->findChild<QAction *>(QStringLiteral("saveDriveAction"));
    }
    QString statusMessage() const { return m_window->statusBar()->currentMessage(); }
    QProgressBar *noticeProgress() const
    {
        return m_window->noticeBar()->findChild<QProgressBar *>(QStringLiteral("noticeProgress"));
    }

    // File > Save Drive to File, `file` chosen in its file dialog.
    bool chooseSaveDrive(const QString &file)
    {
        saveDriveAction()->trigger();
        QFileDialog *dialog = nullptr;
        if (!QTest::qWaitFor(
                [&] {
                    dialog
                        = m_window->findChild<QFileDialog *>(QStringLiteral("parameterFileDialog"));
                    return dialog && dialog->isVisible();
                },
                kWaitMs))
            return false;
        dialog->selectFile(file);
        static_cast<QDialog *>(dialog)->accept(); // QFileDialog::accept() is protected
        return saveDrive()->isSavingDrive();
    }

    // The drive's parameter list as an upload reads it, past the window.
    DriveDescription parameterListOnDrive() const
    {
        ScanOptions options;
        options.parameterList = true;
        const QFuture<DriveDescription> future = m_window->session()->client()->scan(options);
        if (!QTest::qWaitFor([&] { return future.isFinished(); }, 120000)
            || future.resultCount() == 0)
            return {};
        return future.result();
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void init()
    {
        m_settings.clear();
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    }

    void cleanup() { m_window.reset(); }

    void aDriveReadInPartIsReadWholeBeforeItIsSaved()
    {
        ConnectionSettings settings = simulated();
        settings.simulation.replyLatencyUs = 3000; // slow enough to cancel halfway
        m_window->connectTo(settings);
        QTRY_VERIFY_WITH_TIMEOUT(
            noticeProgress()->maximum() == 1000 && noticeProgress()->value() > 600, 60000);
        QTest::mouseClick(
            m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeCancel")),
            Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->noticeBar()->kind(), NoticeBar::Kind::Problem, kWaitMs);
        const QString partNotice = m_window->noticeBar()->text();
        QVERIFY2(partNotice.contains(QStringLiteral("read only in part")), qPrintable(partNotice));
        const int shown = m_window->model()->state()->description().parameterCount();
        QVERIFY2(shown > 0 && shown < kSimulatedParameters, qPrintable(QString::number(shown)));

        const QString file = path(QStringLiteral("part.json"));
        QVERIFY(saveDriveAction()->isEnabled());
        QVERIFY(chooseSaveDrive(file));
        // Reading, with progress and Cancel where the scan showed them; one read at a time.
        QCOMPARE(m_window->noticeBar()->kind(), NoticeBar::Kind::Progress);
        QVERIFY2(m_window->noticeBar()->text().contains(QStringLiteral("Saving the drive to "
                                                                       "part.json")),
                 qPrintable(m_window->noticeBar()->text()));
        QVERIFY(!saveDriveAction()->isEnabled());
        QVERIFY(!m_window->findChild<QAction *>(QStringLiteral("refreshAction"))->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!saveDrive()->isSavingDrive(), 120000);

        // Whole, or nothing: never the part the table shows.
        QVERIFY2(QFileInfo::exists(file), qPrintable(statusMessage()));
        QVERIFY2(statusMessage().startsWith(QStringLiteral("Saved"))
                     && statusMessage().contains(QStringLiteral("part.json")),
                 qPrintable(statusMessage()));
        QString error;
        const std::optional<DriveDescription> saved = ParameterDocument::load(file, &error);
        QVERIFY2(saved, qPrintable(error));
        const DriveDescription list = parameterListOnDrive();
        QVERIFY(list.incompleteReason.isEmpty());
        QCOMPARE(saved->parameterCount(), list.parameterCount());
        QVERIFY(saved->parameterCount() > shown);
        for (const GroupDescription &group : list.groups) {
            for (const ParameterDescription &parameter : group.parameters) {
                const ParameterDescription *inFile = saved->find(parameter.address);
                QVERIFY2(inFile, qPrintable(parameter.name));
                QVERIFY2(inFile->error.isEmpty(), qPrintable(inFile->error));
                const int sets = parameter.isSetProgrammable() ? kParameterSets : 1;
                for (int set = 0; set < sets; ++set)
                    QVERIFY2(inFile->values[std::size_t(set)], qPrintable(parameter.name));
            }
        }
        // The notice of the part read is back; the table is as it was.
        QCOMPARE(m_window->noticeBar()->text(), partNotice);
        QCOMPARE(m_window->model()->state()->description().parameterCount(), shown);
    }

    void staleValuesAreReadAgainBeforeTheyAreSaved()
    {
        ServedDrive server(Protocol::Hsp5, answeringAtOnce());
        const QString problem = serveAndConnect(*m_window, server);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const QModelIndex speed = m_window->model()->valueIndex(kFixedSpeed1, 2);
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 2), 100);

        // Polling notices the silence (and, later, the drive back).
        auto *polling = m_window->findChild<QAction *>(QStringLiteral("pollingAction"));
        polling->setChecked(true);

        // Silent: the table's values go stale, and no backup can be read.
        server.setSilent(true);
        QTRY_VERIFY_WITH_TIMEOUT(speed.data(ParameterModel::StaleRole).toBool(), kWaitMs);
        const QString whileSilent = path(QStringLiteral("silent.json"));
        QVERIFY(saveDrive()->saveDriveToFile(whileSilent));
        QMessageBox *refusal = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT(
            (refusal = m_window->findChild<QMessageBox *>(QStringLiteral("uploadRefused")))
                && refusal->isVisible(),
            kWaitMs);
        QVERIFY2(refusal->text().contains(QStringLiteral("stopped answering"))
                     && refusal->text().contains(QStringLiteral("nothing was saved")),
                 qPrintable(refusal->text()));
        QVERIFY(!QFileInfo::exists(whileSilent));
        QVERIFY(!saveDrive()->isSavingDrive());
        refusal->accept();

        // Back, with a value changed that the table has not read since.
        server.setSilent(false);
        QTRY_VERIFY_WITH_TIMEOUT(!speed.data(ParameterModel::StaleRole).toBool(), kWaitMs);
        polling->setChecked(false);
        const QFuture<Reply> write
            = m_window->session()->client()->writeValue(kFixedSpeed1, 777, quint8(1u << 2));
        QVERIFY(waitFinished(write) && write.result().ok());
        QCOMPARE(m_window->model()->state()->value(kFixedSpeed1, 2), 100);

        const QString file = path(QStringLiteral("fresh.json"));
        QVERIFY(saveDriveAndWait(*m_window, file));
        QString error;
        const std::optional<DriveDescription> saved = ParameterDocument::load(file, &error);
        QVERIFY2(saved, qPrintable(error));
        QCOMPARE(saved->find(kFixedSpeed1)->values[2], 777);
        QCOMPARE(saved->find(kFixedSpeed1)->values[3], 100);
    }

    void aCancelledSaveSavesNothing()
    {
        ConnectionSettings settings = simulated();
        settings.simulation.replyLatencyUs = 3000;
        m_window->connectTo(settings);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->isReady(), 120000);
        const QString file = path(QStringLiteral("cancelled.json"));
        QVERIFY(saveDrive()->saveDriveToFile(file));
        QTRY_VERIFY_WITH_TIMEOUT(noticeProgress()->value() > 100, 60000);
        QTest::mouseClick(
            m_window->noticeBar()->findChild<QPushButton *>(QStringLiteral("noticeCancel")),
            Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!saveDrive()->isSavingDrive(), kWaitMs);
        QVERIFY2(statusMessage().contains(QStringLiteral("cancelled"))
                     && statusMessage().contains(QStringLiteral("nothing was saved")),
                 qPrintable(statusMessage()));
        QVERIFY(!QFileInfo::exists(file));
        QVERIFY(!m_window->noticeBar()->isVisible());
        QVERIFY(saveDriveAction()->isEnabled());
    }
};

QTEST_MAIN(TestSaveDrive)
#include "tst_savedrive.moc"
