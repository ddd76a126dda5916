#include "tst_mainwindow_support.h"

#include "compare/CompareFeature.h"
#include "compare/CompareWindow.h"
#include "compare/ComparisonFilterModel.h"
#include "compare/ComparisonModel.h"
#include "files/ParameterFileFeature.h"
#include "transfer/DownloadDialog.h"
#include "transfer/DownloadFeature.h"
#include "parameters/ChosenValues.h"
#include "parameters/DriveIdentity.h"
#include "parameters/ParameterDocument.h"

#include <QAbstractItemModelTester>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QUndoStack>

#include <memory>

using namespace DriveDesk;
using namespace DriveDesk::MainWindowTest;

namespace {

DriveDescription withValue(DriveDescription drive, quint16 address, int set, qint32 raw)
{
    for (GroupDescription &group : drive.groups) {
        for (ParameterDescription &parameter : group.parameters) {
            if (parameter.address == address)
                parameter.values[std::size_t(set)] = raw;
        }
    }
    return drive;
}

// The rows the view shows, as "op.20 3 100 1/min | 250 1/min different" lines.
QStringList shownRows(const CompareWindow &window)
{
    QStringList lines;
    const QAbstractItemModel *model = window.filterModel();
    for (int g = 0; g < model->rowCount(); ++g) {
        const QModelIndex group = model->index(g, 0);
        for (int r = 0; r < model->rowCount(group); ++r) {
            auto cell = [&](int column) { return model->index(r, column, group).data().toString(); };
            lines << QStringLiteral("%1 %2 %3 | %4 %5")
                         .arg(cell(ComparisonModel::IdColumn), cell(ComparisonModel::SetColumn),
                              cell(ComparisonModel::AColumn), cell(ComparisonModel::BColumn),
                              cell(ComparisonModel::StateColumn));
        }
    }
    return lines;
}

// The view's index of the row of a parameter and set (A's set), column Id.
QModelIndex rowOf(const CompareWindow &window, quint16 address, int set)
{
    const QAbstractItemModel *model = window.filterModel();
    for (int g = 0; g < model->rowCount(); ++g) {
        const QModelIndex group = model->index(g, 0);
        for (int r = 0; r < model->rowCount(group); ++r) {
            const QModelIndex index = model->index(r, 0, group);
            if (index.data(ParameterModel::AddressRole).value<quint16>() == address
                && index.data(ParameterModel::SetRole).toInt() == set) {
                return index;
            }
        }
    }
    return {};
}

// Ticks a row with the keyboard, as a user does: the row current, then Space.
bool choose(CompareWindow &window, quint16 address, int set)
{
    const QModelIndex index = rowOf(window, address, set);
    if (!index.isValid())
        return false;
    window.view()->setCurrentIndex(index);
    window.view()->setFocus();
    QTest::keyClick(window.view(), Qt::Key_Space);
    return index.data(Qt::CheckStateRole).toInt() == Qt::Checked;
}

QPushButton *button(const CompareWindow &window, const char *name)
{
    return window.findChild<QPushButton *>(QString::fromLatin1(name));
}

// "Write 2 Values to B (b.json)"; "Value(s)" while the English catalogue lacks the plural.
bool isWriteText(const QString &text, int count, const QString &side)
{
    const QString values = count == 1 ? QStringLiteral("Value") : QStringLiteral("Values");
    return text == QStringLiteral("Write %1 %2 to %3").arg(count).arg(values, side)
        || text == QStringLiteral("Write %1 Value(s) to %2").arg(count).arg(side);
}

QCheckBox *stateBox(const CompareWindow &window, ComparisonRow::State state)
{
    return window.findChild<QCheckBox *>(QStringLiteral("showState%1").arg(int(state)));
}

} // namespace

