// What reverting journal entries writes (JournalRevert, docs/journal.md): each entry's value
// before into its parameter and set, the oldest entry's where several touch one value; refused,
// naming the entry, for an id the journal lacks, another drive's entry, a password, an entry
// without a value before or of the active set. The last change of each value and its text.
#include "JournalTestSupport.h"

#include "journal/JournalChanges.h"
#include "journal/JournalRevert.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::JournalTest;

namespace {

constexpr quint16 kAcceleration = 0x0A1C; // op.28, per set
constexpr quint16 kMode = 0x0A05;         // op.05, one value
constexpr quint16 kPassword = 0x0801;     // ud.01

DriveDescription drive()
{
    ParameterDescription acceleration;
    acceleration.address = kAcceleration;
    acceleration.properties1 = 1u << 11;
    acceleration.maximum = 10000;
    ParameterDescription mode;
    mode.address = kMode;
    mode.maximum = 10;
    GroupDescription op;
    op.address = 0x0A00;
    op.id = QStringLiteral("op");
    op.parameters = { mode, acceleration };
    ParameterDescription password;
    password.address = kPassword;
    GroupDescription ud;
    ud.address = 0x0800;
    ud.id = QStringLiteral("ud");
    ud.parameters = { password };
    DriveDescription description;
    description.groups = { ud, op };
    return description;
}

JournalEntry entry(qint64 id, quint16 address, std::optional<int> set, qint32 before,
                   qint32 written)
{
    JournalEntry e = fullEntry();
    e.id = id;
    e.parameterAddress = address;
    e.parameterId = address == kMode ? QStringLiteral("op.05") : QStringLiteral("op.28");
    e.set = set;
    e.before = { before, QStringLiteral("%1").arg(before) };
    e.written = { written, QStringLiteral("%1").arg(written) };
    e.outcome = JournalOutcome::Written;
    return e;
}

} // namespace

class tst_JournalRevert : public QObject
{
    Q_OBJECT

private slots:
    void theOldestValueBeforeWins()
    {
        // op.28 set 2: 500 -> 750 (entry 3), 750 -> 900 (entry 7); set 4: 100 -> 200; op.05.
        const QList<JournalEntry> found = { entry(7, kAcceleration, 2, 750, 900),
                                            entry(3, kAcceleration, 2, 500, 750),
                                            entry(5, kAcceleration, 4, 100, 200),
                                            entry(6, kMode, std::nullopt, 1, 2) };
        const JournalRevertPlan plan
            = JournalRevert::ofEntries({ 3, 5, 6, 7 }, found, busDrive(), drive());
        QVERIFY2(plan.refusals.isEmpty(), qPrintable(plan.refusals.join(QLatin1Char('\n'))));
        QCOMPARE(plan.entries, (QList<qint64> { 3, 5, 6, 7 }));
        QCOMPARE(plan.values,
                 (QList<ChosenValue> { { kAcceleration, 2, 500 }, { kAcceleration, 4, 100 },
                                       { kMode, 0, 1 } }));
        QCOMPARE(plan.job(), QStringLiteral("revert of entries 3..7"));

        // The download's selection holds those values and nothing else of op.28.
        const DriveDescription selection = plan.selection(drive());
        const ParameterDescription *acceleration = selection.find(kAcceleration);
        QVERIFY(acceleration);
        QCOMPARE(acceleration->values[2], 500);
        QCOMPARE(acceleration->values[4], 100);
        QVERIFY(!acceleration->values[0] && !acceleration->values[3]);
        QCOMPARE(selection.find(kMode)->values[0], 1);
    }

    void badEntriesAreRefusedByName()
    {
        JournalEntry other = entry(2, kAcceleration, 1, 500, 600);
        other.drive.serialNumber = QStringLiteral("7654321");
        JournalEntry password = entry(3, kPassword, std::nullopt, 0, 0);
        password.password = true;
        password.before = {};
        password.parameterId = QStringLiteral("ud.01");
        JournalEntry neverRead = entry(4, kAcceleration, 1, 0, 600);
        neverRead.before = {};
        const JournalEntry active = entry(5, kAcceleration, std::nullopt, 500, 600);
        const JournalEntry good = entry(6, kAcceleration, 3, 500, 600);
        const JournalRevertPlan plan = JournalRevert::ofEntries(
            { 1, 2, 3, 4, 5, 6 }, { other, password, neverRead, active, good }, busDrive(),
            drive());
        QVERIFY(plan.isRefused());
        const QString text = plan.refusals.join(QLatin1Char('\n'));
        QCOMPARE(plan.refusals.size(), 5);
        QVERIFY2(text.contains(QStringLiteral("entry 1: the journal has no such entry")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("entry 2 (op.28) was written to another drive "
                                              "(7654321), not the one connected (1234567)")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("entry 3 (ud.01) is a password entered")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("entry 4 (op.28): the value before was not read")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("entry 5 (op.28) was written to the active set")),
                 qPrintable(text));
    }

