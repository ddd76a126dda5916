#include "EditorSampleDrive.h"

#include "parameters/ChosenValues.h"
#include "parameters/ParameterComparison.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

namespace {

ParameterDescription *find(DriveDescription &drive, quint16 address)
{
    return const_cast<ParameterDescription *>(drive.find(address));
}

void remove(DriveDescription &drive, quint16 address)
{
    for (GroupDescription &group : drive.groups)
        group.parameters.removeIf(
            [address](const ParameterDescription &p) { return p.address == address; });
}

// One row as a line: "oP.10 3/3 50.00 Hz vs 40.00 Hz different". The set reads "-" for a
// parameter with one value.
QString line(const ComparisonRow &row)
{
    const QString sets = row.perSet ? QStringLiteral("%1/%2").arg(row.setA).arg(row.setB)
                                    : QStringLiteral("-");
    return QStringLiteral("%1 %2 %3 vs %4 %5")
        .arg(row.id, sets, row.a, row.b, ComparisonTable::stateText(row.state));
}

QStringList lines(const ComparisonTable &table)
{
    QStringList lines;
    for (const ComparisonRow &row : table.rows)
        lines << line(row);
    return lines;
}

// Side B of most tests: oP.10 set 3 at 40 Hz, oP.11 at 7.5 s, another actual frequency (a
// live value), no Pn.07.
DriveDescription changed()
{
    DriveDescription b = drive();
    find(b, kMaxFrequency)->values[3] = 4000;
    find(b, kRampTime)->values[0] = 750;
    find(b, kFrequency)->values[0] = 0;
    remove(b, kService);
    return b;
}

} // namespace

// The comparison behind the compare view: every parameter on both sides, set by set, in display
// form and raw, with a state; the sides made from one description (its defaults, another set);
// and what writing chosen rows puts into a file or hands a download.
class TestComparisonTable : public QObject
{
    Q_OBJECT
private slots:
    void everyValueIsARow()
    {
        const ComparisonTable table = compareAll(drive(), changed());
        const QStringList expected{
            QStringLiteral("ru.00 - Fcon vs Fcon not a setting"),
            QStringLiteral("ru.03 - -52.25 Hz vs 0.00 Hz not a setting"),
            QStringLiteral("oP.10 0/0 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 1/1 60.00 Hz vs 60.00 Hz equal"),
            QStringLiteral("oP.10 2/2 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 3/3 50.00 Hz vs 40.00 Hz different"),
            QStringLiteral("oP.10 4/4 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 5/5 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 6/6 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 7/7 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.11 - 5.00 s vs 7.50 s different"),
            QStringLiteral("oP.12 - analog vs analog equal"),
            QStringLiteral("Pn.05 - forward | released vs forward | released equal"),
            QStringLiteral("Pn.06 - 00FFh vs 00FFh equal"),
            QStringLiteral("Pn.07 - 10 vs  only in A"),
        };
        QCOMPARE(lines(table), expected);
        QCOMPARE(table.count(ComparisonRow::State::Equal), 10);
        QCOMPARE(table.count(ComparisonRow::State::Different), 2);
        QCOMPARE(table.count(ComparisonRow::State::ReadOnly), 0);
        QCOMPARE(table.count(ComparisonRow::State::NotASetting), 2);
        QCOMPARE(table.count(ComparisonRow::State::OnlyInA), 1);
        QCOMPARE(table.count(ComparisonRow::State::OnlyInB), 0);
    }

    void rowsCarryRawValuesAndGroups()
    {
        const ComparisonTable table = compareAll(drive(), changed());
        const ComparisonRow &row = table.rows[5];
        QCOMPARE(row.address, kMaxFrequency);
        QCOMPARE(row.groupId, QStringLiteral("oP"));
        QCOMPARE(row.name, QStringLiteral("Max. frequency"));
        QCOMPARE(row.rawA, std::optional<qint32>(5000));
        QCOMPARE(row.rawB, std::optional<qint32>(4000));
        QVERIFY(row.differs);
        QVERIFY(row.isWritableTo(true));
        QVERIFY(row.isWritableTo(false));
    }