// The compare window: two parameter files differing in known values, the rows and states it
// shows, its filters, values written into a file and nothing else, the defaults, one set
// against another, the file the main window shows, and the selection handed to the download.
class TestCompareWindow : public QObject
{
    Q_OBJECT
private:
    IsolatedSettings m_settings;
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window; // connected to the simulated drive
    DriveDescription m_a; // the drive's file
    qint32 m_demoPeriod = 0; // op.05 in the drive's file
    QString m_pathA;
    QString m_pathB;

    QString path(const QString &name) const { return m_dir.filePath(name); }

    // a.json is the drive; b.json differs in op.20 sets 3 and 5 and in op.05.
    DriveDescription makeB() const
    {
        DriveDescription b = withValue(m_a, kFixedSpeed1, 3, 250);
        b = withValue(b, kFixedSpeed1, 5, -300);
        return withValue(b, kDemoPeriod, 0, m_demoPeriod + 15);
    }

    void writeFiles()
    {
        QVERIFY(ParameterDocument::save(m_pathA, m_a));
        QVERIFY(ParameterDocument::save(m_pathB, makeB()));
    }

    static DriveDescription load(const QString &path)
    {
        QString error;
        const std::optional<DriveDescription> drive = ParameterDocument::load(path, &error);
        if (!drive)
            qWarning("%s", qPrintable(error));
        return drive.value_or(DriveDescription());
    }

    std::unique_ptr<CompareWindow> filesWindow()
    {
        auto window = std::make_unique<CompareWindow>(nullptr);
        window->setSide(true, CompareWindow::Source::File, m_pathA);
        window->setSide(false, CompareWindow::Source::File, m_pathB);
        window->show();
        return window;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_settings.clear();
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(connectAndRead(*m_window, simulated()));
        m_pathA = path(QStringLiteral("a.json"));
        m_pathB = path(QStringLiteral("b.json"));
        QVERIFY(saveDriveAndWait(*m_window, m_pathA));
        m_a = load(m_pathA);
        QVERIFY(m_a.parameterCount() > 100);
        m_demoPeriod = *m_a.find(kDemoPeriod)->values[0];
        QCOMPARE(m_a.find(kFixedSpeed1)->values[3], 100);
    }

    void init() { writeFiles(); }

    void twoFilesShowTheirDifferences()
    {
        auto window = filesWindow();
        QAbstractItemModelTester tester(window->comparisonModel());
        QVERIFY(window->compare());
        const ComparisonTable &table = window->comparisonModel()->comparison();
        QCOMPARE(table.count(ComparisonRow::State::Different), 3);
        QCOMPARE(table.count(ComparisonRow::State::OnlyInA), 0);
        QCOMPARE(table.count(ComparisonRow::State::OnlyInB), 0);
        QVERIFY(table.count(ComparisonRow::State::ReadOnly) > 0);
        QVERIFY(table.count(ComparisonRow::State::Equal) > 100);
        QVERIFY2(window->message().contains(QStringLiteral("3 value")), qPrintable(window->message()));
        // The counts on the state filters.
        QCOMPARE(stateBox(*window, ComparisonRow::State::Different)->text(),
                 QStringLiteral("&Different (3)"));

        // Only what differs: the three values, in display form.
        for (ComparisonRow::State state :
             { ComparisonRow::State::Equal, ComparisonRow::State::ReadOnly,
               ComparisonRow::State::OnlyInA, ComparisonRow::State::OnlyInB }) {
            stateBox(*window, state)->setChecked(false);
        }
        const QStringList rows = shownRows(*window);
        QCOMPARE(rows.size(), 3);
        QCOMPARE(rows[0].section(QLatin1Char(' '), 0, 1), QStringLiteral("op.05 all"));
        QVERIFY2(rows[0].endsWith(QStringLiteral(" different")), qPrintable(rows[0]));
        QCOMPARE(rows[1], QStringLiteral("op.20 3 100 1/min | 250 1/min different"));
        QCOMPARE(rows[2], QStringLiteral("op.20 5 100 1/min | -300 1/min different"));

        // Raw only when asked.
        window->findChild<QCheckBox *>(QStringLiteral("rawValues"))->setChecked(true);
        QCOMPARE(shownRows(*window)[1], QStringLiteral("op.20 3 100 | 250 different"));
        window->findChild<QCheckBox *>(QStringLiteral("rawValues"))->setChecked(false);
    }

