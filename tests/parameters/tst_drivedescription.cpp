#include "parameters/DriveDescription.h"

#include <QTest>

using namespace DriveDesk;

namespace {

DriveDescription twoGroups()
{
    DriveDescription drive;
    GroupDescription sy;
    sy.id = QStringLiteral("Sy");
    sy.address = 0x0000;
    for (quint16 number : { 2, 3, 6 }) {
        ParameterDescription p;
        p.address = number;
        p.name = QStringLiteral("Sy %1").arg(number);
        sy.parameters << p;
    }
    GroupDescription ru;
    ru.id = QStringLiteral("ru");
    ru.address = 0x0200;
    ParameterDescription state;
    state.address = 0x0200;
    state.name = QStringLiteral("Inverter state");
    ru.parameters << state;
    drive.groups << sy << ru;
    return drive;
}

} // namespace

// What a scan found: lookups by address and group id, and ids shown to users.
class TestDriveDescription : public QObject
{
    Q_OBJECT
private slots:
    void countsTheParametersFound()
    {
        QCOMPARE(DriveDescription().parameterCount(), 0);
        QCOMPARE(twoGroups().parameterCount(), 4);
    }

    void findsByAddress()
    {
        const DriveDescription drive = twoGroups();
        QCOMPARE(drive.find(0x0200)->name, QStringLiteral("Inverter state"));
        QCOMPARE(drive.find(0x0006)->name, QStringLiteral("Sy 6"));
        QVERIFY(!drive.find(0x0203));
        QVERIFY(!drive.find(0xFFFF));
        QVERIFY(!DriveDescription().find(0));
    }

    void findsGroupsByIdExactFirst()
    {
        DriveDescription drive = twoGroups();
        QCOMPARE(drive.findGroup(QStringLiteral("ru"))->address, quint16(0x0200));
        QCOMPARE(drive.findGroup(QStringLiteral("RU"))->address, quint16(0x0200));
        QCOMPARE(drive.findGroup(QStringLiteral("sy"))->id, QStringLiteral("Sy"));
        QVERIFY(!drive.findGroup(QStringLiteral("xx")));
        QVERIFY(!drive.findGroup(QString()));
        GroupDescription sy;
        sy.id = QStringLiteral("sy");
        sy.address = 0x1400;
        drive.groups << sy;
        QCOMPARE(drive.findGroup(QStringLiteral("sy"))->address, quint16(0x1400));
        QCOMPARE(drive.findGroup(QStringLiteral("Sy"))->address, quint16(0x0000));
    }

    void parameterIdsHaveTwoDigits()
    {
        QCOMPARE(parameterId(QStringLiteral("ru"), 3), QStringLiteral("ru.03"));
        QCOMPARE(parameterId(QStringLiteral("ru"), 0), QStringLiteral("ru.00"));
        QCOMPARE(parameterId(QStringLiteral("Sy"), 41), QStringLiteral("Sy.41"));
        QCOMPARE(parameterId(QStringLiteral("op"), 255), QStringLiteral("op.255"));
    }
};

QTEST_GUILESS_MAIN(TestDriveDescription)
#include "tst_drivedescription.moc"
