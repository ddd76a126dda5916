#include "parameters/SetList.h"
#include "parameters/TelegramText.h"

#include <QTest>

using namespace DriveDesk;

namespace {

constexpr quint16 kActualLoad = 0x020D;
constexpr quint16 kPercent = 37; // display unit code of %

// Group ru at 0200h with ru.13 "Actual load" in %.
DriveDescription runDisplay()
{
    ParameterDescription load;
    load.address = kActualLoad;
    load.name = QStringLiteral("Actual load");
    load.maximum = 250;
    load.scaling = { kActualLoad, 1, 1, 0, kPercent };
    GroupDescription ru;
    ru.address = 0x0200;
    ru.id = QStringLiteral("ru");
    ru.name = QStringLiteral("Run display");
    ru.parameters << load;
    DriveDescription drive;
    drive.groups << ru;
    return drive;
}

Telegram valueRequest(Service service, Access access, quint8 set, qint32 value = 0)
{
    return Telegram::request(service, access, ParameterValue { kActualLoad, set, value });
}

} // namespace

// How telegrams read for a user: ids, names, values as shown, set lists; without a
// description, ids from the address and raw values.
class TestTelegramText : public QObject
{
    Q_OBJECT
private slots:
    void setListsNameTheSets()
    {
        QCOMPARE(SetList::text(0x01), QStringLiteral("set 0"));
        QCOMPARE(SetList::text(0x02), QStringLiteral("set 1"));
        QCOMPARE(SetList::text(0x25), QStringLiteral("sets 0, 2, 5"));
        QCOMPARE(SetList::text(0xFF), QStringLiteral("all sets"));
        QCOMPARE(SetList::standardSetText(0), QStringLiteral("active set"));
    }

    void aReadAndItsAnswerNameTheParameter()
    {
        const DriveDescription drive = runDisplay();
        const Telegram read = valueRequest(Service::ParameterValueStandard, Access::Read, 0);
        QCOMPARE(TelegramText::describe(read, &drive), QStringLiteral("read ru.13 Actual load"));
        Telegram answer = read.response();
        answer.as<ParameterValue>()->value = 57;
        QCOMPARE(TelegramText::describe(answer, &drive, &read),
                 QStringLiteral("ru.13 Actual load: 57 %"));
        // No description: the id from the address, the raw value.
        QCOMPARE(TelegramText::describe(answer, nullptr, &read), QStringLiteral("020Dh: 57"));
        // An answer to no known request names nothing it cannot know.
        QVERIFY(!TelegramText::describe(answer, &drive).contains(QStringLiteral("ru.13")));
    }

    void aWriteNamesItsSetsAsAList()
    {
        const DriveDescription drive = runDisplay();
        const Telegram write = valueRequest(Service::ParameterValue, Access::Write, 0x01, 80);
        QCOMPARE(TelegramText::describe(write, &drive),
                 QStringLiteral("write ru.13 Actual load = 80 % (set 0)"));
        QCOMPARE(TelegramText::describe(write.response(), &drive, &write),
                 QStringLiteral("written: ru.13 Actual load = 80 % (set 0)"));
        QCOMPARE(TelegramText::describe(write.response(Ack::WriteProtected), &drive, &write),
                 QStringLiteral("write ru.13 Actual load = 80 % (set 0) refused: %1")
                     .arg(ackText(Ack::WriteProtected)));
    }

    void metadataAndGroupsAreNamedToo()
    {
        const DriveDescription drive = runDisplay();
        const Telegram limits
            = Telegram::request(Service::Limits, Access::Read, ParameterLimits { kActualLoad });
        Telegram answer = limits.response();
        answer.as<ParameterLimits>()->upper = 250;
        QCOMPARE(TelegramText::describe(answer, &drive, &limits),
                 QStringLiteral("limits of ru.13 Actual load: 0 % .. 250 %"));
        const Telegram group
            = Telegram::request(Service::GroupName, Access::Read, NameData { 0x0200, 0, {} });
        QCOMPARE(TelegramText::describe(group, &drive),
                 QStringLiteral("read the name of group ru Run display"));
    }
};

QTEST_GUILESS_MAIN(TestTelegramText)
#include "tst_telegramtext.moc"