    void filtersByGroupAndSearch()
    {
        auto window = filesWindow();
        QVERIFY(window->compare());
        auto *group = window->findChild<QComboBox *>(QStringLiteral("groupFilter"));
        group->setCurrentIndex(group->findData(QStringLiteral("In")));
        QVERIFY(group->currentIndex() > 0);
        QStringList rows = shownRows(*window);
        QVERIFY(!rows.isEmpty());
        for (const QString &row : std::as_const(rows))
            QVERIFY2(row.startsWith(QStringLiteral("In.")), qPrintable(row));
        group->setCurrentIndex(0);

        // The parameter table's search: "op20" names op.20, in every set.
        auto *search = window->findChild<QLineEdit *>(QStringLiteral("compareSearch"));
        QTest::keyClicks(search, QStringLiteral("op20"));
        rows = shownRows(*window);
        QCOMPARE(rows.size(), kParameterSets);
        for (const QString &row : std::as_const(rows))
            QVERIFY2(row.startsWith(QStringLiteral("op.20 ")), qPrintable(row));
        // A value as shown finds its parameter.
        search->setText(QStringLiteral("-300 1/min"));
        QCOMPARE(shownRows(*window).size(), kParameterSets);
        search->setText(QStringLiteral("no such text anywhere"));
        QVERIFY(shownRows(*window).isEmpty());
    }

    void chosenValuesAreWrittenIntoFileBAndNothingElse()
    {
        auto window = filesWindow();
        QVERIFY(window->compare());
        QPushButton *writeB = button(*window, "writeToBButton");
        QVERIFY(!writeB->isEnabled());
        QVERIFY(choose(*window, kFixedSpeed1, 3));
        QVERIFY(choose(*window, kDemoPeriod, 0));
        // An equal row has no check box.
        QVERIFY(!(rowOf(*window, kFixedSpeed1, 0).flags() & Qt::ItemIsUserCheckable));
        QVERIFY(writeB->isEnabled());
        QVERIFY2(isWriteText(writeB->text(), 2, QStringLiteral("B (b.json)")), qPrintable(writeB->text()));
        // The last look: only the chosen rows.
        window->findChild<QCheckBox *>(QStringLiteral("chosenOnly"))->setChecked(true);
        QCOMPARE(shownRows(*window).size(), 2);

        QTest::mouseClick(writeB, Qt::LeftButton);
        DriveDescription expected = makeB();
        expected = withValue(expected, kFixedSpeed1, 3, 100);
        expected = withValue(expected, kDemoPeriod, 0, m_demoPeriod);
        QCOMPARE(load(m_pathB), expected);
        QCOMPARE(load(m_pathA), m_a); // the source is untouched
        // Compared again: one difference left, nothing chosen.
        QCOMPARE(window->comparisonModel()->comparison().count(ComparisonRow::State::Different),
                 1);
        QVERIFY(window->comparisonModel()->chosenRows().isEmpty());
        QVERIFY2(window->message().contains(QStringLiteral("2 value")), qPrintable(window->message()));
    }

