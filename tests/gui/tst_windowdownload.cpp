#include "tst_mainwindow_support.h"

#include "journal/Journal.h"
#include "parameters/ParameterDocument.h"
#include "transfer/DownloadDialog.h"
#include "transfer/DownloadFeature.h"
#include "transfer/ExportFeature.h"

#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>
#include <QTreeWidget>

#include <algorithm>
#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

constexpr quint16 kSoftwareVersion = 0x0E06; // In.06
constexpr quint16 kEnergySaving = 0x0506;    // uF.06, plaintexts in three bit fields

void setValue(DriveDescription &drive, quint16 address, int set, qint32 raw)
{
    for (GroupDescription &group : drive.groups) {
        for (ParameterDescription &parameter : group.parameters) {
            if (parameter.address == address)
                parameter.values[std::size_t(set)] = raw;
        }
    }
}

} // namespace

// A parameter file downloaded to the drive from the window: the last look, the checks, the
// sets chosen, the writing and the report, and the table reading the drive again.
class TestWindowDownload : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;

    DownloadFeature *feature() const { return m_window->findChild<DownloadFeature *>(); }
    DownloadDialog *dialog() const { return feature()->dialog(); }
    template<typename T>
    T *part(const char *name) const
    {
        return dialog() ? dialog()->findChild<T *>(QString::fromLatin1(name)) : nullptr;
    }
    std::optional<qint32> onDrive(quint16 address, int set) const
    {
        return driveValue(m_window->session()->client(), address, set);
    }

    // The drive's parameter list as the window saves it, changed by `edit`, in a file.
    template<typename Edit>
    QString fileWith(const QString &name, Edit edit)
    {
        const QString path = m_dir.filePath(name);
        if (!saveDriveAndWait(*m_window, path))
            return {};
        std::optional<DriveDescription> file = ParameterDocument::load(path);
        if (!file)
            return {};
        edit(*file);
        return ParameterDocument::save(path, *file) ? path : QString();
    }

    // The rows of the last look: "op.20|set 3|100 1/min|777 1/min".
    QStringList rows() const
    {
        QStringList rows;
        auto *list = part<QTreeWidget>("downloadList");
        for (int i = 0; list && i < list->topLevelItemCount(); ++i) {
            const QTreeWidgetItem *item = list->topLevelItem(i);
            rows << QStringList{ item->text(0), item->text(2), item->text(3), item->text(4),
                                 item->text(5) }
                        .join(QLatin1Char('|'));
        }
        return rows;
    }

    // The window's journal's entries after the entry `after` (the journal outlives the test).
    static QList<JournalEntry> journalEntries(qint64 after = 0)
    {
        Journal journal; // the default one, in the test's own data folder
        QList<JournalEntry> found;
        if (!journal.open(Journal::Access::Read))
            return found;
        for (const JournalEntry &entry : journal.entries().value_or(QList<JournalEntry>())) {
            if (entry.id > after)
                found << entry;
        }
        return found;
    }

    static qint64 lastEntry()
    {
        const QList<JournalEntry> entries = journalEntries();
        return entries.isEmpty() ? 0 : entries.constLast().id;
    }

    bool planned() const
    {
        return QTest::qWaitFor(
            [this] { return dialog() && dialog()->run()->stage() == DownloadRun::Stage::Planned; },
            kWaitMs);
    }

    bool writeAndFinish()
    {
        auto *write = part<QPushButton>("downloadWrite");
        if (!write || !write->isEnabled())
            return false;
        write->click();
        return QTest::qWaitFor(
            [this] { return dialog()->run()->stage() == DownloadRun::Stage::Done; }, kWaitMs);
    }