    void sinceTakesTheConnectedDrivesEntriesAndLeavesPasswordsOut()
    {
        JournalEntry other = entry(2, kAcceleration, 1, 500, 600);
        other.drive.serialNumber = QStringLiteral("7654321");
        JournalEntry password = entry(3, kPassword, std::nullopt, 0, 0);
        password.password = true;
        password.before = {};
        const JournalRevertPlan plan = JournalRevert::since(
            { other, password, entry(4, kAcceleration, 1, 300, 600) }, busDrive(), drive());
        QVERIFY(!plan.isRefused());
        QCOMPARE(plan.values, (QList<ChosenValue> { { kAcceleration, 1, 300 } }));
        QCOMPARE(plan.leftOut.size(), 1);
        QVERIFY(plan.leftOut.constFirst().contains(QStringLiteral("password")));
        QCOMPARE(plan.job(), QStringLiteral("revert of entry 4"));
    }

    void sameDriveNeedsTheLinkWhereThereIsNoSerialNumber()
    {
        JournalDrive a = busDrive(QString(), 3);
        JournalDrive b = a;
        QVERIFY(a.isSameDrive(b));
        b.address = 4;
        QVERIFY(!a.isSameDrive(b));
        JournalDrive c = busDrive();
        JournalDrive d = c;
        d.link = QStringLiteral("tcp:10.0.0.5:5020"); // the same drive, reached another way
        QVERIFY(c.isSameDrive(d));
        d.softwareVersion = QStringLiteral("1.90");
        QVERIFY(!c.isSameDrive(d));
    }

    void idsAndRanges()
    {
        QString error;
        QCOMPARE(JournalRevert::parseIds({ QStringLiteral("12"), QStringLiteral("14..16") }, &error),
                 (QList<qint64> { 12, 14, 15, 16 }));
        for (const char *bad : { "0", "x", "15..12", "-3", "12..", "" }) {
            error.clear();
            QVERIFY2(!JournalRevert::parseIds({ QLatin1String(bad) }, &error), bad);
            QVERIFY2(error.contains(QStringLiteral("names no entry")), qPrintable(error));
        }
    }

    void theLastChangeOfEachValue()
    {
        JournalEntry refused = entry(9, kAcceleration, 2, 900, 950);
        refused.outcome = JournalOutcome::Refused;
        JournalEntry first = entry(3, kAcceleration, 2, 500, 750);
        JournalEntry second = entry(7, kAcceleration, 2, 750, 900);
        second.user = QStringLiteral("ben");
        const JournalChanges changes
            = JournalChanges::of({ first, second, refused, entry(6, kMode, std::nullopt, 1, 2) });
        QVERIFY(changes.last(kAcceleration, 2));
        QCOMPARE(changes.last(kAcceleration, 2)->id, qint64(7)); // refused is no change
        QVERIFY(!changes.last(kAcceleration, 3));
        QCOMPARE(changes.last(kMode, -1)->id, qint64(6));

        JournalEntry shown = entry(1, kAcceleration, 2, 500, 750);
        shown.before.text = QStringLiteral("5.00 s");
        shown.written.text = QStringLiteral("7.50 s");
        shown.readBack = { 750, QStringLiteral("7.50 s") };
        shown.user = QStringLiteral("anna");
        shown.time = QDateTime(QDate(2026, 11, 24), QTime(10, 42), Qt::LocalTime).toUTC();
        QCOMPARE(shown.changeText(QDateTime(QDate(2026, 11, 24), QTime(18, 0), Qt::LocalTime)),
                 QStringLiteral("7.50 s since 10:42 by anna, was 5.00 s"));
        QCOMPARE(shown.changeText(QDateTime(QDate(2026, 11, 25), QTime(8, 0), Qt::LocalTime)),
                 QStringLiteral("7.50 s since 2026-11-24 10:42 by anna, was 5.00 s"));
    }
};

QTEST_GUILESS_MAIN(tst_JournalRevert)
#include "tst_journalrevert.moc"