    void aValueADownloadWouldNotWriteIsNeverChosen()
    {
        DriveDescription b = withValue(makeB(), kInverterState, 0, 1234);
        QVERIFY(ParameterDocument::save(m_pathB, b));
        auto window = filesWindow();
        QVERIFY(window->compare());
        // A live value is no setting: not shown at first, shown on request, never chosen.
        QVERIFY(!rowOf(*window, kInverterState, 0).isValid());
        QCOMPARE(window->comparisonModel()->comparison().count(ComparisonRow::State::Different), 3);
        QCheckBox *notSettings = stateBox(*window, ComparisonRow::State::NotASetting);
        QVERIFY(!notSettings->isChecked());
        notSettings->setChecked(true);
        const QModelIndex state = rowOf(*window, kInverterState, 0);
        QCOMPARE(state.siblingAtColumn(ComparisonModel::StateColumn).data().toString(),
                 QStringLiteral("not a setting, different"));
        QVERIFY(!(state.flags() & Qt::ItemIsUserCheckable));
        QVERIFY(!choose(*window, kInverterState, 0));
    }

    void defaultsOfA()
    {
        auto window = filesWindow();
        window->setSide(true, CompareWindow::Source::File, m_pathB);
        window->setSide(false, CompareWindow::Source::Defaults);
        QVERIFY(window->compare());
        // Only the values a user sets; op.20 set 3 (250) and set 5 (-300) against 100.
        const ComparisonTable &table = window->comparisonModel()->comparison();
        QCOMPARE(table.count(ComparisonRow::State::OnlyInA), 0);
        QCOMPARE(table.count(ComparisonRow::State::Different),
                 compareWithDefaults(makeB()).differences.size());
        QCOMPARE(rowOf(*window, kFixedSpeed1, 3)
                     .siblingAtColumn(ComparisonModel::BColumn)
                     .data()
                     .toString(),
                 QStringLiteral("100 1/min"));
        QVERIFY(!button(*window, "writeToBButton")->isVisibleTo(window.get()));
        // Back to the default in set 3 of file B (side A here).
        QVERIFY(choose(*window, kFixedSpeed1, 3));
        QVERIFY2(isWriteText(button(*window, "writeToAButton")->text(), 1, QStringLiteral("A (b.json)")), qPrintable(button(*window, "writeToAButton")->text()));
        window->writeChosen(true);
        QCOMPARE(load(m_pathB), withValue(makeB(), kFixedSpeed1, 3, 100));
    }

    void oneSetAgainstAnother()
    {
        auto window = filesWindow();
        window->setSide(true, CompareWindow::Source::File, m_pathB);
        window->setSide(false, CompareWindow::Source::SameAsA);
        window->setSets(3, 0);
        QVERIFY(window->compare());
        const ComparisonTable &table = window->comparisonModel()->comparison();
        for (const ComparisonRow &row : table.rows) {
            QVERIFY(row.perSet);
            QCOMPARE(row.setA, 3);
            QCOMPARE(row.setB, 0);
        }
        const QModelIndex speed = rowOf(*window, kFixedSpeed1, 3);
        QCOMPARE(speed.siblingAtColumn(ComparisonModel::SetColumn).data().toString(),
                 QStringLiteral("3 / 0"));
        QCOMPARE(speed.siblingAtColumn(ComparisonModel::StateColumn).data().toString(),
                 QStringLiteral("different"));
        // Set 3's value into set 0 of the same file.
        QVERIFY(choose(*window, kFixedSpeed1, 3));
        window->writeChosen(false);
        QCOMPARE(load(m_pathB), withValue(makeB(), kFixedSpeed1, 0, 250));
    }

