#include "parameters/MetadataMatch.h"

#include <QTest>

using namespace DriveDesk;

namespace {

constexpr quint32 kVariableUpperLimit = 2u << 14; // properties 1 bits 14-15: always variable
constexpr quint32 kVariableScaling = 1u << 31;
constexpr quint32 kExcluded = 1u << 14; // properties 2: not in the complete list

ParameterDescription parameter(quint16 address, const QString &name, qint32 maximum)
{
    ParameterDescription p;
    p.address = address;
    p.name = name;
    p.maximum = maximum;
    p.scaling = DisplayScalingData{address, 100, 1, 0, 0x0200}; // F2, no unit
    return p;
}

// Two groups as a drive without identification parameters reports them.
DriveDescription drive()
{
    DriveDescription d;
    GroupDescription op;
    op.address = 0x0300;
    op.id = QStringLiteral("op");
    op.name = QStringLiteral("Operational parameters");
    op.parameters << parameter(0x030B, QStringLiteral("Maximum speed forward"), 4000)
                  << parameter(0x031C, QStringLiteral("Acceleration time"), 30000);
    GroupDescription ud;
    ud.address = 0x0800;
    ud.id = QStringLiteral("ud");
    ud.name = QStringLiteral("User definition");
    ud.parameters << parameter(0x0801, QStringLiteral("Password"), 9999);
    d.groups << op << ud;
    return d;
}

} // namespace

// The rule that makes a drive without identification the kind of a file: its metadata.
class TestMetadataMatch : public QObject
{
    Q_OBJECT
private slots:
    void theSameMetadataIsTheSameKindWhateverTheValues()
    {
        DriveDescription other = drive();
        other.groups[0].parameters[0].values[0] = 1234;
        other.groups[0].parameters[0].defaultValue = 99;
        other.driveAddress = 11;
        QVERIFY(!MetadataMatch::firstDifference(drive(), other));
    }

    void theFirstFieldThatDiffersIsNamedBeforeWhatOneSideLacks()
    {
        DriveDescription file = drive();
        file.groups[1].parameters.clear();                // ud.01 only on the drive
        file.groups[0].parameters[1].maximum = 60000;     // op.28
        file.groups[0].parameters[1].name = QStringLiteral("Accel. time");
        const auto difference = MetadataMatch::firstDifference(file, drive());
        QVERIFY(difference);
        QCOMPARE(difference->id, QStringLiteral("op.28"));
        QCOMPARE(difference->field, QStringLiteral("name")); // before the limit
        QCOMPARE(difference->a, QStringLiteral("\"Accel. time\""));

        file.groups[0].parameters[1].name = QStringLiteral("Acceleration time");
        const auto limit = MetadataMatch::firstDifference(file, drive());
        QVERIFY(limit);
        QCOMPARE(limit->field, QStringLiteral("upper limit"));
        QCOMPARE(limit->a, QStringLiteral("600.00"));
        QCOMPARE(limit->b, QStringLiteral("300.00"));

        file.groups[0].parameters[1].maximum = 30000;
        const auto missing = MetadataMatch::firstDifference(file, drive());
        QVERIFY(missing);
        QCOMPARE(missing->id, QStringLiteral("ud.01"));
        QCOMPARE(missing->presence, MetadataDifference::Presence::OnlyInB);
        // A selection of values may hold less than the drive.
        QVERIFY(!MetadataMatch::firstDifference(file, drive(), MetadataMatch::Scope::AHoldsPart));
    }

    void whatTheDriveWorksOutAfreshIsNotCompared()
    {
        DriveDescription file = drive();
        DriveDescription onDrive = drive();
        for (DriveDescription *side : {&file, &onDrive})
            side->groups[0].parameters[0].properties1 = kVariableUpperLimit | kVariableScaling;
        file.groups[0].parameters[0].maximum = 3000;
        file.groups[0].parameters[0].scaling.divisor = 1;
        QVERIFY(!MetadataMatch::firstDifference(file, onDrive));
        // The limit of a parameter whose limits are constant is compared.
        file.groups[0].parameters[0].properties1 = 0;
        onDrive.groups[0].parameters[0].properties1 = 0;
        file.groups[0].parameters[0].scaling.divisor = 100;
        QCOMPARE(MetadataMatch::firstDifference(file, onDrive)->field, QStringLiteral("upper limit"));
    }

    void aParameterOutsideTheListIsNoDifference()
    {
        DriveDescription onDrive = drive();
        ParameterDescription excluded = parameter(0x0802, QStringLiteral("Excluded"), 1);
        excluded.properties2 = kExcluded;
        onDrive.groups[1].parameters << excluded; // a file never holds it
        QVERIFY(!MetadataMatch::firstDifference(drive(), onDrive));
    }

    void aGroupOnlyOneSideHasIsNamed()
    {
        DriveDescription file = drive();
        file.groups.removeLast();
        const auto difference = MetadataMatch::firstDifference(file, drive());
        QVERIFY(difference);
        QVERIFY(difference->isGroup);
        QCOMPARE(difference->id, QStringLiteral("ud"));
        QCOMPARE(difference->presence, MetadataDifference::Presence::OnlyInB);
    }
};

QTEST_GUILESS_MAIN(TestMetadataMatch)
#include "tst_metadatamatch.moc"
