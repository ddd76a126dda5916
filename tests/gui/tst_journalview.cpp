// The journal view (View > Journal, docs/journal.md) offscreen: its filters and search over a
// journal of the test's own, a page at a time; an entry written later appears on refresh; a
// value's tooltip names its last change. In the window against the simulated drive: a value
// written appears in the view, and Revert puts the value before back through the download's
// last look, writing nothing else; another drive's entry is refused and nothing written.
#include "tst_mainwindow_support.h"

#include "journal/Journal.h"
#include "journal/JournalFeature.h"
#include "journal/JournalDock.h"
#include "journal/JournalTableModel.h"
#include "transfer/DownloadDialog.h"
#include "transfer/DownloadFeature.h"

#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScopeGuard>
#include <QTableView>
#include <QTreeWidget>

#include <algorithm>
#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

JournalDrive driveNumbered(const QString &serialNumber)
{
    JournalDrive drive;
    drive.link = QStringLiteral("serial:/dev/ttyUSB0");
    drive.protocol = QStringLiteral("hsp5");
    drive.kind = QStringLiteral("F5");
    drive.softwareVersion = QStringLiteral("1.80");
    drive.serialNumber = serialNumber;
    return drive;
}

// An entry of op.28 set 2 written `minutes` after 2026-11-24 10:00 local time.
JournalEntry entryAt(int minutes, const QString &user, const QString &serialNumber,
                     const QString &parameterId = QStringLiteral("op.28"))
{
    JournalEntry entry;
    entry.time = QDateTime(QDate(2026, 11, 24), QTime(10, 0), Qt::LocalTime).addSecs(minutes * 60);
    entry.user = user;
    entry.host = QStringLiteral("line3-laptop");
    entry.drive = driveNumbered(serialNumber);
    entry.parameterId = parameterId;
    entry.parameterAddress = parameterId == QLatin1String("op.28") ? 0x031C : 0x0314;
    entry.parameterName = QStringLiteral("Acceleration time");
    entry.set = 2;
    entry.before = { 500, QStringLiteral("5.00 s") };
    entry.written = { 750, QStringLiteral("7.50 s") };
    return entry;
}

void removeJournal(const QString &path)
{
    for (const char *suffix : { "", "-wal", "-shm" })
        QFile::remove(path + QLatin1String(suffix));
}

// The rows the view shows: "id|user|parameter".
QStringList shown(const JournalDock &dock)
{
    QStringList rows;
    const QAbstractItemModel *model = dock.view()->model();
    for (int row = 0; row < model->rowCount(); ++row) {
        rows << QStringList { model->index(row, JournalTableModel::IdColumn).data().toString(),
                              model->index(row, JournalTableModel::UserColumn).data().toString(),
                              model->index(row, JournalTableModel::ParameterColumn).data().toString() }
                    .join(QLatin1Char('|'));
    }
    return rows;
}

// Types into a filter field as a user would, and leaves it.
void typeInto(JournalDock &dock, const char *field, const QString &text)
{
    auto *edit = dock.findChild<QLineEdit *>(QLatin1String(field));
    edit->setText(text);
    edit->setModified(true);
    emit edit->editingFinished();
}

} // namespace

class TestJournalView : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_dir;