    void theFileShownIsWrittenThroughTheWindow()
    {
        MainWindow main;
        main.show();
        QVERIFY(main.feature<ParameterFileFeature>()->openParameterFile(m_pathA));
        auto *feature = main.findChild<CompareFeature *>();
        QVERIFY(feature);
        CompareWindow *window = feature->showCompareWindow();
        QVERIFY(window->isVisible());
        QVERIFY(!window->isModal());
        window->setSide(true, CompareWindow::Source::ShownFile);
        window->setSide(false, CompareWindow::Source::File, m_pathB);
        QVERIFY(window->compare());
        QVERIFY(choose(*window, kFixedSpeed1, 5));
        QVERIFY2(isWriteText(button(*window, "writeToAButton")->text(), 1, QStringLiteral("A (a.json (shown))")), qPrintable(button(*window, "writeToAButton")->text()));
        window->writeChosen(true);
        // An unsaved, undoable edit of the window; the file on disk is as it was.
        QCOMPARE(main.model()->state()->value(kFixedSpeed1, 5), -300);
        QVERIFY(main.feature<ParameterFileFeature>()->hasUnsavedChanges());
        QCOMPARE(load(m_pathA), m_a);
        QCOMPARE(window->comparisonModel()->comparison().count(ComparisonRow::State::Different),
                 2);
        main.undoStack()->undo();
        QCOMPARE(main.model()->state()->value(kFixedSpeed1, 5), 100);
        QVERIFY(!main.feature<ParameterFileFeature>()->hasUnsavedChanges());
        // Chosen by its path, the file shown is still written through the window.
        window->setSide(true, CompareWindow::Source::File, m_pathA);
        QVERIFY(window->compare());
        QVERIFY(choose(*window, kFixedSpeed1, 3));
        window->writeChosen(true);
        QCOMPARE(main.model()->state()->value(kFixedSpeed1, 3), 250);
        QCOMPARE(load(m_pathA), m_a);
        main.undoStack()->undo();
        window->close();
    }

    // The drive against a backup made a moment ago: what the backup leaves out (parameters
    // outside the parameter list) and live values that moved on are no difference, and the
    // default filter shows nothing to act on.
    void theDriveAgainstItsFreshBackupShowsNoDifference()
    {
        const QString backup = path(QStringLiteral("backup.json"));
        QVERIFY(saveDriveAndWait(*m_window, backup));
        auto *feature = m_window->findChild<CompareFeature *>();
        CompareWindow *window = feature->showCompareWindow();
        window->setSide(true, CompareWindow::Source::Drive);
        window->setSide(false, CompareWindow::Source::File, backup);
        QVERIFY2(window->compare(), qPrintable(window->message()));
        const ComparisonTable &table = window->comparisonModel()->comparison();
        QCOMPARE(table.count(ComparisonRow::State::Different), 0);
        QCOMPARE(table.count(ComparisonRow::State::OnlyInA), 0);
        QCOMPARE(table.count(ComparisonRow::State::OnlyInB), 0);
        QVERIFY(table.count(ComparisonRow::State::NotASetting) > 0);
        for (const ComparisonRow &row : table.rows) {
            if (row.onlyInA)
                QCOMPARE(row.state, ComparisonRow::State::NotASetting);
        }
        for (const QString &row : shownRows(*window)) {
            QVERIFY2(!row.contains(QStringLiteral("different")) && !row.contains(QStringLiteral("only in"))
                         && !row.contains(QStringLiteral("not a setting")),
                     qPrintable(row));
        }
        QVERIFY2(window->message().contains(QStringLiteral("0 value")), qPrintable(window->message()));
        window->close();
    }

