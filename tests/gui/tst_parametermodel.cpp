#include "../parameters/EditorSampleDrive.h"

#include "model/ParameterModel.h"

#include <QAbstractItemModelTester>
#include <QDateTime>
#include <QFont>
#include <QGuiApplication>
#include <QIcon>
#include <QPalette>
#include <QSignalSpy>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

namespace {

QString shown(const ParameterModel &model, quint16 address, int column)
{
    return model.indexOf(address, column).data().toString();
}

QString shownValue(const ParameterModel &model, quint16 address, int set = 0)
{
    return model.valueIndex(address, set).data().toString();
}

// The model only asks for a write; the edit path (ValueEdits::pending) has the cells marked.
void markPendingAsTheEditPathDoes(ParameterModel &model)
{
    QObject::connect(&model, &ParameterModel::valueEdited, model.state(), &DriveState::markPending);
}

} // namespace

// The parameter tree: what it shows, value updates, edit states, password level, favourites.
class TestParameterModel : public QObject
{
    Q_OBJECT
private slots:
    void passesTheModelTesterThroughFillUpdatesAndReset()
    {
        ParameterModel model;
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        model.state()->setDescription(drive());
        model.state()->setValue(kMaxFrequency, 2, 7000);
        model.state()->setValues(kMaxFrequency, 0xF0, 100);
        model.setShowRawValues(true);
        model.state()->setPasswordLevel(PasswordLevel::CpReadOnly);
        model.setFavourite(kRampTime, true);
        QVERIFY(model.setData(model.indexOf(kState), true, ParameterModel::FavouriteRole));
        model.state()->setPasswordLevel(PasswordLevel::Supervisor);
        QVERIFY(model.setData(model.valueIndex(kMaxFrequency, 1), 7100));
        model.state()->markFailed(kMaxFrequency, 0x02, QStringLiteral("write protected"));
        model.state()->setDescription(drive());
        model.state()->clear();
        QCOMPARE(model.rowCount(), 0);
    }

