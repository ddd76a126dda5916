#include "EditorSampleDrive.h"

#include "parameters/ParameterComparison.h"

#include <QTest>

#include <algorithm>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

namespace {

ParameterDescription *find(DriveDescription &drive, quint16 address)
{
    return const_cast<ParameterDescription *>(drive.find(address));
}

int settingCount(const DriveDescription &drive)
{
    int count = 0;
    for (const GroupDescription &group : drive.groups)
        count += int(std::count_if(group.parameters.cbegin(), group.parameters.cend(),
                                   [](const ParameterDescription &p) { return countsAsSetting(p); }));
    return count;
}

} // namespace

// What differs between two descriptions of a drive: values set by set, in display form, and
// parameters only one side has.
class TestParameterComparison : public QObject
{
    Q_OBJECT
private slots:
    void theSameDescriptionIsEqual()
    {
        const ParameterComparison comparison = compareDescriptions(drive(), drive());
        QVERIFY(comparison.isEqual());
        QCOMPARE(comparison.compared, settingCount(drive()));
    }

    void valuesDifferSetBySetInDisplayForm()
    {
        DriveDescription b = drive();
        find(b, kMaxFrequency)->values[3] = 4000;
        find(b, kRampTime)->values[0] = 750;
        const ParameterComparison comparison = compareDescriptions(drive(), b);
        QCOMPARE(comparison.differences.size(), 2);
        const ParameterDifference &maxFrequency = comparison.differences[0];
        QCOMPARE(maxFrequency.address, kMaxFrequency);
        QCOMPARE(maxFrequency.id, QStringLiteral("oP.10"));
        QCOMPARE(maxFrequency.set, 3);
        QCOMPARE(maxFrequency.a, QStringLiteral("50.00 Hz"));
        QCOMPARE(maxFrequency.b, QStringLiteral("40.00 Hz"));
        // One value, compared once: not per set.
        QCOMPARE(comparison.differences[1].address, kRampTime);
        QCOMPARE(comparison.differences[1].set, 0);
    }

    void anUnreadValueDiffersFromARead()
    {
        DriveDescription b = drive();
        find(b, kRampTime)->values[0].reset();
        ParameterComparison comparison = compareDescriptions(drive(), b);
        QCOMPARE(comparison.differences.size(), 1);
        QCOMPARE(comparison.differences[0].b, QStringLiteral("?"));
        // Unread on both sides: nothing to tell apart.
        comparison = compareDescriptions(b, b);
        QVERIFY(comparison.isEqual());
    }

    // "Does the drive still match its backup?" asks about settings: a live or read-only value
    // that moved on, a parameter a parameter list leaves out (an upload does not write it into
    // the file) or whose value it does not read (write only) is no difference.
    void onlySettingsCount()
    {
        // find() writes through const: every side is made afresh, never a shared copy.
        auto made = [] {
            DriveDescription drive = EditorSample::drive();
            find(drive, kService)->properties2 |= 1u << 14; // excluded from the complete list
            find(drive, kErrorMask)->properties2 |= 1u << 13; // write only
            return drive;
        };
        const DriveDescription drive = made();
        QVERIFY(countsAsSetting(*drive.find(kMaxFrequency)));
        for (quint16 address : { kState, kFrequency, kService, kErrorMask })
            QVERIFY(!countsAsSetting(*drive.find(address)));

        DriveDescription backup = made();
        find(backup, kFrequency)->values[0] = 0; // live
        find(backup, kState)->values[0] = 3; // read-only
        find(backup, kErrorMask)->values[0] = 0x1234; // never read
        for (GroupDescription &group : backup.groups)
            group.parameters.removeIf([](const ParameterDescription &p) { return p.address == kService; });
        ParameterComparison comparison = compareDescriptions(drive, backup);
        QVERIFY(comparison.isEqual());
        QCOMPARE(comparison.compared, settingCount(drive));
        QVERIFY(compareDescriptions(backup, drive).isEqual());

        // A setting that changed is found.
        find(backup, kRampTime)->values[0] = 750;
        comparison = compareDescriptions(drive, backup);
        QCOMPARE(comparison.differences.size(), 1);
        QCOMPARE(comparison.differences[0].address, kRampTime);
    }

    void aParameterOnlyOneSideHasIsListed()
    {
        DriveDescription b = drive();
        for (GroupDescription &group : b.groups)
            group.parameters.removeIf(
                [](const ParameterDescription &p) { return p.address == kRampTime; });
        ParameterComparison comparison = compareDescriptions(drive(), b);
        QCOMPARE(comparison.differences.size(), 1);
        QCOMPARE(comparison.differences[0].kind, ParameterDifference::Kind::OnlyInA);
        QCOMPARE(comparison.differences[0].set, -1);
        QVERIFY(comparison.differences[0].b.isEmpty());
        QCOMPARE(comparison.compared, settingCount(drive()) - 1);
        comparison = compareDescriptions(b, drive());
        QCOMPARE(comparison.differences[0].kind, ParameterDifference::Kind::OnlyInB);
        QCOMPARE(comparison.differences[0].a, QString());
    }
};

QTEST_GUILESS_MAIN(TestParameterComparison)
#include "tst_parametercomparison.moc"