    void chosenValuesReachTheDriveThroughTheDownload()
    {
        auto *feature = m_window->findChild<CompareFeature *>();
        QVERIFY(feature);
        CompareWindow *window = feature->showCompareWindow();
        window->setSide(true, CompareWindow::Source::Drive);
        window->setSide(false, CompareWindow::Source::File, m_pathB);
        QVERIFY(window->compare());
        QVERIFY(choose(*window, kFixedSpeed1, 3));
        QVERIFY(choose(*window, kDemoPeriod, 0));
        // The window's download takes the chosen values to the drive.
        QPushButton *writeA = button(*window, "writeToAButton");
        QSignalSpy requested(feature, &CompareFeature::writeToDriveRequested);
        QVERIFY(feature->canWriteToDrive());
        QVERIFY(writeA->isEnabled());
        QVERIFY2(isWriteText(writeA->text(), 2, QStringLiteral("A (the drive)")), qPrintable(writeA->text()));
        QTest::mouseClick(writeA, Qt::LeftButton);
        QCOMPARE(requested.count(), 1);
        const auto selection = requested.at(0).at(0).value<DriveDescription>();

        // B's values for the chosen rows, the identification, and nothing else.
        const DriveDescription b = makeB();
        QCOMPARE(selection.groups.size(), b.groups.size());
        QList<quint16> identification;
        for (const IdentificationParameter &id : DriveIdentity::parameters()) {
            if (const GroupDescription *group = b.findGroup(QString::fromLatin1(id.group)))
                identification << quint16(group->address | id.number);
        }
        QVERIFY(!identification.isEmpty());
        int values = 0;
        for (const GroupDescription &group : selection.groups) {
            for (const ParameterDescription &parameter : group.parameters) {
                for (int set = 0; set < kParameterSets; ++set) {
                    const std::optional<qint32> value = parameter.values[std::size_t(set)];
                    if (!value)
                        continue;
                    ++values;
                    if (identification.contains(parameter.address)) {
                        QCOMPARE(value, b.find(parameter.address)->values[std::size_t(set)]);
                    } else if (parameter.address == kFixedSpeed1) {
                        QCOMPARE(set, 3);
                        QCOMPARE(*value, 250);
                    } else {
                        QCOMPARE(parameter.address, kDemoPeriod);
                        QCOMPARE(*value, m_demoPeriod + 15);
                    }
                }
            }
        }
        int identificationValues = 0;
        for (quint16 address : std::as_const(identification))
            identificationValues += b.find(address) && b.find(address)->values[0] ? 1 : 0;
        QCOMPARE(values, identificationValues + 2);
        // The drive is untouched until the download's last look is accepted.
        QCOMPARE(driveValue(m_window->session()->client(), kFixedSpeed1, 3), 100);
        auto *download = m_window->findChild<DownloadFeature *>();
        QTRY_VERIFY_WITH_TIMEOUT(download->dialog()
                                     && download->dialog()->run()->stage() == DownloadRun::Stage::Planned,
                                 kWaitMs);
        const DownloadPlan &plan = download->dialog()->run()->plan();
        QVERIFY2(plan.problems.isEmpty(), qPrintable(plan.problems.join(QLatin1Char('\n'))));
        QCOMPARE(plan.valueCount(), 2);
        QCOMPARE(driveValue(m_window->session()->client(), kFixedSpeed1, 3), 100);
        download->dialog()->findChild<QPushButton *>(QStringLiteral("downloadWrite"))->click();
        QTRY_VERIFY_WITH_TIMEOUT(download->dialog()->run()->stage() == DownloadRun::Stage::Done, kWaitMs);
        QCOMPARE(driveValue(m_window->session()->client(), kFixedSpeed1, 3), 250);
        QCOMPARE(driveValue(m_window->session()->client(), kDemoPeriod, 0), m_demoPeriod + 15);
        // The window reads the drive again and the compare window compares again by itself:
        // what was written is equal, and nothing stays chosen.
        auto rowState = [&](quint16 address, int set) {
            return rowOf(*window, address, set).siblingAtColumn(ComparisonModel::StateColumn).data().toString();
        };
        QTRY_COMPARE_WITH_TIMEOUT(rowState(kFixedSpeed1, 3), QStringLiteral("equal"), kWaitMs);
        QCOMPARE(rowState(kDemoPeriod, 0), QStringLiteral("equal"));
        QVERIFY(window->comparisonModel()->chosenRows().isEmpty());
        QCOMPARE(window->comparisonModel()->comparison().count(ComparisonRow::State::Different), 1);
        QVERIFY(isWriteText(writeA->text(), 0, QStringLiteral("A (the drive)")));
        download->dialog()->reject();
        window->close();
    }
};

QTEST_MAIN(TestCompareWindow)
#include "tst_comparewindow.moc"