    void aValueThatIsNoSettingTellsWhetherItDiffers()
    {
        const ComparisonTable table = compareAll(drive(), changed());
        QCOMPARE(table.rows[0].state, ComparisonRow::State::NotASetting);
        QVERIFY(!table.rows[0].differs);
        QCOMPARE(table.rows[1].state, ComparisonRow::State::NotASetting);
        QVERIFY(table.rows[1].differs);
        QVERIFY(!table.rows[1].isWritableTo(false));
        QVERIFY(!table.rows[1].isWritableTo(true));
    }

    // A parameter a list leaves out is "not a setting" on the side that has it, never "only in".
    void aLeftOutParameterIsNoSettingOnItsSide()
    {
        DriveDescription a = drive();
        find(a, kService)->properties2 |= 1u << 14; // excluded from the complete list
        const ComparisonTable table = compareAll(a, changed());
        QCOMPARE(table.count(ComparisonRow::State::OnlyInA), 0);
        const ComparisonRow &row = table.rows.constLast();
        QCOMPARE(row.address, kService);
        QCOMPARE(row.state, ComparisonRow::State::NotASetting);
        QVERIFY(row.onlyInA);
        QVERIFY(!row.isWritableTo(false));
    }

    // A setting a download does not write ("read only for up/download lists", properties 2
    // bit 17) is read-only here, and still a difference.
    void aSettingADownloadLeavesIsReadOnlyAndCounts()
    {
        DriveDescription a = drive();
        find(a, kRampTime)->properties2 |= 1u << 17;
        DriveDescription b = drive(); // afresh: find() writes through const
        find(b, kRampTime)->properties2 |= 1u << 17;
        find(b, kRampTime)->values[0] = 750;
        const ComparisonTable table = compareAll(a, b);
        QCOMPARE(table.rows[10].address, kRampTime);
        QCOMPARE(table.rows[10].state, ComparisonRow::State::ReadOnly);
        QVERIFY(table.rows[10].differs);
        QVERIFY(!table.rows[10].isWritableTo(true));
        QCOMPARE(compareDescriptions(a, b).differences.size(), 1);
    }

    void aParameterOnlyInBIsListedSetBySet()
    {
        DriveDescription a = drive();
        remove(a, kMaxFrequency);
        const ComparisonTable table = compareAll(a, drive());
        QCOMPARE(table.count(ComparisonRow::State::OnlyInB), kParameterSets);
        const ComparisonRow &set1 = table.rows[3];
        QCOMPARE(line(set1), QStringLiteral("oP.10 1/1  vs 60.00 Hz only in B"));
        QVERIFY(!set1.rawA);
        QVERIFY(!set1.isWritableTo(true));
    }

    void twoUnreadValuesAreEqualOneUnreadDiffers()
    {
        DriveDescription a = drive();
        DriveDescription b = drive();
        find(a, kRampTime)->values[0].reset();
        QCOMPARE(line(compareAll(a, b).rows[10]), QStringLiteral("oP.11 - ? vs 5.00 s different"));
        // The unknown value cannot be written into B; B's known value can go into A.
        QVERIFY(!compareAll(a, b).rows[10].isWritableTo(false));
        QVERIFY(compareAll(a, b).rows[10].isWritableTo(true));
        find(b, kRampTime)->values[0].reset();
        QCOMPARE(line(compareAll(a, b).rows[10]), QStringLiteral("oP.11 - ? vs ? equal"));
    }

    void defaultsAreTheUserSettingsWithTheirDefaults()
    {
        const DriveDescription d = drive();
        const ComparisonTable table = compareAll(userSettingsOf(d), defaultsOf(d));
        const QStringList expected{
            QStringLiteral("oP.10 0/0 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 1/1 60.00 Hz vs 50.00 Hz different"),
            QStringLiteral("oP.10 2/2 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 3/3 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 4/4 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 5/5 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 6/6 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.10 7/7 50.00 Hz vs 50.00 Hz equal"),
            QStringLiteral("oP.11 - 5.00 s vs 5.00 s equal"),
            QStringLiteral("oP.12 - analog vs digital different"),
            QStringLiteral("Pn.05 - forward | released vs stop | locked different"),
            QStringLiteral("Pn.06 - 00FFh vs 00FFh equal"),
            QStringLiteral("Pn.07 - 10 vs 10 equal"),
        };
        QCOMPARE(lines(table), expected);
        // The same differences as the command line's diff against defaults.
        QCOMPARE(compareWithDefaults(d).differences.size(),
                 table.count(ComparisonRow::State::Different));
    }