private slots:
    void init() { m_settings.clear(); }

    void filtersAndSearchPickEntries()
    {
        const QString path = m_dir.filePath(QStringLiteral("filters.sqlite"));
        {
            Journal journal(path);
            QVERIFY2(journal.open(), qPrintable(journal.errorString()));
            QVERIFY(journal.begin(entryAt(0, QStringLiteral("anna"), QStringLiteral("1111"))));
            QVERIFY(journal.begin(entryAt(60, QStringLiteral("ben"), QStringLiteral("2222"),
                                          QStringLiteral("op.20"))));
            QVERIFY(journal.begin(entryAt(24 * 60, QStringLiteral("anna"), QStringLiteral("2222"))));
        }
        JournalDock dock(nullptr, path);
        dock.resize(1200, 400);
        dock.show();
        QTRY_COMPARE(shown(dock), (QStringList { QStringLiteral("3|anna|op.28"),
                                                 QStringLiteral("2|ben|op.20"),
                                                 QStringLiteral("1|anna|op.28") }));
        QVERIFY2(dock.statusText().contains(QStringLiteral("3 entries")), qPrintable(dock.statusText()));

        typeInto(dock, "journalUser", QStringLiteral("anna"));
        QTRY_COMPARE(shown(dock), (QStringList { QStringLiteral("3|anna|op.28"),
                                                 QStringLiteral("1|anna|op.28") }));
        typeInto(dock, "journalDrive", QStringLiteral("2222"));
        QTRY_COMPARE(shown(dock), QStringList { QStringLiteral("3|anna|op.28") });
        typeInto(dock, "journalUser", QString());
        typeInto(dock, "journalParameter", QStringLiteral("OP.020"));
        QTRY_COMPARE(shown(dock), QStringList { QStringLiteral("2|ben|op.20") });
        typeInto(dock, "journalDrive", QString());
        typeInto(dock, "journalParameter", QString());
        typeInto(dock, "journalUntil", QStringLiteral("2026-11-24"));
        QTRY_COMPARE(shown(dock), (QStringList { QStringLiteral("2|ben|op.20"),
                                                 QStringLiteral("1|anna|op.28") }));
        typeInto(dock, "journalSince", QStringLiteral("2026-11-24 10:30"));
        QTRY_COMPARE(shown(dock), QStringList { QStringLiteral("2|ben|op.20") });

        // A time that cannot be read says so, and shows nothing.
        typeInto(dock, "journalSince", QStringLiteral("yesterday"));
        QTRY_VERIFY2(dock.statusText().contains(QStringLiteral("'yesterday' is no time")),
                     qPrintable(dock.statusText()));
        QCOMPARE(shown(dock), QStringList());
        typeInto(dock, "journalSince", QString());
        typeInto(dock, "journalUntil", QString());
        QTRY_COMPARE(shown(dock).size(), 3);

        // The search matches any field of the entries read.
        dock.findChild<QLineEdit *>(QStringLiteral("journalSearch"))->setText(QStringLiteral("BEN"));
        QCOMPARE(shown(dock), QStringList { QStringLiteral("2|ben|op.20") });
        dock.findChild<QLineEdit *>(QStringLiteral("journalSearch"))->clear();
        QCOMPARE(shown(dock).size(), 3);

        // Written later: on top after a refresh.
        {
            Journal journal(path);
            QVERIFY(journal.open());
            QVERIFY(journal.begin(entryAt(25 * 60, QStringLiteral("carl"), QStringLiteral("1111"))));
        }
        dock.refresh();
        QTRY_COMPARE(shown(dock).value(0), QStringLiteral("4|carl|op.28"));
        QCOMPARE(shown(dock).size(), 4);

        // The filters are remembered.
        typeInto(dock, "journalUser", QStringLiteral("carl"));
        dock.saveSettings();
        JournalDock again(nullptr, path);
        again.show();
        QTRY_COMPARE(shown(again), QStringList { QStringLiteral("4|carl|op.28") });
    }

    void aBigJournalIsReadAPageAtATime()
    {
        const QString path = m_dir.filePath(QStringLiteral("big.sqlite"));
        const int count = JournalDock::kPageSize + 500;
        {
            Journal journal(path);
            QVERIFY(journal.open());
            for (int i = 0; i < count; ++i)
                QVERIFY(journal.begin(entryAt(i, QStringLiteral("anna"), QStringLiteral("1111"))));
        }
        JournalDock dock(nullptr, path);
        dock.show();
        QTRY_COMPARE(dock.model()->rowCount(), JournalDock::kPageSize);
        QCOMPARE(dock.model()->newestId(), qint64(count));
        auto *older = dock.findChild<QPushButton *>(QStringLiteral("journalLoadOlder"));
        QVERIFY(older->isEnabled());
        older->click();
        QTRY_COMPARE(dock.model()->rowCount(), count);
        QCOMPARE(dock.model()->oldestId(), qint64(1));
        QTRY_VERIFY(!older->isEnabled());
    }

    void theTooltipNamesTheLastChange()
    {
        ParameterDescription acceleration;
        acceleration.address = 0x031C;
        acceleration.name = QStringLiteral("Acceleration time");
        acceleration.properties1 = 1u << 11;
        acceleration.maximum = 10000;
        acceleration.values.fill(500);
        GroupDescription op;
        op.address = 0x0300;
        op.id = QStringLiteral("op");
        op.parameters = { acceleration };
        DriveDescription drive;
        drive.groups = { op };
        DriveState state;
        state.setDescription(drive);
        ParameterModel model(&state);
        const QModelIndex cell = model.valueIndex(0x031C, 2);
        QVERIFY(!cell.data(Qt::ToolTipRole).toString().contains(QStringLiteral("since")));

        JournalEntry change = entryAt(42, QStringLiteral("anna"), QStringLiteral("1111"));
        change.id = 7;
        change.time = QDateTime::currentDateTime().toUTC();
        change.readBack = change.written;
        change.outcome = JournalOutcome::Written;
        state.setJournalChanges(JournalChanges::of({ change }));
        const QString expected = QStringLiteral("7.50 s since %1 by anna, was 5.00 s")
                                     .arg(change.time.toLocalTime().toString(QStringLiteral("HH:mm")));
        QVERIFY2(cell.data(Qt::ToolTipRole).toString().contains(expected),
                 qPrintable(cell.data(Qt::ToolTipRole).toString()));
        // Another set's cell has no change of its own.
        QVERIFY(!model.valueIndex(0x031C, 3).data(Qt::ToolTipRole).toString().contains(
            QStringLiteral("since")));
    }

    // drivedesk --journal PATH: the window's edits go there and its view reads it; the journal
    // in the standard place is left alone.
    void aJournalNamedAtStartTakesTheWindowsWrites()
    {
        const QString standard = Journal::defaultPath();
        removeJournal(standard);
        const QString chosen = m_dir.filePath(QStringLiteral("machine-7.sqlite"));
        Journal::setDefaultPath(chosen);
        const auto standardAgain = qScopeGuard([] { Journal::setDefaultPath({}); });
        QCOMPARE(Journal::defaultPath(), chosen);
        {
            MainWindow window;
            window.resize(1300, 900);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QVERIFY(connectAndRead(window, simulated()));
            window.browser()->showGroup(QStringLiteral("op"));
            QVERIFY(window.browser()->view()->model()->setData(viewIndex(window, kFixedSpeed1, 2),
                                                               QStringLiteral("345")));
            QTRY_COMPARE_WITH_TIMEOUT(window.model()->state()->value(kFixedSpeed1, 2), 345,
                                      kWaitMs);
            JournalDock *dock = window.findChild<JournalFeature *>()->dock();
            window.findChild<QAction *>(QStringLiteral("journalViewAction"))->trigger();
            QTRY_VERIFY_WITH_TIMEOUT(!shown(*dock).isEmpty()
                                         && shown(*dock).constFirst().endsWith(
                                             QStringLiteral("|op.20")),
                                     kWaitMs);
        }
        Journal journal(chosen);
        QVERIFY2(journal.open(Journal::Access::Read), qPrintable(journal.errorString()));
        const std::optional<QList<JournalEntry>> entries = journal.entries();
        QVERIFY(entries);
        QCOMPARE(entries->size(), 1);
        QCOMPARE(entries->constFirst().written.raw, std::optional<qint32>(345));
        QVERIFY(!QFileInfo::exists(standard));
    }

    void aWriteAppearsAndIsReverted()
    {
        removeJournal(Journal::defaultPath());
        MainWindow window;
        window.resize(1300, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(connectAndRead(window, simulated()));
        auto *feature = window.findChild<JournalFeature *>();
        QVERIFY(feature);
        JournalDock *dock = feature->dock();
        window.findChild<QAction *>(QStringLiteral("journalViewAction"))->trigger();
        QTRY_VERIFY(dock->isVisible());

        window.browser()->showGroup(QStringLiteral("op"));
        const QModelIndex cell = viewIndex(window, kFixedSpeed1, 2);
        QVERIFY(window.browser()->view()->model()->setData(cell, QStringLiteral("345")));
        QTRY_COMPARE_WITH_TIMEOUT(window.model()->state()->value(kFixedSpeed1, 2), 345, kWaitMs);
        QTRY_VERIFY_WITH_TIMEOUT(!shown(*dock).isEmpty()
                                     && shown(*dock).constFirst().endsWith(QStringLiteral("|op.20")),
                                 kWaitMs);
        const QAbstractItemModel *rows = dock->view()->model();
        QCOMPARE(rows->index(0, JournalTableModel::BeforeColumn).data().toString(),
                 QStringLiteral("100 1/min"));
        QCOMPARE(rows->index(0, JournalTableModel::WrittenColumn).data().toString(),
                 QStringLiteral("345 1/min"));
        // The cell's tooltip names the change.
        const auto tooltip = [&window] {
            return viewIndex(window, kFixedSpeed1, 2).data(Qt::ToolTipRole).toString();
        };
        QTRY_VERIFY2_WITH_TIMEOUT(tooltip().contains(QStringLiteral("345 1/min since")),
                                  qPrintable(tooltip()), kWaitMs);
        QVERIFY2(tooltip().contains(QStringLiteral("was 100 1/min")), qPrintable(tooltip()));

        // Revert: the download's last look lists the one value, then writes it.
        dock->view()->selectRow(0);
        auto *revert = dock->findChild<QPushButton *>(QStringLiteral("journalRevert"));
        QTRY_VERIFY(revert->isEnabled());
        revert->click();
        auto *download = window.findChild<DownloadFeature *>();
        QTRY_VERIFY_WITH_TIMEOUT(download->dialog()
                                     && download->dialog()->run()->stage()
                                         == DownloadRun::Stage::Planned,
                                 kWaitMs);
        auto *list = download->dialog()->findChild<QTreeWidget *>(QStringLiteral("downloadList"));
        QTRY_COMPARE(list->topLevelItemCount(), 1);
        QCOMPARE(list->topLevelItem(0)->text(0), QStringLiteral("op.20"));
        QCOMPARE(download->dialog()->run()->options().journalJob, QStringLiteral("revert of entry 1"));
        const QList<QLabel *> labels = download->dialog()->findChildren<QLabel *>();
        QVERIFY(std::any_of(labels.begin(), labels.end(), [](const QLabel *label) {
            return label->text()
                == QLatin1String("Writes the value before entry 1 to the drive, each read back.");
        }));
        QCOMPARE(driveValue(window.session()->client(), kFixedSpeed1, 2), 345); // not yet
        auto *write = download->dialog()->findChild<QPushButton *>(QStringLiteral("downloadWrite"));
        QVERIFY(write->isEnabled());
        write->click();
        QTRY_VERIFY_WITH_TIMEOUT(download->dialog()->run()->stage() == DownloadRun::Stage::Done,
                                 kWaitMs);
        QCOMPARE(driveValue(window.session()->client(), kFixedSpeed1, 2), 100);
        for (int set : { 0, 1, 3 })
            QCOMPARE(driveValue(window.session()->client(), kFixedSpeed1, set), 100);
        download->dialog()->reject();
        QTRY_VERIFY(!download->dialog());

        // Another drive's entry: refused, said so, and no download begins.
        {
            Journal journal;
            QVERIFY(journal.open());
            JournalEntry other = entryAt(0, QStringLiteral("ben"), QStringLiteral("999999"),
                                         QStringLiteral("op.20"));
            QVERIFY(journal.begin(other));
        }
        dock->refresh();
        QTRY_VERIFY(shown(*dock).constFirst().contains(QStringLiteral("|ben|")));
        dock->view()->clearSelection();
        dock->view()->selectRow(0);
        revert->click();
        auto *box = window.findChild<QMessageBox *>(QStringLiteral("fileProblem"));
        QTRY_VERIFY(box && box->isVisible());
        QVERIFY2(box->text().contains(QStringLiteral("another drive (999999)")), qPrintable(box->text()));
        QVERIFY(!download->dialog());
        box->close();
    }
};

QTEST_MAIN(TestJournalView)
#include "tst_journalview.moc"