private slots:
    void init()
    {
        m_settings.clear();
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1300, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QVERIFY(connectAndRead(*m_window, simulated()));
    }

    void cleanup() { m_window.reset(); }

    void aFileIsWrittenAfterALastLook()
    {
        const QString file = fileWith(QStringLiteral("changed.json"), [](DriveDescription &d) {
            setValue(d, kFixedSpeed1, 3, 777);
            setValue(d, kDemoPeriod, 0, 300);
        });
        QVERIFY(!file.isEmpty());
        auto *action = m_window->findChild<QAction *>(QStringLiteral("downloadAction"));
        QVERIFY(action->isEnabled());
        feature()->downloadFile(file);
        QVERIFY(planned());
        QVERIFY(!action->isEnabled()); // one download at a time
        const QStringList shown = rows();
        QVERIFY2(shown.contains(QStringLiteral("op.20|set 3|100 1/min|777 1/min|")), qPrintable(shown.join(QLatin1Char('\n'))));
        QVERIFY2(shown.contains(QStringLiteral("op.05||20.0 s|30.0 s|")), qPrintable(shown.join(QLatin1Char('\n'))));
        QVERIFY(shown.contains(QStringLiteral("Fr.09||0|0|always written")));
        QVERIFY(!part<QLabel>("downloadProblems")->isVisible());
        QVERIFY(part<QPushButton>("downloadWrite")->text().startsWith(QStringLiteral("&Write 4 Value")));
        QCOMPARE(onDrive(kFixedSpeed1, 3), 100); // nothing written before the click

        QVERIFY(writeAndFinish());
        QCOMPARE(onDrive(kFixedSpeed1, 3), 777);
        QCOMPARE(onDrive(kDemoPeriod, 0), 300);
        const QString report = part<QPlainTextEdit>("downloadReport")->toPlainText();
        QVERIFY2(report.contains(QStringLiteral("op.20  Fixed speed 1: set 3: 777 1/min")), qPrintable(report));
        QVERIFY(part<QLabel>("downloadStatus")->text().contains(QStringLiteral("everything to write was written")));
        // The table reads the drive again.
        QTRY_COMPARE_WITH_TIMEOUT(m_window->model()->state()->value(kFixedSpeed1, 3), 777, kWaitMs);
        dialog()->reject();
        QTRY_VERIFY(!dialog());
        QTRY_VERIFY(action->isEnabled());
    }

    // Drive > Journal Every Write on (as it is unless turned off): each value the download
    // writes has its entry in the window's journal, as the drive took it; off: none.
    void theDownloadIsJournaledWhileJournalEveryWriteIsOn()
    {
        const QString file = fileWith(QStringLiteral("journaled.json"), [](DriveDescription &d) {
            setValue(d, kFixedSpeed1, 5, 555);
        });
        QVERIFY(!file.isEmpty());
        auto *journalAction = m_window->findChild<QAction *>(QStringLiteral("journalWritesAction"));
        QVERIFY(journalAction->isChecked());
        const qint64 last = lastEntry();
        feature()->downloadFile(file);
        QVERIFY(planned());
        QVERIFY(writeAndFinish());
        QCOMPARE(onDrive(kFixedSpeed1, 5), 555);
        const QList<JournalEntry> entries = journalEntries(last);
        QCOMPARE(entries.size(), dialog()->run()->plan().valueCount());
        const auto fixedSpeed = std::find_if(entries.begin(), entries.end(), [](const JournalEntry &e) {
            return e.parameterAddress == kFixedSpeed1;
        });
        QVERIFY(fixedSpeed != entries.end());
        QCOMPARE(fixedSpeed->jobDescription, QStringLiteral("download of journaled.json"));
        QCOMPARE(fixedSpeed->set, 5);
        QCOMPARE(fixedSpeed->before.raw, 100);
        QCOMPARE(fixedSpeed->written.raw, 555);
        QCOMPARE(fixedSpeed->readBack.raw, 555);
        QCOMPARE(fixedSpeed->outcome, JournalOutcome::Written);
        QCOMPARE(fixedSpeed->drive.link, m_window->session()->settings().target());
        QVERIFY(!fixedSpeed->drive.serialNumber.isEmpty());
        dialog()->reject();
        QTRY_VERIFY(!dialog());

        journalAction->setChecked(false);
        const QString unjournaled = fileWith(QStringLiteral("unjournaled.json"), [](DriveDescription &d) {
            setValue(d, kFixedSpeed1, 6, 666);
        });
        QVERIFY(!unjournaled.isEmpty());
        const qint64 lastBefore = lastEntry();
        feature()->downloadFile(unjournaled);
        QVERIFY(planned());
        QVERIFY(writeAndFinish());
        QCOMPARE(onDrive(kFixedSpeed1, 6), 666);
        QVERIFY(journalEntries(lastBefore).isEmpty());
        dialog()->reject();
        QTRY_VERIFY(!dialog());
    }

    void aFileOfAnotherDriveNeedsTheChecksOverruled()
    {
        const QString file = fileWith(QStringLiteral("other.json"), [](DriveDescription &d) {
            setValue(d, kSoftwareVersion, 0, 170);
            setValue(d, kFixedSpeed1, 1, 555);
        });
        feature()->downloadFile(file);
        QVERIFY(planned());
        auto *problems = part<QLabel>("downloadProblems");
        QVERIFY(problems->isVisible());
        QVERIFY2(problems->text().contains(QStringLiteral("In.06 Software version is 1.70 in the file, 1.82 on the drive")),
                 qPrintable(problems->text()));
        QVERIFY(!part<QPushButton>("downloadWrite")->isEnabled());
        part<QCheckBox>("downloadForce")->setChecked(true);
        QVERIFY(writeAndFinish());
        QCOMPARE(onDrive(kFixedSpeed1, 1), 555);
    }

    void theSetsChosenLimitTheWrite()
    {
        const QString file = fileWith(QStringLiteral("sets.json"), [](DriveDescription &d) {
            setValue(d, kFixedSpeed1, 1, 555);
            setValue(d, kFixedSpeed1, 2, 556);
        });
        feature()->downloadFile(file);
        QVERIFY(planned());
        part<QCheckBox>("downloadSet2")->setChecked(false);
        const QStringList shown = rows();
        QVERIFY(shown.contains(QStringLiteral("op.20|set 1|100 1/min|555 1/min|")));
        QVERIFY(!shown.join(QLatin1Char('\n')).contains(QStringLiteral("556")));
        QVERIFY(writeAndFinish());
        QCOMPARE(onDrive(kFixedSpeed1, 1), 555);
        QCOMPARE(onDrive(kFixedSpeed1, 2), 100);
    }

    void closingBeforeTheWriteWritesNothing()
    {
        const QString file = fileWith(QStringLiteral("closed.json"), [](DriveDescription &d) {
            setValue(d, kFixedSpeed1, 4, 444);
        });
        feature()->downloadFile(file);
        QVERIFY(planned());
        dialog()->reject();
        QTRY_VERIFY(!dialog());
        QCOMPARE(onDrive(kFixedSpeed1, 4), 100);
    }

    // The drive stops answering while the values are on their way: none is answered, yet any
    // may have reached it, so the table does not go on showing what it read before as what the
    // drive holds: it reads the drive again all the same.
    void aDownloadWithoutAnswersReadsTheDriveAgain()
    {
        ServedDrive server(Protocol::Hsp5, answeringAtOnce());
        const QString problem = serveAndConnect(*m_window, server);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const QString file = fileWith(QStringLiteral("unanswered.json"), [](DriveDescription &d) {
            setValue(d, kFixedSpeed1, 3, 777);
        });
        QVERIFY(!file.isEmpty());
        feature()->downloadFile(file);
        QVERIFY(planned());
        server.setSilent(true);
        QVERIFY(writeAndFinish());
        const QString report = part<QPlainTextEdit>("downloadReport")->toPlainText();
        QVERIFY2(report.startsWith(QStringLiteral("0 value")) && report.contains(QStringLiteral("no answer")),
                 qPrintable(report));
        QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("read again")),
                 qPrintable(m_window->statusBar()->currentMessage()));
        // The reading ends with its summary, whatever the silent drive left it to read.
        const QRegularExpression summary(QStringLiteral("\\d+ value(s|\\(s\\))? read"));
        QTRY_VERIFY_WITH_TIMEOUT(m_window->statusBar()->currentMessage().contains(summary), kWaitMs);
        server.setSilent(false);
    }

    // File > Export as CSV: what the table shows, as core's CSV rule writes it.
    void theDriveReadIsExportedForASpreadsheet()
    {
        auto *action = m_window->findChild<QAction *>(QStringLiteral("exportCsvAction"));
        QVERIFY(action && action->isEnabled());
        const QString path = m_dir.filePath(QStringLiteral("drive.csv"));
        QVERIFY(m_window->findChild<ExportFeature *>()->exportCsv(path));
        QFile csv(path);
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + kSimulatedParameters);
        QVERIFY(lines.contains(QStringLiteral("op.20,Fixed speed 1,1/min,100,100,100,100,100,100,100,100")));
        QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("drive.csv")));
        // A folder that is not there: a message, and no file.
        QVERIFY(!m_window->findChild<ExportFeature *>()->exportCsv(m_dir.filePath(QStringLiteral("none/x.csv"))));
        QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("Not exported")));
        // ... and a box titled by what the user did, not by another command.
        auto *box = m_window->findChild<QMessageBox *>(QStringLiteral("fileProblem"));
        QVERIFY(box);
        QTRY_VERIFY(box->isVisible());
        QCOMPARE(box->windowTitle(), QStringLiteral("Export as CSV"));
        QVERIFY(box->text().contains(QStringLiteral("Not exported")));
        box->close();
    }

    // The file dialog's next folder is where the last file went, never a folder the export
    // could not write to.
    void aFailedExportsFolderIsNotOfferedNextTime()
    {
        const QString key = QStringLiteral("files/lastDirectory");
        auto exportTo = [this](const QString &path) {
            m_window->findChild<QAction *>(QStringLiteral("exportCsvAction"))->trigger();
            QFileDialog *dialog = nullptr;
            if (!QTest::qWaitFor([&] {
                    dialog = m_window->findChild<QFileDialog *>(QStringLiteral("parameterFileDialog"));
                    return dialog && dialog->isVisible();
                }, kWaitMs))
                return false;
            dialog->selectFile(path);
            static_cast<QDialog *>(dialog)->accept(); // QFileDialog::accept() is protected
            return true;
        };
        QVERIFY(exportTo(m_dir.filePath(QStringLiteral("good.csv"))));
        QTRY_VERIFY(QFile::exists(m_dir.filePath(QStringLiteral("good.csv"))));
        QCOMPARE(QSettings().value(key).toString(), QDir(m_dir.path()).absolutePath());

        // A folder the dialog shows but no file can be made in, even by an administrator.
        QVERIFY(exportTo(QStringLiteral("/proc/drive.csv")));
        QTRY_VERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("Not exported")));
        if (auto *box = m_window->findChild<QMessageBox *>(QStringLiteral("fileProblem")))
            box->close();
        QCOMPARE(QSettings().value(key).toString(), QDir(m_dir.path()).absolutePath());
    }

    // A German window exports as a German spreadsheet reads it: ';' between the fields, the
    // decimal comma unquoted. (The command line keeps ',' and '.', tst_cliread.)
    void aGermanExportIsForAGermanSpreadsheet()
    {
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        const QString path = m_dir.filePath(QStringLiteral("drive-de.csv"));
        const bool exported = m_window->findChild<ExportFeature *>()->exportCsv(path);
        QLocale::setDefault(before);
        QVERIFY(exported);
        QFile csv(path);
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + kSimulatedParameters);
        QCOMPARE(lines.first().count(QLatin1Char(';')), 10);
        QVERIFY(!lines.first().contains(QLatin1Char(',')));
        QVERIFY2(lines.contains(QStringLiteral("op.05;Demo cycle period;s;20,0;;;;;;;")),
                 qPrintable(lines.filter(QStringLiteral("op.05")).join(QLatin1Char('\n'))));
    }

    // Long plaintexts on both sides: "To write" stays in view, the texts whole in tool tips.
    void longPlaintextsLeaveToWriteInView()
    {
        const QString file = fileWith(QStringLiteral("energy.json"), [](DriveDescription &d) {
            setValue(d, kEnergySaving, 0, 0x92); // at actual = set value, ramp / 2, shown
        });
        QVERIFY(!file.isEmpty());
        feature()->downloadFile(file);
        QVERIFY(planned());
        QCOMPARE(part<QLabel>("downloadIntro")->text(),
                 QStringLiteral("Writes the values of %1 to the drive, each read back.")
                     .arg(QDir::toNativeSeparators(file)));
        auto *list = part<QTreeWidget>("downloadList");
        QTRY_VERIFY(list->isVisible());
        const QTreeWidgetItem *energy = nullptr;
        for (int i = 0; i < list->topLevelItemCount(); ++i) {
            if (list->topLevelItem(i)->text(0) == QStringLiteral("uF.06"))
                energy = list->topLevelItem(i);
        }
        QVERIFY2(energy, qPrintable(rows().join(QLatin1Char('\n'))));
        QCOMPARE(energy->toolTip(4), energy->text(4));
        QHeaderView *header = list->header();
        const int right = header->sectionViewportPosition(4) + header->sectionSize(4);
        QVERIFY2(right <= list->viewport()->width(),
                 qPrintable(QStringLiteral("'To write' ends at %1 of %2 px; '%3' -> '%4'")
                                .arg(right)
                                .arg(list->viewport()->width())
                                .arg(energy->text(3), energy->text(4))));
    }

    void aCorruptFileIsNamedAndNothingStarts()
    {
        const QString path = m_dir.filePath(QStringLiteral("broken.json"));
        QFile broken(path);
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{\n  \"format\": \"drivedesk-parameters\",\n  \"version\": 1,\n  \"groups\": [\n");
        broken.close();
        feature()->downloadFile(path);
        QVERIFY(!dialog());
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("broken.json")) && message.contains(QStringLiteral("line")),
                 qPrintable(message));
        // Shown in a box as File > Open shows it, not only in the status bar.
        auto *box = m_window->findChild<QMessageBox *>(QStringLiteral("fileProblem"));
        QVERIFY(box);
        QTRY_VERIFY(box->isVisible());
        QCOMPARE(box->windowTitle(), QStringLiteral("Download File to Drive"));
        QCOMPARE(box->text(), message);
        box->close();
    }
};

QTEST_MAIN(TestWindowDownload)
#include "tst_windowdownload.moc"