    void groupsInTheDrivesOrderWithTheirParameters()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QCOMPARE(model.rowCount(), 4);
        QCOMPARE(model.columnCount(), int(ParameterModel::ColumnCount));
        const QModelIndex ru = model.index(0, 0);
        QCOMPARE(ru.data().toString(), QStringLiteral("ru  Run display"));
        QVERIFY(ru.data(ParameterModel::IsGroupRole).toBool());
        QCOMPARE(model.rowCount(ru), 2);
        QCOMPARE(model.rowCount(model.index(1, 0)), 3);
        QCOMPARE(model.rowCount(model.index(3, 0)), 0);
        QCOMPARE(model.index(1, 0, ru).data().toString(), QStringLiteral("ru.03"));
        QCOMPARE(model.index(1, ParameterModel::NameColumn, ru).data().toString(),
                 QStringLiteral("Actual frequency"));
        QCOMPARE(model.indexOf(kFrequency).parent(), ru);
        QCOMPARE(model.indexOf(kControl).data().toString(), QStringLiteral("Pn.05"));
        QCOMPARE(model.indexOf(kControl).data(ParameterModel::AddressRole).toUInt(),
                 uint(kControl));
        QCOMPARE(model.headerData(ParameterModel::columnOfSet(3), Qt::Horizontal).toString(),
                 QStringLiteral("Set 3"));
        QCOMPARE(model.headerData(ParameterModel::MinimumColumn, Qt::Horizontal).toString(),
                 QStringLiteral("Minimum"));
    }

    void showsValuesAsTheDriveDoes()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QCOMPARE(shownValue(model, kState), QStringLiteral("Fcon"));
        QCOMPARE(shownValue(model, kFrequency), QStringLiteral("-52.25 Hz"));
        QCOMPARE(shownValue(model, kMaxFrequency, 0), QStringLiteral("50.00 Hz"));
        QCOMPARE(shownValue(model, kMaxFrequency, 1), QStringLiteral("60.00 Hz"));
        QCOMPARE(shownValue(model, kRampTime), QStringLiteral("5.00 s"));
        QCOMPARE(shownValue(model, kSource), QStringLiteral("analog"));
        QCOMPARE(shownValue(model, kControl), QStringLiteral("forward | released"));
        QCOMPARE(shownValue(model, kErrorMask), QStringLiteral("00FFh"));

        QCOMPARE(shown(model, kMaxFrequency, ParameterModel::MinimumColumn),
                 QStringLiteral("0.00"));
        QCOMPARE(shown(model, kMaxFrequency, ParameterModel::MaximumColumn),
                 QStringLiteral("400.00"));
        QCOMPARE(shown(model, kMaxFrequency, ParameterModel::DefaultColumn),
                 QStringLiteral("50.00"));
        QCOMPARE(shown(model, kMaxFrequency, ParameterModel::UnitColumn), QStringLiteral("Hz"));
        QCOMPARE(shown(model, kSource, ParameterModel::DefaultColumn), QStringLiteral("digital"));
        QCOMPARE(shown(model, kFrequency, ParameterModel::AccessColumn),
                 QStringLiteral("read-only (read: CP read only)"));
        QCOMPARE(shown(model, kService, ParameterModel::AccessColumn),
                 QStringLiteral("read: CP service, write: Application"));
        QCOMPARE(model.indexOf(kMaxFrequency, ParameterModel::MaximumColumn)
                     .data(ParameterModel::RawValueRole)
                     .toInt(),
                 40000);
    }

    void aSingleValueFillsTheFirstValueColumnOnly()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        const QModelIndex first = model.indexOf(kRampTime, ParameterModel::columnOfSet(0));
        const QModelIndex second = model.indexOf(kRampTime, ParameterModel::columnOfSet(1));
        QCOMPARE(first.data(ParameterModel::SetRole).toInt(), 0);
        QCOMPARE(second.data(ParameterModel::SetRole).toInt(), -1);
        QVERIFY(second.data().toString().isEmpty());
        QVERIFY(first.flags() & Qt::ItemIsEditable);
        QVERIFY(!(second.flags() & Qt::ItemIsEditable));
        // Any set reaches the one value; its cell is the first.
        QCOMPARE(model.valueIndex(kRampTime, 5), first);
        QVERIFY(model.state()->setValue(kRampTime, 5, 700));
        QCOMPARE(first.data().toString(), QStringLiteral("7.00 s"));
        QCOMPARE(model.state()->value(kRampTime, 0).value_or(-1), 700);
    }

    void unreadValuesAreMarkedNotGuessed()
    {
        DriveDescription description = drive();
        description.groups[1].parameters[1].values[0].reset();
        description.groups[1].parameters[1].error = QStringLiteral("inverter busy");
        ParameterModel model;
        model.state()->setDescription(description);
        const QModelIndex cell = model.valueIndex(kRampTime, 0);
        QCOMPARE(cell.data().toString(), QStringLiteral("?"));
        QVERIFY(!cell.data(ParameterModel::RawValueRole).isValid());
        QVERIFY(cell.data(Qt::ToolTipRole).toString().contains(QStringLiteral("inverter busy")));
        QVERIFY(!model.state()->value(kRampTime, 0));
    }

    void showsRawValuesOnDemand()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QCOMPARE(model.valueIndex(kFrequency, 0).data(ParameterModel::RawValueRole).toInt(), -4180);
        model.setShowRawValues(true);
        QVERIFY(model.showsRawValues());
        QVERIFY(!changed.isEmpty());
        QCOMPARE(shownValue(model, kFrequency), QStringLiteral("-4180"));
        QCOMPARE(shownValue(model, kState), QStringLiteral("66"));
        QCOMPARE(shownValue(model, kErrorMask), QStringLiteral("255"));
        QCOMPARE(shown(model, kMaxFrequency, ParameterModel::MaximumColumn),
                 QStringLiteral("40000"));
        QVERIFY(model.valueIndex(kState, 0).data(ParameterModel::RawModeRole).toBool());
        model.setShowRawValues(false);
        QCOMPARE(shownValue(model, kFrequency), QStringLiteral("-52.25 Hz"));
    }

    void aValueUpdateChangesJustItsCell()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QSignalSpy reset(&model, &QAbstractItemModel::modelAboutToBeReset);
        QVERIFY(model.state()->setValue(kMaxFrequency, 3, 7000));
        QCOMPARE(changed.size(), 1);
        const QModelIndex cell = model.valueIndex(kMaxFrequency, 3);
        QCOMPARE(changed.at(0).at(0).value<QModelIndex>(), cell);
        QCOMPARE(changed.at(0).at(1).value<QModelIndex>(), cell);
        QCOMPARE(cell.data().toString(), QStringLiteral("70.00 Hz"));

        // The same value again: nothing to redraw.
        QVERIFY(model.state()->setValue(kMaxFrequency, 3, 7000));
        QCOMPARE(changed.size(), 1);

        // A burst, as polling the run display brings it: one cell each, never a reset.
        for (int i = 0; i < 500; ++i)
            model.state()->setValue(kFrequency, 0, i);
        QCOMPARE(changed.size(), 1 + 500);
        QCOMPARE(reset.size(), 0);
        QCOMPARE(shownValue(model, kFrequency), QStringLiteral("6.24 Hz"));

        QVERIFY(!model.state()->setValue(0x0999, 0, 1));
        QVERIFY(!model.state()->setValue(kMaxFrequency, 8, 1));
        QCOMPARE(changed.size(), 501);
    }

    void valuesNotReadSinceTheDriveFellSilentAreStale()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QAbstractItemModelTester tester(&model);
        QVERIFY(model.state()->setValue(kFrequency, 0, 100));
        const QModelIndex cell = model.valueIndex(kFrequency, 0);
        const QDateTime read = cell.data(ParameterModel::LastReadRole).toDateTime();
        QVERIFY(read.isValid());
        QVERIFY(!cell.data(ParameterModel::StaleRole).toBool());
        const QVariant freshForeground = cell.data(Qt::ForegroundRole);

        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        model.state()->setStaleSince(read.toMSecsSinceEpoch() + 1000);
        QVERIFY(!changed.isEmpty());
        QVERIFY(model.state()->isStale(kFrequency));
        QVERIFY(cell.data(ParameterModel::StaleRole).toBool());
        QVERIFY(cell.data(Qt::FontRole).value<QFont>().italic());
        QVERIFY(cell.data(Qt::ForegroundRole) != freshForeground);
        const QString tip = cell.data(Qt::ToolTipRole).toString();
        QVERIFY2(tip.startsWith(QStringLiteral("Last read %1; the drive is not answering")
                                    .arg(read.toString(QStringLiteral("HH:mm:ss")))),
                 qPrintable(tip));
        // Only value cells: the id and the name are not values of the drive.
        QVERIFY(!model.indexOf(kFrequency).data(ParameterModel::StaleRole).toBool());

        // The drive answers again: nothing is stale.
        model.state()->setStaleSince(0);
        QVERIFY(!cell.data(ParameterModel::StaleRole).toBool());
        QVERIFY(!cell.data(Qt::FontRole).value<QFont>().italic());
        QVERIFY(!cell.data(Qt::ToolTipRole).toString().contains(QStringLiteral("not answering")));

        // A value read after the drive fell silent is fresh, even when it did not change.
        const qint64 since = read.toMSecsSinceEpoch() + 1;
        model.state()->setStaleSince(since);
        QVERIFY(model.state()->isStale(kFrequency));
        changed.clear();
        QTRY_VERIFY(QDateTime::currentMSecsSinceEpoch() > since);
        QVERIFY(model.state()->setValue(kFrequency, 0, 100));
        QVERIFY(!model.state()->isStale(kFrequency));
        QCOMPARE(changed.size(), 1); // its row, so that the mark goes
    }

    void editingEmitsValueEditedAndMarksThePendingCell()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        markPendingAsTheEditPathDoes(model);
        QSignalSpy edited(&model, &ParameterModel::valueEdited);
        const QModelIndex cell = model.valueIndex(kMaxFrequency, 2);
        QVERIFY(model.setData(cell, 7000));
        QCOMPARE(edited.size(), 1);
        QCOMPARE(edited.at(0).at(0).value<quint16>(), kMaxFrequency);
        QCOMPARE(edited.at(0).at(1).value<quint8>(), quint8(0x04));
        QCOMPARE(edited.at(0).at(2).value<qint32>(), 7000);
        QCOMPARE(cell.data(ParameterModel::EditStateRole).value<EditState>(), EditState::Pending);
        QCOMPARE(cell.data().toString(), QStringLiteral("70.00 Hz"));
        QVERIFY(cell.data(Qt::BackgroundRole).value<QColor>().isValid());
        QVERIFY(!cell.data(Qt::DecorationRole).value<QIcon>().isNull());
        // The drive's value stays what it reported until the write is confirmed.
        QCOMPARE(model.state()->value(kMaxFrequency, 2).value_or(-1), 5000);

        // A parameter that is not set-programmable is written as set 0.
        QVERIFY(model.setData(model.valueIndex(kRampTime, 0), QStringLiteral("12.5 s")));
        QCOMPARE(edited.size(), 2);
        QCOMPARE(edited.at(1).at(1).value<quint8>(), quint8(0x01));
        QCOMPARE(edited.at(1).at(2).value<qint32>(), 1250);

        // Outside the limits, not exact, or what the drive already holds: nothing is written.
        QVERIFY(!model.setData(model.valueIndex(kMaxFrequency, 0), 50000));
        QVERIFY(!model.setData(model.valueIndex(kRampTime, 0), QStringLiteral("12.555")));
        QVERIFY(model.setData(model.valueIndex(kMaxFrequency, 0), 5000));
        QCOMPARE(edited.size(), 2);
        QCOMPARE(model.state()->editState(kMaxFrequency, 0), EditState::None);

        QString error;
        QVERIFY(!model.requestWrite(kMaxFrequency, 0x01, -1, &error));
        QCOMPARE(error, QStringLiteral("oP.10: -0.01 Hz is outside the limits 0.00 .. 400.00 Hz"));
        QVERIFY(model.requestWrite(kMaxFrequency, 0xFF, 100, &error));
        QCOMPARE(edited.size(), 3);
        for (int set = 0; set < kParameterSets; ++set)
            QCOMPARE(model.state()->editState(kMaxFrequency, set), EditState::Pending);
    }

    void writtenAndFailedCellsSayWhy()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        markPendingAsTheEditPathDoes(model);
        QVERIFY(model.requestWrite(kMaxFrequency, 0x06, 7000));
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        model.state()->markWritten(kMaxFrequency, 0x02);
        QCOMPARE(changed.size(), 1);
        QCOMPARE(model.state()->editState(kMaxFrequency, 1), EditState::Written);
        QCOMPARE(model.state()->value(kMaxFrequency, 1).value_or(-1), 7000);
        const QColor written
            = model.valueIndex(kMaxFrequency, 1).data(Qt::BackgroundRole).value<QColor>();

        model.state()->markFailed(kMaxFrequency, 0x04, QStringLiteral("parameter write protected"));
        const QModelIndex failed = model.valueIndex(kMaxFrequency, 2);
        QCOMPARE(failed.data(ParameterModel::EditStateRole).value<EditState>(), EditState::Failed);
        QCOMPARE(failed.data(Qt::ToolTipRole).toString(),
                 QStringLiteral("Writing 70.00 Hz failed: parameter write protected"));
        QCOMPARE(failed.data().toString(), QStringLiteral("50.00 Hz")); // what the drive holds
        QVERIFY(failed.data(Qt::BackgroundRole).value<QColor>() != written);

        // A read-back that differs from what was written fails the cell.
        QVERIFY(model.requestWrite(kMaxFrequency, 0x08, 8000));
        model.state()->confirmReadBack(kMaxFrequency, 3, 7999);
        QCOMPARE(model.state()->editState(kMaxFrequency, 3), EditState::Failed);
        QCOMPARE(model.valueIndex(kMaxFrequency, 3).data(Qt::ToolTipRole).toString(),
                 QStringLiteral("Writing 80.00 Hz failed: the drive holds 79.99 Hz, not 80.00 Hz"));
        QVERIFY(model.requestWrite(kMaxFrequency, 0x10, 8000));
        model.state()->confirmReadBack(kMaxFrequency, 4, 8000);
        QCOMPARE(model.state()->editState(kMaxFrequency, 4), EditState::Written);

        model.state()->clearEditStates();
        for (int set = 0; set < kParameterSets; ++set)
            QCOMPARE(model.state()->editState(kMaxFrequency, set), EditState::None);
        QVERIFY(!model.valueIndex(kMaxFrequency, 2).data(Qt::BackgroundRole).isValid());
    }

    // A parameter file's changed cell: marked as a written one, with a tip of its own, never
    // taken for a write to a drive, and unmarked when its value is put back.
    void changedFileCellsLookWrittenAndSaySo()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QVERIFY(model.state()->putValue(kMaxFrequency, 1, 7000));
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        model.state()->markChanged(kMaxFrequency, 0x02);
        QCOMPARE(changed.size(), 1);
        const QModelIndex cell = model.valueIndex(kMaxFrequency, 1);
        QCOMPARE(cell.data(ParameterModel::EditStateRole).value<EditState>(), EditState::Changed);
        QCOMPARE(cell.data(Qt::BackgroundRole).value<QColor>(),
                 CellDecoration().background(EditState::Written));
        QVERIFY(!cell.data(Qt::DecorationRole).value<QIcon>().isNull());
        QCOMPARE(cell.data(Qt::ToolTipRole).toString(),
                 QStringLiteral("Changed in the file: 70.00 Hz; save to keep it"));
        QCOMPARE(cell.data().toString(), QStringLiteral("70.00 Hz"));
        // Nothing was asked of a drive: a stray "written" leaves the cell as it is.
        model.state()->markWritten(kMaxFrequency, 0x02);
        QCOMPARE(model.state()->editState(kMaxFrequency, 1), EditState::Changed);
        QCOMPARE(model.state()->value(kMaxFrequency, 1), 7000);

        QVERIFY(model.state()->putValue(kMaxFrequency, 1, 5000));
        QCOMPARE(model.state()->editState(kMaxFrequency, 1), EditState::None);
        QVERIFY(!cell.data(Qt::BackgroundRole).isValid());
    }

    void editStateColoursKeepTheThemesLightness()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        markPendingAsTheEditPathDoes(model);
        QVERIFY(model.requestWrite(kRampTime, 0x01, 900));
        const QModelIndex cell = model.valueIndex(kRampTime, 0);
        const QPalette original = QGuiApplication::palette();
        QPalette dark = original;
        dark.setColor(QPalette::Base, QColor(30, 30, 30));
        dark.setColor(QPalette::Text, QColor(230, 230, 230));
        QGuiApplication::setPalette(dark);
        const QColor onDark = cell.data(Qt::BackgroundRole).value<QColor>();
        QGuiApplication::setPalette(original);
        const QColor onLight = cell.data(Qt::BackgroundRole).value<QColor>();
        QVERIFY(onDark.lightness() < 110);
        QVERIFY(onLight.lightness() > 150);
        QVERIFY(onDark != QColor(30, 30, 30)); // still marked
    }

    void readOnlyParametersAreNotEditable()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        const QModelIndex cell = model.valueIndex(kFrequency, 0);
        QVERIFY(!(cell.flags() & Qt::ItemIsEditable));
        QVERIFY(!cell.data(ParameterModel::EditableRole).toBool());
        QVERIFY(!model.setData(cell, 100));
        QString error;
        QVERIFY(!model.requestWrite(kFrequency, 0x01, 100, &error));
        QCOMPARE(error, QStringLiteral("ru.03 is read-only"));
        QVERIFY(!(model.indexOf(kMaxFrequency, ParameterModel::NameColumn).flags()
                  & Qt::ItemIsEditable));
    }

    void parametersAboveThePasswordLevelAreLocked()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QVERIFY(model.state()->isEditable(kService));
        QSignalSpy level(model.state(), &DriveState::passwordLevelChanged);
        model.state()->setPasswordLevel(PasswordLevel::CpReadWrite);
        QCOMPARE(level.size(), 1);
        const QModelIndex service = model.valueIndex(kService, 0);
        QVERIFY(service.data(ParameterModel::AboveLevelRole).toBool());
        QVERIFY(!(service.flags() & Qt::ItemIsEditable));
        QVERIFY(service.data(Qt::ForegroundRole).value<QColor>().isValid());
        QVERIFY(model.state()->isEditable(kMaxFrequency));
        QString error;
        QVERIFY(!model.requestWrite(kService, 0x01, 20, &error));
        QCOMPARE(error, QStringLiteral("Pn.07 needs password level Application (in force: CP read/write)"));

        model.state()->setPasswordLevel(PasswordLevel::CpReadOnly);
        QVERIFY(model.state()->isAboveLevel(kMaxFrequency)); // written from CP read/write on
        QVERIFY(!model.state()->isAboveLevel(kFrequency)); // read-only: only its read level counts
        QVERIFY(!model.indexOf(kFrequency).data(Qt::ForegroundRole).isValid());
    }

    void marksFavourites()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        QSignalSpy favourites(&model, &ParameterModel::favouritesChanged);
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        const QModelIndex id = model.indexOf(kRampTime);
        const qint64 plain = id.data(Qt::DecorationRole).value<QIcon>().cacheKey();
        model.toggleFavourite(kRampTime);
        QVERIFY(model.isFavourite(kRampTime));
        QVERIFY(id.data(ParameterModel::FavouriteRole).toBool());
        QVERIFY(id.data(Qt::DecorationRole).value<QIcon>().cacheKey() != plain);
        QCOMPARE(favourites.size(), 1);
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed.at(0).at(0).value<QModelIndex>(), id);

        QVERIFY(model.setData(model.valueIndex(kSource, 0), true, ParameterModel::FavouriteRole));
        QCOMPARE(model.favourites(), (QSet<quint16> { kRampTime, kSource }));
        model.setFavourites({ kSource, 0x0999 }); // the caller's set may name other drives' ones
        QVERIFY(!model.isFavourite(kRampTime));
        QCOMPARE(favourites.size(), 3);

        model.state()->setDescription(drive());
        QVERIFY(model.indexOf(kSource).data(ParameterModel::FavouriteRole).toBool());
    }

    void knowsWhichValuesDifferFromTheDefault()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        auto differs = [&model](quint16 address) {
            return model.indexOf(address).data(ParameterModel::DiffersFromDefaultRole).toBool();
        };
        QVERIFY(differs(kMaxFrequency)); // set 1 only
        QVERIFY(!differs(kRampTime));
        QVERIFY(differs(kControl));
        QVERIFY(!differs(kErrorMask));
        model.state()->setValue(kMaxFrequency, 1, 5000);
        QVERIFY(!differs(kMaxFrequency));

        // What the user cannot set is no setting that differs: read-only values, values the
        // drive changes itself (properties 2 bit 9), the password parameter.
        QVERIFY(model.state()->value(kFrequency, 0) != model.state()->parameter(kFrequency)->defaultValue);
        QVERIFY(!differs(kFrequency));
        DriveDescription changing = drive();
        auto *ramp = const_cast<ParameterDescription *>(changing.find(kRampTime));
        ramp->properties2 |= 1u << 9;
        ramp->values[0] = 700;
        model.state()->setDescription(changing);
        QVERIFY(!differs(kRampTime));
        ramp->properties2 &= ~(1u << 9);
        model.state()->setDescription(changing);
        QVERIFY(differs(kRampTime));
    }

    void searchTextHoldsIdsNameAndShownValues()
    {
        ParameterModel model;
        model.state()->setDescription(drive());
        const QString text
            = model.indexOf(kFrequency).data(ParameterModel::SearchTextRole).toString();
        for (const char *part : { "ru.03", "ru.3", "0203h", "actual frequency", "-52.25 hz" })
            QVERIFY2(text.contains(QLatin1String(part)), part);
        model.state()->setValue(kFrequency, 0, 800);
        QVERIFY(model.indexOf(kFrequency)
                    .data(ParameterModel::SearchTextRole)
                    .toString()
                    .contains(QStringLiteral("10.00 hz")));
    }

    void givesBackTheDescriptionWithTheValuesHeldNow()
    {
        ParameterModel model;
        const DriveDescription original = drive();
        model.state()->setDescription(original);
        QCOMPARE(model.state()->description(), original);
        model.state()->setValue(kMaxFrequency, 7, 1234);
        QVERIFY(model.requestWrite(kRampTime, 0x01, 900)); // pending: not the drive's yet
        const DriveDescription now = model.state()->description();
        QCOMPARE(now.find(kMaxFrequency)->values[7].value_or(-1), 1234);
        QCOMPARE(now.find(kRampTime)->values[0].value_or(-1), 500);
        QCOMPARE(model.state()->parameter(kControl)->name, QStringLiteral("Control word"));
        QVERIFY(!model.state()->parameter(0x0999));
    }
};

QTEST_MAIN(TestParameterModel)
#include "tst_parametermodel.moc"