    void oneSetAgainstAnother()
    {
        const DriveDescription d = drive();
        QCOMPARE(lines(compareSets(d, 0, d, 1)),
                 QStringList{ QStringLiteral("oP.10 0/1 50.00 Hz vs 60.00 Hz different") });
        QCOMPARE(lines(compareSets(d, 2, d, 3)),
                 QStringList{ QStringLiteral("oP.10 2/3 50.00 Hz vs 50.00 Hz equal") });
    }

    void chosenRowsGiveTheOtherSidesValuesForTheWrittenSidesSet()
    {
        const DriveDescription d = drive();
        const ComparisonTable sets = compareSets(d, 0, d, 1);
        QCOMPARE(ChosenValues::from(sets.rows, false),
                 (QList<ChosenValue>{ ChosenValue{ kMaxFrequency, 1, 5000 } }));
        QCOMPARE(ChosenValues::from(sets.rows, true),
                 (QList<ChosenValue>{ ChosenValue{ kMaxFrequency, 0, 6000 } }));
        // Equal, read-only and one-sided rows write nothing.
        const ComparisonTable table = compareAll(d, changed());
        QCOMPARE(ChosenValues::from(table.rows, false),
                 (QList<ChosenValue>{ { kMaxFrequency, 3, 5000 }, { kRampTime, 0, 500 } }));
    }

    void applyPutsInExactlyTheChosenValues()
    {
        DriveDescription target = changed();
        const DriveDescription before = target;
        QStringList refusals;
        QCOMPARE(ChosenValues::apply(target, { { kMaxFrequency, 3, 5000 } }, &refusals), 1);
        QVERIFY(refusals.isEmpty());
        DriveDescription expected = before;
        find(expected, kMaxFrequency)->values[3] = 5000;
        QCOMPARE(target, expected);
    }

    void applyRefusesWhatADownloadWouldNotWrite()
    {
        DriveDescription target = drive();
        const DriveDescription before = target;
        QStringList refusals;
        const int applied = ChosenValues::apply(
            target, { { kFrequency, 0, 10 }, { kService, 0, 1000 }, { 0x0999, 0, 1 } },
            &refusals);
        QCOMPARE(applied, 0);
        QCOMPARE(refusals.size(), 3);
        QVERIFY2(refusals[0].startsWith(QStringLiteral("ru.03: ")), qPrintable(refusals[0]));
        QVERIFY2(refusals[1].contains(QStringLiteral("limits")), qPrintable(refusals[1]));
        QVERIFY2(refusals[2].contains(QStringLiteral("no such parameter")),
                 qPrintable(refusals[2]));
        QCOMPARE(target, before);
    }

    void aSelectionHoldsTheChosenValuesAndTheIdentification()
    {
        DriveDescription source = drive();
        GroupDescription in;
        in.address = 0x0D00;
        in.id = QStringLiteral("In");
        ParameterDescription type = parameter(0x0D00, QStringLiteral("Inverter type"),
                                              levels(0, 7), kReadOnly);
        type.values[0] = 0x1234;
        ParameterDescription other = parameter(0x0D02, QStringLiteral("Not identifying"),
                                               levels(0, 7), kReadOnly);
        other.values[0] = 7;
        in.parameters << type << other;
        source.groups << in;

        const DriveDescription selection = ChosenValues::selectionFor(
            source, { { kMaxFrequency, 3, 4000 }, { kRampTime, 5, 750 } });

        DriveDescription expected = source;
        for (GroupDescription &group : expected.groups) {
            for (ParameterDescription &parameter : group.parameters)
                parameter.values = {};
        }
        find(expected, 0x0D00)->values[0] = 0x1234;
        find(expected, kMaxFrequency)->values[3] = 4000;
        find(expected, kRampTime)->values[0] = 750; // one value: set 0
        QCOMPARE(selection, expected);
    }
};

QTEST_GUILESS_MAIN(TestComparisonTable)
#include "tst_comparisontable.moc"
