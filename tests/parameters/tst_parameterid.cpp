#include "parameters/ParameterId.h"

#include <QTest>

using namespace DriveDesk;

namespace {

QList<GroupAddress> f5Groups()
{
    return { { QStringLiteral("Sy"), 0x0000 }, { QStringLiteral("ru"), 0x0200 },
             { QStringLiteral("Fb"), 0x0280 }, { QStringLiteral("op"), 0x0300 },
             { QStringLiteral("dS"), 0x1100 }, { QStringLiteral("ds"), 0x1200 } };
}

} // namespace

// Parameter ids as users type and read them: "ru.03", "0203h".
class TestParameterId : public QObject
{
    Q_OBJECT
private slots:
    void parsesGroupDotNumber_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("address");
        QTest::newRow("ru.3") << QStringLiteral("ru.3") << 0x0203;
        QTest::newRow("ru.03") << QStringLiteral("ru.03") << 0x0203;
        QTest::newRow("RU.3") << QStringLiteral("RU.3") << 0x0203;
        QTest::newRow("spaces") << QStringLiteral("  ru.0 ") << 0x0200;
        QTest::newRow("Sy.02") << QStringLiteral("Sy.02") << 0x0002;
        QTest::newRow("leading zeros") << QStringLiteral("op.00007") << 0x0307;
        QTest::newRow("ru.127") << QStringLiteral("ru.127") << 0x027F;
        QTest::newRow("half page Fb.09") << QStringLiteral("Fb.09") << 0x0289;
        QTest::newRow("op.255") << QStringLiteral("op.255") << 0x03FF;
        QTest::newRow("exact case wins") << QStringLiteral("ds.1") << 0x1201;
        QTest::newRow("without the dot") << QStringLiteral("op28") << 0x031C;
        QTest::newRow("without the dot, upper case") << QStringLiteral("RU3") << 0x0203;
        QTest::newRow("half page without the dot") << QStringLiteral("Fb09") << 0x0289;
        QTest::newRow("0x0203") << QStringLiteral("0x0203") << 0x0203;
        QTest::newRow("0203h") << QStringLiteral("0203h") << 0x0203;
        QTest::newRow("0203H") << QStringLiteral("0203H") << 0x0203;
        QTest::newRow("unknown group hex") << QStringLiteral("7F05h") << 0x7F05;
        QTest::newRow("FFFFh") << QStringLiteral("FFFFh") << 0xFFFF;
    }

    void parsesGroupDotNumber()
    {
        QFETCH(QString, text);
        QFETCH(int, address);
        QString error;
        const std::optional<quint16> parsed = ParameterId::parse(text, f5Groups(), &error);
        QVERIFY2(parsed, qPrintable(error));
        QCOMPARE(*parsed, quint16(address));
    }

    void errorsSayWhatIsWrong_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("no group") << QStringLiteral("xy.3")
                                  << QStringLiteral("no group 'xy' on this drive");
        QTest::newRow("above 255")
            << QStringLiteral("ru.300") << QStringLiteral("'ru.300': parameter number above 255");
        QTest::newRow("very long")
            << QStringLiteral("op.99999999999")
            << QStringLiteral("'op.99999999999': parameter number above 255");
        QTest::newRow("into next group")
            << QStringLiteral("ru.128")
            << QStringLiteral("'ru.128': parameter number above 127 in group ru");
        QTest::newRow("address above FFFFh")
            << QStringLiteral("0x12345") << QStringLiteral("'0x12345': address above FFFFh");
        QTest::newRow("ambiguous case")
            << QStringLiteral("DS.1")
            << QStringLiteral(
                   "'DS.1': the group id is ambiguous ('dS' or 'ds'); write it with its case");
        QTest::newRow("empty") << QString() << QStringLiteral("no parameter given");
        QTest::newRow("no group without the dot")
            << QStringLiteral("xy3") << QStringLiteral("no group 'xy' on this drive");
        QTest::newRow("garbage") << QStringLiteral("ru-3")
                                 << QStringLiteral(
                                        "'ru-3' is not a parameter id: write it as group.number "
                                        "(ru.03, ru03) or as a hexadecimal address (0203h, 0x0203)");
        QTest::newRow("negative") << QStringLiteral("ru.-3")
                                  << QStringLiteral(
                                         "'ru.-3' is not a parameter id: write it as group.number "
                                         "(ru.03, ru03) or as a hexadecimal address (0203h, 0x0203)");
    }

    void errorsSayWhatIsWrong()
    {
        QFETCH(QString, text);
        QFETCH(QString, error);
        QString actual;
        QVERIFY(!ParameterId::parse(text, f5Groups(), &actual));
        QCOMPARE(actual, error);
    }

    void formatsWithTheGroupOrInHex()
    {
        const QList<GroupAddress> groups = f5Groups();
        QCOMPARE(ParameterId::format(0x0203, groups), QStringLiteral("ru.03"));
        QCOMPARE(ParameterId::format(0x0002, groups), QStringLiteral("Sy.02"));
        QCOMPARE(ParameterId::format(0x0289, groups), QStringLiteral("Fb.09"));
        QCOMPARE(ParameterId::format(0x03FF, groups), QStringLiteral("op.255"));
        QCOMPARE(ParameterId::format(0x0203, QList<GroupAddress>()), QStringLiteral("0203h"));
        QCOMPARE(ParameterId::format(0x7F05, groups), QStringLiteral("7F05h"));
        const QList<GroupAddress> operatorGroups { { QStringLiteral("os"), 0x0180 } };
        QCOMPARE(ParameterId::format(0x0180, operatorGroups), QStringLiteral("os.00"));
        QCOMPARE(ParameterId::format(0x017F, operatorGroups), QStringLiteral("017Fh"));
        for (int address = 0; address <= 0xFFFF; address += 7) {
            const QString text = ParameterId::format(quint16(address), groups);
            QCOMPARE(ParameterId::parse(text, groups), quint16(address));
        }
    }

    // Tables, files and messages name a group's parameter by one rule: counted from the group's
    // first address, also where a group starts half way through a page.
    void namesAParameterOfItsGroup()
    {
        GroupDescription ru;
        ru.id = QStringLiteral("ru");
        ru.address = 0x0200;
        ParameterDescription actual;
        actual.address = 0x0203;
        QCOMPARE(parameterId(ru, actual), QStringLiteral("ru.03"));

        GroupDescription half;
        half.id = QStringLiteral("Fb");
        half.address = 0x0280;
        ParameterDescription ninth;
        ninth.address = 0x0289;
        QCOMPARE(parameterId(half, ninth), QStringLiteral("Fb.09"));
    }

    void worksFromADriveDescription()
    {
        DriveDescription drive;
        GroupDescription ru;
        ru.id = QStringLiteral("ru");
        ru.address = 0x0200;
        drive.groups << ru;
        QCOMPARE(ParameterId::parse(QStringLiteral("ru.3"), drive), quint16(0x0203));
        QCOMPARE(ParameterId::format(0x0203, drive), QStringLiteral("ru.03"));
        QCOMPARE(ParameterId::groupsOf(drive),
                 (QList<GroupAddress> { { QStringLiteral("ru"), 0x0200 } }));
    }
};

QTEST_GUILESS_MAIN(TestParameterId)
#include "tst_parameterid.moc"
