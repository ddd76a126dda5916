#include "EditorSampleDrive.h"

#include "parameters/ParameterComparison.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::EditorSample;

namespace {

ParameterDescription *find(DriveDescription &drive, quint16 address)
{
    return const_cast<ParameterDescription *>(drive.find(address));
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
        QCOMPARE(comparison.compared, drive().parameterCount());
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
        QCOMPARE(comparison.compared, drive().parameterCount() - 1);
        comparison = compareDescriptions(b, drive());
        QCOMPARE(comparison.differences[0].kind, ParameterDifference::Kind::OnlyInB);
        QCOMPARE(comparison.differences[0].a, QString());
    }
};

QTEST_GUILESS_MAIN(TestParameterComparison)
#include "tst_parametercomparison.moc"
