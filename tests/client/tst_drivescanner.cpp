#include "client/DriveScanner.h"

#include <QDir>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <array>
#include <bit>
#include <deque>
#include <map>
#include <optional>
#include <set>

using namespace DriveDesk;

namespace {

struct FakeEntry {
    qint32 value = 0;
    quint8 type = 0;
    QByteArray text;
};

struct FakeDefinition {
    quint32 mask = 0;
    QByteArray text;
    QList<FakeEntry> entries;
};

struct FakeParameter {
    QByteArray name;
    qint32 lower = 0;
    qint32 upper = 0;
    qint32 defaultValue = 0;
    quint32 properties1 = 0;
    quint32 properties2 = 0;
    DisplayScalingData scaling;
    std::array<qint32, kParameterSets> values{};
    quint16 plaintextIndex = 0; // 0: no COMBIVIS plaintexts
    bool limitsRefused = false;
    bool propertiesRefused = false;
    int refusedSet = -1;
};

struct FakeGroup {
    quint8 index = 0;
    QByteArray id;
    char shortcut = 0;
    quint16 properties = 0x18;
    quint8 highest = 0;
    int count = 0;
    QByteArray name; // empty: the group refuses to tell its name
    std::map<quint8, FakeParameter> parameters;
};

constexpr quint32 kSetProgrammable = 1u << 11;

// A small drive written by hand, behind a RequestSink that answers from the event loop
// (or, when `synchronous`, inside submit()).
class FakeDrive : public QObject, public RequestSink
{
public:
    std::map<quint8, FakeGroup> groups;                 // by page
    std::map<quint16, QList<FakeDefinition>> plaintexts; // by COMBIVIS plaintext index
    QByteArray identification;                          // empty: service 13 refused (ack 7)
    bool framesService13 = true; // false: a link that cannot carry service 13 (HSP5, seed 000)
    int linkLostAfter = -1; // from this many answers on, every request ends with LinkLost
    bool synchronous = false;
    // Name reads of these addresses get no answer at all, as from a drive that stays silent.
    std::set<quint16> silentNames;
    // The first answer to a name read of these addresses comes back with a letter changed
    // that no checksum saw (bit 5: "Fixed" reads "fixed").
    std::set<quint16> garbledNames;
    // The first answer to a limits read of these addresses has its minimum above its maximum.
    std::set<quint16> swappedLimits;
    // The value of these addresses is another at every read, as a speed or a timer.
    std::set<quint16> movingValues;
    // Once a value of each of these addresses was answered, the line shows an error: what was
    // kept before it is read again.
    std::set<quint16> errorOnceValuesRead;
    quint64 errorsNoted = 0; // what the client would have counted on the line

    QList<Telegram> received;
    int answered = 0;
    int mostHeld = 0;
    int cancelCalls = 0;

    void submit(const Telegram &request, std::function<void(const Reply &)> done) override
    {
        received.append(request);
        if (synchronous) {
            done(answerNext(request));
            return;
        }
        m_held.push_back({request, std::move(done)});
        mostHeld = std::max(mostHeld, int(m_held.size()));
        QTimer::singleShot(0, this, [this] {
            if (m_held.empty())
                return;
            Held next = std::move(m_held.front());
            m_held.pop_front();
            next.done(answerNext(next.request));
        });
    }

    bool supports(Service service, Access) const override
    {
        return service != Service::Fieldbus || framesService13;
    }

    void cancelPending() override
    {
        ++cancelCalls;
        std::deque<Held> held;
        held.swap(m_held);
        for (Held &h : held) {
            Reply reply;
            reply.request = h.request;
            reply.status = Reply::Status::Cancelled;
            h.done(reply);
        }
    }

    int held() const { return int(m_held.size()); }
    quint64 lineErrors() const override { return errorsNoted; }

    int count(Service service, quint8 page) const
    {
        return int(std::count_if(received.begin(), received.end(), [&](const Telegram &t) {
            return t.service == service && pageOf(t) == page;
        }));
    }

    static int pageOf(const Telegram &t)
    {
        if (const auto *d = t.as<GroupPropertiesData>())
            return d->address >> 8;
        if (const auto *d = t.as<NameData>())
            return d->address >> 8;
        return -1;
    }

private:
    struct Held {
        Telegram request;
        std::function<void(const Reply &)> done;
    };

    Reply answerNext(const Telegram &request)
    {
        ++answered;
        Reply reply;
        reply.request = request;
        reply.attempts = 1;
        if (linkLostAfter >= 0 && answered > linkLostAfter) {
            reply.status = Reply::Status::LinkLost;
            reply.detail = QStringLiteral("cable pulled");
            return reply;
        }
        const auto *name = request.as<NameData>();
        const bool parameterName = name && request.service == Service::ParameterName;
        if (parameterName && silentNames.count(name->address)) {
            ++errorsNoted;
            reply.status = Reply::Status::Timeout;
            reply.attempts = 4;
            return reply;
        }
        reply.response = request.response();
        const Ack ack = answer(reply.response);
        reply.response.ack = ack;
        reply.status = ack == Ack::Ok ? Reply::Status::Ok : Reply::Status::Refused;
        if (parameterName && garbledNames.erase(name->address) && reply.ok())
            reply.response.as<NameData>()->text[0] ^= 0x20;
        if (auto *limits = reply.response.as<ParameterLimits>();
            limits && swappedLimits.erase(limits->address)) {
            std::swap(limits->lower, limits->upper);
        }
        if (auto *value = reply.response.as<ParameterValue>();
            value && reply.ok() && movingValues.count(value->address)) {
            value->value += ++m_moves;
        }
        if (const auto *value = reply.response.as<ParameterValue>();
            value && reply.ok() && errorOnceValuesRead.erase(value->address)
            && errorOnceValuesRead.empty()) {
            ++errorsNoted;
        }
        return reply;
    }

    const FakeParameter *parameter(quint16 address) const
    {
        const auto group = groups.find(quint8(address >> 8));
        if (group == groups.end())
            return nullptr;
        const auto p = group->second.parameters.find(quint8(address & 0xFF));
        return p == group->second.parameters.end() ? nullptr : &p->second;
    }

    // Fills the response payload; returns the acknowledge.
    Ack answer(Telegram &t) const
    {
        if (auto *d = t.as<GroupPropertiesData>()) {
            const auto g = groups.find(quint8(d->address >> 8));
            if (g == groups.end())
                return Ack::AddressInvalid;
            d->index = g->second.index;
            d->id = {g->second.id.at(0), g->second.id.at(1)};
            d->shortcut = g->second.shortcut;
            d->properties = g->second.properties;
            d->highestNumber = g->second.highest;
            d->countMinusOne = quint8(g->second.count - 1);
            return Ack::Ok;
        }
        if (t.service == Service::GroupName) {
            auto *d = t.as<NameData>();
            const auto g = groups.find(quint8(d->address >> 8));
            if (g == groups.end())
                return Ack::AddressInvalid;
            if (g->second.name.isEmpty())
                return Ack::LanguageInvalid;
            d->text = g->second.name;
            return Ack::Ok;
        }
        if (auto *d = t.as<FieldbusData>()) {
            if (d->function != 1 || identification.isEmpty())
                return Ack::ServiceNotAvailable;
            d->data = identification;
            return Ack::Ok;
        }
        if (auto *d = t.as<PlaintextDefinitionData>()) {
            const QList<FakeDefinition> &definitions = plaintexts.at(d->index);
            if (d->definition >= definitions.size())
                return Ack::AddressInvalid;
            const FakeDefinition &definition = definitions.at(d->definition);
            d->mask = definition.mask;
            d->count = quint8(definition.entries.size());
            d->text = definition.text;
            return Ack::Ok;
        }
        if (auto *d = t.as<CombivisPlaintextData>()) {
            const FakeEntry &entry
                = plaintexts.at(d->index).at(d->definition).entries.at(d->subindex);
            d->value = entry.value;
            d->type = entry.type;
            d->text = entry.text;
            return Ack::Ok;
        }
        return answerParameter(t);
    }

    Ack answerParameter(Telegram &t) const
    {
        const auto address = std::visit(
            [](const auto &d) -> int {
                if constexpr (requires { d.address; })
                    return d.address;
                else
                    return -1;
            },
            t.data);
        const FakeParameter *p = address < 0 ? nullptr : parameter(quint16(address));
        if (!p)
            return Ack::AddressInvalid;
        switch (t.service) {
        case Service::ParameterName:
            t.as<NameData>()->text = p->name;
            return Ack::Ok;
        case Service::Limits:
            if (p->limitsRefused)
                return Ack::DataInvalid;
            t.as<ParameterLimits>()->lower = p->lower;
            t.as<ParameterLimits>()->upper = p->upper;
            return Ack::Ok;
        case Service::DefaultValue:
            t.as<DefaultValue>()->value = p->defaultValue;
            return Ack::Ok;
        case Service::Properties:
            if (p->propertiesRefused)
                return Ack::OperationNotPossible;
            t.as<PropertiesData>()->properties1 = p->properties1;
            t.as<PropertiesData>()->properties2 = p->properties2;
            return Ack::Ok;
        case Service::DisplayScaling:
            // The response carries no address: leave it 0 as a codec would.
            *t.as<DisplayScalingData>() = p->scaling;
            t.as<DisplayScalingData>()->address = 0;
            // A parameter given no scaling shows its raw number: divisor and multiplier 1.
            if (p->scaling.divisor == 0) {
                t.as<DisplayScalingData>()->divisor = 1;
                t.as<DisplayScalingData>()->multiplier = 1;
            }
            return Ack::Ok;
        case Service::PlaintextIndices: {
            auto *d = t.as<PlaintextIndicesData>();
            d->address = 0;
            d->combivisIndex = p->plaintextIndex;
            d->combivisCount = p->plaintextIndex ? quint16(plaintexts.at(p->plaintextIndex).size())
                                                 : 0;
            return Ack::Ok;
        }
        case Service::ParameterValue: {
            auto *d = t.as<ParameterValue>();
            // Over several sets the drive answers their value when they all hold the same,
            // and ack 3 when they differ (seed 000, 2.1).
            std::optional<qint32> value;
            for (int set = 0; set < kParameterSets; ++set) {
                if (!(d->set & (1u << set)))
                    continue;
                if (set == p->refusedSet || (value && *value != p->values.at(set)))
                    return Ack::DataInvalid;
                value = p->values.at(set);
            }
            if (!value)
                return Ack::SetInvalid;
            d->value = *value;
            return Ack::Ok;
        }
        case Service::ParameterValueStandard:
            if (t.as<ParameterValue>()->set != 0)
                return Ack::SetInvalid;
            t.as<ParameterValue>()->value = p->values.at(0);
            return Ack::Ok;
        default:
            return Ack::ServiceNotAvailable;
        }
    }

    std::deque<Held> m_held;
    qint32 m_moves = 0;
};

void makeDrive(FakeDrive &drive)
{
    drive.identification = QByteArrayLiteral("F5-M test drive 4.2");

    FakeGroup ud{0, "ud", 'u', 0x1B, 1, 2, "User definition", {}};
    ud.parameters[0] = {"Password", -8, 9999, 0, 0x0400, 0, {}, {440}};
    ud.parameters[1] = {"Display parameter",        0, 100, 5, kSetProgrammable | 0x40, 0x2000,
                        {0, 10, 1, 0, 0x0100}, {10, 11, 12, 13, 14, 15, 16, 17}};
    ud.parameters[1].refusedSet = 5;
    drive.groups[0x05] = ud;

    // Numbers 4..9 are reserved: the drive says it has 3 parameters, so they are never asked.
    FakeGroup ru{1, "ru", 'r', 0x18, 9, 3, {}, {}};
    ru.parameters[0] = {"Inverter state", 0, 128, 0, 0, 0, {}, {66}};
    ru.parameters[1] = {"Set value display", -4000, 4000, 0, 0x0400, 0, {}, {-1234}};
    ru.parameters[1].propertiesRefused = true;
    ru.parameters[3] = {"Actual frequency", -32000, 32000, 0, 0x04C0, 0x4000,
                        {0, 80, 1, 0, 0x0203}, {-4180}};
    drive.groups[0x02] = ru;

    FakeGroup op{2, "op", 'o', 0x18, 1, 2, "Operation", {}};
    op.parameters[0] = {"Rotation setting", 0, 7, 0, 0, 0, {}, {6}};
    op.parameters[0].plaintextIndex = 7;
    op.parameters[1] = {"Set value", -400, 400, 0, kSetProgrammable, 0, {},
                        {100, 101, 102, 103, 104, 105, 106, 107}};
    op.parameters[1].limitsRefused = true;
    drive.groups[0x03] = op;

    drive.plaintexts[7] = {
        {0x03, "source", {{0, 0, "digital"}, {1, 0, "analog"}, {2, 1, "bus"}}},
        {0x04, "direction", {{0, 0, "forward"}, {4, 0, "reverse"}}},
    };
}

// The identification parameters of an F5 (Sy.02, Sy.03, In.00, In.06, In.07 name its kind):
// with them the drive's metadata can be cached.
void addIdentification(FakeDrive &drive)
{
    FakeGroup sy{10, "Sy", 's', 0x18, 3, 2, "System", {}};
    sy.parameters[2] = {"Inverter identifier", 0, 0xFFFF, 0, 0, 0, {}, {0x0F51}};
    sy.parameters[3] = {"Power unit", -255, 255, 0, 0, 0, {}, {7}};
    drive.groups[0x00] = sy;
    FakeGroup in{11, "In", 'i', 0x18, 10, 4, "Information", {}};
    in.parameters[0] = {"Inverter type", 0, 0xFFFF, 0, 0, 0, {}, {0x0F50}};
    in.parameters[6] = {"Software version", 0, 9999, 0, 0, 0, {}, {180}};
    in.parameters[7] = {"Software date", 0, 31129, 0, 0, 0, {}, {22114}};
    in.parameters[10] = {"Serial number", 0, 99999999, 0, 0, 0, {}, {1234}};
    drive.groups[0x0E] = in;
}

// One scan's outcome as a user of the scanner sees it.
struct ScanResult {
    std::optional<DriveDescription> description;
    int finishedCount = 0;
    int lastDone = 0;
    int lastTotal = 0;
    QStringList whats;
};

void watch(DriveScanner &scanner, ScanResult &result)
{
    QObject::connect(&scanner, &DriveScanner::finished, [&result](const DriveDescription &d) {
        result.description = d;
        ++result.finishedCount;
    });
    QObject::connect(&scanner, &DriveScanner::progress,
                     [&result](int done, int total, const QString &what) {
                         QVERIFY(done <= total);
                         result.lastDone = done;
                         result.lastTotal = total;
                         result.whats.append(what);
                     });
}

// Options that ask for service 13, as a user does who says the drive has it.
ScanOptions identified()
{
    ScanOptions options;
    options.identificationText = true;
    return options;
}

// Runs one scan to its end.
ScanResult scan(FakeDrive &drive, const ScanOptions &options = identified(),
                Language language = Language::English)
{
    DriveScanner scanner(drive, options, language);
    ScanResult result;
    watch(scanner, result);
    scanner.start();
    if (!QTest::qWaitFor([&result] { return result.finishedCount > 0; }))
        qWarning("the scan did not finish"); // the caller's check of finishedCount fails
    return result;
}

std::array<std::optional<qint32>, kParameterSets> allSets(qint32 first)
{
    std::array<std::optional<qint32>, kParameterSets> values;
    for (int s = 0; s < kParameterSets; ++s)
        values[s] = first + s;
    return values;
}

} // namespace

// The drive scan against a hand-made drive: what it asks, what it records, how it stops.
class TestDriveScanner : public QObject
{
    Q_OBJECT
private slots:
    void readsEveryGroupAndParameter();
    void recordsFailedReadsWithoutGuessing();
    void readsPlaintextDefinitions();
    void followsTheOptions();
    void readsGroupsOnly();
    void readsOnlyListedParameters();
    void worksWithASinkThatAnswersAtOnce();
    void cancelKeepsWhatWasRead();
    void linkLostEndsTheScan();
    void readsSetsTogetherWhereTheyAgree_data();
    void readsSetsTogetherWhereTheyAgree();
    void asksService13OnlyWhereTheLinkFramesIt();
    void asksService13OnlyWhenTheUserOptsIn();
    void aNameReadThatTimesOutIsNeverAParameter();
    void aParameterWhoseNameGotNoAnswerMakesTheGroupIncomplete();
    void onALineWithErrorsAnswersAreConfirmed();
    void anImplausibleAnswerIsReadAgain();
    void aValueTheDriveChangesByItselfIsLeftUnconfirmedNotUnread();
    void aLiveValueKeptBeforeTheLineShowedErrorsHoldsUpNothing();
    void aDriveWithoutIdentityIsNeverCached();
    void variableMetadataIsReadAgainOnACachedKind();
};

void TestDriveScanner::readsEveryGroupAndParameter()
{
    FakeDrive drive;
    makeDrive(drive);
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;

    QCOMPARE(d.incompleteReason, QString());
    QCOMPARE(d.identification, QStringLiteral("F5-M test drive 4.2"));
    QCOMPARE(d.language, int(Language::English));
    QCOMPARE(drive.count(Service::GroupProperties, 0x00), 1);
    QCOMPARE(drive.count(Service::GroupProperties, 0xFF), 1);
    QCOMPARE(drive.count(Service::GroupName, 0x02), 1);

    // Groups in the drive's display order, not by page.
    QCOMPARE(d.groups.size(), 3);
    const GroupDescription &ud = d.groups.at(0);
    QCOMPARE(ud.id, QStringLiteral("ud"));
    QCOMPARE(ud.address, quint16(0x0500));
    QCOMPARE(ud.index, quint8(0));
    QCOMPARE(ud.shortcut, 'u');
    QCOMPARE(ud.properties, quint16(0x1B));
    QCOMPARE(ud.highestNumber, quint8(1));
    QCOMPARE(ud.parameterCount, 2);
    QCOMPARE(ud.name, QStringLiteral("User definition"));
    QCOMPARE(d.groups.at(1).id, QStringLiteral("ru"));
    QCOMPARE(d.groups.at(2).id, QStringLiteral("op"));
    QCOMPARE(d.groups.at(2).name, QStringLiteral("Operation"));

    // The group that refuses its name keeps an empty one; its parameters are still read.
    const GroupDescription &ru = d.groups.at(1);
    QCOMPARE(ru.name, QString());
    QCOMPARE(ru.parameterCount, 3);
    QCOMPARE(ru.parameters.size(), 3);
    QCOMPARE(ru.parameters.at(0).address, quint16(0x0200));
    QCOMPARE(ru.parameters.at(1).address, quint16(0x0201));
    QCOMPARE(ru.parameters.at(2).address, quint16(0x0203)); // ru.02 is unused
    QVERIFY(!d.find(0x0202));
    // Once the third parameter was found, numbers 4..9 were never asked.
    QCOMPARE(drive.count(Service::ParameterName, 0x02), 4);

    const ParameterDescription &frequency = ru.parameters.at(2);
    QCOMPARE(frequency.name, QStringLiteral("Actual frequency"));
    QCOMPARE(frequency.minimum, -32000);
    QCOMPARE(frequency.maximum, 32000);
    QCOMPARE(frequency.defaultValue, 0);
    QCOMPARE(frequency.properties1, quint32(0x04C0));
    QCOMPARE(frequency.properties2, quint32(0x4000));
    QCOMPARE(frequency.scaling, (DisplayScalingData{0x0203, 80, 1, 0, 0x0203}));
    QCOMPARE(frequency.plaintextIndices, (PlaintextIndicesData{0x0203, 0, 0, 0, 0}));
    QVERIFY(frequency.plaintexts.isEmpty());
    QCOMPARE(frequency.values[0], std::optional<qint32>(-4180));
    for (int s = 1; s < kParameterSets; ++s)
        QVERIFY(!frequency.values[s]);
    QCOMPARE(frequency.error, QString());

    const ParameterDescription *display = d.find(0x0501);
    QVERIFY(display);
    QVERIFY(display->isSetProgrammable());
    QCOMPARE(display->name, QStringLiteral("Display parameter"));
    QCOMPARE(display->minimum, 0);
    QCOMPARE(display->maximum, 100);
    QCOMPARE(display->defaultValue, 5);
    QCOMPARE(d.find(0x0500)->values[0], std::optional<qint32>(440));
    QCOMPARE(d.parameterCount(), 7);

    QCOMPARE(result.lastDone, result.lastTotal);
    QCOMPARE(result.lastDone, drive.answered);
    QCOMPARE(drive.answered, int(drive.received.size()));
    QVERIFY(result.whats.contains(QStringLiteral("group ru: parameter ru.03")));
    QVERIFY2(drive.mostHeld >= 4, "requests must be queued ahead so the sink can pipeline");
}

void TestDriveScanner::recordsFailedReadsWithoutGuessing()
{
    FakeDrive drive;
    makeDrive(drive);
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;
    QCOMPARE(d.incompleteReason, QString());

    // The limits read fails: the reason is kept, everything else is read as usual.
    const ParameterDescription *setValue = d.find(0x0301);
    QVERIFY(setValue);
    QCOMPARE(setValue->name, QStringLiteral("Set value"));
    QVERIFY2(setValue->error.contains(QStringLiteral("limits")), qPrintable(setValue->error));
    QVERIFY2(setValue->error.contains(ackText(Ack::DataInvalid)), qPrintable(setValue->error));
    QCOMPARE(setValue->minimum, 0);
    QCOMPARE(setValue->maximum, 0);
    QCOMPARE(setValue->values, allSets(100));

    // Without its properties it is unknown whether ru.01 has sets: no value is read.
    const ParameterDescription *setValueDisplay = d.find(0x0201);
    QCOMPARE(setValueDisplay->minimum, -4000);
    QCOMPARE(setValueDisplay->properties1, quint32(0));
    QCOMPARE(setValueDisplay->values, (std::array<std::optional<qint32>, kParameterSets>{}));
    QVERIFY2(setValueDisplay->error.contains(ackText(Ack::OperationNotPossible)),
             qPrintable(setValueDisplay->error));
    QVERIFY2(setValueDisplay->error.contains(QStringLiteral("values")),
             qPrintable(setValueDisplay->error));
    QVERIFY(!drive.received.contains(
        Telegram::request(Service::ParameterValueStandard, Access::Read, ParameterValue{0x0201})));

    // Set 5 of ud.01 is refused: that set stays empty, the others are read.
    const ParameterDescription *display = d.find(0x0501);
    auto expected = allSets(10);
    expected[5].reset();
    QCOMPARE(display->values, expected);
    QVERIFY2(display->error.contains(QStringLiteral("set 5")), qPrintable(display->error));
    QVERIFY2(display->error.contains(ackText(Ack::DataInvalid)), qPrintable(display->error));
}

void TestDriveScanner::readsPlaintextDefinitions()
{
    FakeDrive drive;
    makeDrive(drive);
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);

    const ParameterDescription *rotation = result.description->find(0x0300);
    QVERIFY(rotation);
    QCOMPARE(rotation->plaintextIndices, (PlaintextIndicesData{0x0300, 0, 0, 7, 2}));
    const QList<PlaintextDefinition> expected{
        {0x03, QStringLiteral("source"),
         {{0, 0, QStringLiteral("digital")}, {1, 0, QStringLiteral("analog")},
          {2, 1, QStringLiteral("bus")}}},
        {0x04, QStringLiteral("direction"),
         {{0, 0, QStringLiteral("forward")}, {4, 0, QStringLiteral("reverse")}}},
    };
    QCOMPARE(rotation->plaintexts, expected);
    QCOMPARE(rotation->values[0], std::optional<qint32>(6));
    QCOMPARE(rotation->error, QString());
}

void TestDriveScanner::followsTheOptions()
{
    FakeDrive drive;
    makeDrive(drive);
    drive.identification.clear(); // this drive refuses service 13 (ack 7)
    ScanOptions options;
    options.values = false;
    options.plaintexts = false;
    options.groupPages = {0x03, 0x02, 0x03, 0x40};
    const ScanResult result = scan(drive, options, Language::German);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;

    QCOMPARE(d.incompleteReason, QString());
    QCOMPARE(d.identification, QString());
    QCOMPARE(d.language, int(Language::German));
    QCOMPARE(d.groups.size(), 2);
    QCOMPARE(d.groups.at(0).id, QStringLiteral("ru"));
    QCOMPARE(d.groups.at(1).id, QStringLiteral("op"));
    int probes = 0;
    for (const Telegram &t : std::as_const(drive.received)) {
        QVERIFY2(t.service != Service::ParameterValue
                     && t.service != Service::ParameterValueStandard
                     && t.service != Service::PlaintextIndices
                     && t.service != Service::PlaintextDefinition
                     && t.service != Service::CombivisPlaintext,
                 qPrintable(describe(t)));
        if (const auto *name = t.as<NameData>())
            QCOMPARE(name->language, quint8(Language::German));
        if (t.service == Service::GroupProperties)
            ++probes;
    }
    QCOMPARE(probes, 3);
    const ParameterDescription *rotation = d.find(0x0300);
    QVERIFY(rotation->plaintexts.isEmpty());
    QCOMPARE(rotation->values, (std::array<std::optional<qint32>, kParameterSets>{}));
    QCOMPARE(result.lastDone, result.lastTotal);
}

void TestDriveScanner::readsGroupsOnly()
{
    FakeDrive drive;
    makeDrive(drive);
    ScanOptions options;
    options.parameters = false;
    const ScanResult result = scan(drive, options);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;

    QCOMPARE(d.incompleteReason, QString());
    QCOMPARE(d.groups.size(), 3);
    QCOMPARE(d.groups.at(0).name, QStringLiteral("User definition"));
    QCOMPARE(d.groups.at(0).parameterCount, 2);
    QCOMPARE(d.parameterCount(), 0);
    for (const Telegram &t : std::as_const(drive.received)) {
        QVERIFY2(t.service == Service::GroupProperties || t.service == Service::GroupName
                     || t.service == Service::Fieldbus,
                 qPrintable(describe(t)));
    }
    QCOMPARE(result.lastDone, result.lastTotal);
}

void TestDriveScanner::readsOnlyListedParameters()
{
    FakeDrive drive;
    makeDrive(drive);
    ScanOptions options;
    options.onlyParameters = {0x0203, 0x0202, 0x0501, 0x0203, 0x4000};
    const ScanResult result = scan(drive, options);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;

    QCOMPARE(d.incompleteReason, QString());
    QCOMPARE(d.groups.size(), 3);
    QCOMPARE(d.parameterCount(), 2); // 0202h is unused, page 40h holds no group
    QCOMPARE(d.find(0x0203)->name, QStringLiteral("Actual frequency"));
    QCOMPARE(d.find(0x0203)->values[0], std::optional<qint32>(-4180));
    QCOMPARE(d.find(0x0501)->defaultValue, 5);
    QVERIFY(d.groups.at(2).parameters.isEmpty());
    QList<quint16> asked;
    for (const Telegram &t : std::as_const(drive.received)) {
        if (t.service == Service::ParameterName)
            asked.append(t.as<NameData>()->address);
    }
    std::sort(asked.begin(), asked.end());
    QCOMPARE(asked, (QList<quint16>{0x0202, 0x0203, 0x0501}));
    QCOMPARE(result.lastDone, result.lastTotal);
}

void TestDriveScanner::worksWithASinkThatAnswersAtOnce()
{
    FakeDrive later;
    makeDrive(later);
    const ScanResult laterResult = scan(later);
    QCOMPARE(laterResult.finishedCount, 1);

    FakeDrive atOnce;
    makeDrive(atOnce);
    atOnce.synchronous = true;
    DriveScanner scanner(atOnce, identified(), Language::English);
    ScanResult result;
    watch(scanner, result);
    scanner.start(); // everything happens inside start()
    QCOMPARE(result.finishedCount, 1);
    QCOMPARE(*result.description, *laterResult.description);
    QCOMPARE(result.lastDone, result.lastTotal);
}

void TestDriveScanner::cancelKeepsWhatWasRead()
{
    FakeDrive drive;
    makeDrive(drive);
    DriveScanner scanner(drive, {}, Language::English);
    ScanResult result;
    watch(scanner, result);
    int cancelledAt = -1;
    // Cancel once every group is known and the parameters are being read.
    connect(&scanner, &DriveScanner::progress, &scanner, [&](int done) {
        if (done == 270 && cancelledAt < 0) {
            cancelledAt = int(drive.received.size());
            scanner.cancel();
        }
    });
    scanner.start();
    QTRY_COMPARE(result.finishedCount, 1);
    QVERIFY(cancelledAt > 0);
    const DriveDescription &d = *result.description;

    QCOMPARE(d.incompleteReason, QStringLiteral("cancelled"));
    QCOMPARE(drive.cancelCalls, 1);
    QCOMPARE(drive.held(), 0);
    QCOMPARE(d.groups.size(), 3);
    QVERIFY(d.parameterCount() > 0);
    bool missingValue = false;
    for (const GroupDescription &group : d.groups) {
        for (const ParameterDescription &p : group.parameters)
            missingValue = missingValue || !p.values[0];
    }
    QVERIFY(missingValue);

    // A request of the test's own, answered from the event loop as the scan's are: by the time
    // its answer is in, the scan would have sent anything it still meant to.
    bool answered = false;
    drive.submit(Telegram::request(Service::ParameterValueStandard, Access::Read,
                                   ParameterValue { 0x0201 }),
                 [&answered](const Reply &) { answered = true; });
    QTRY_VERIFY(answered);
    QCOMPARE(int(drive.received.size()), cancelledAt + 1);
    QCOMPARE(result.finishedCount, 1);
    QVERIFY(result.lastDone < result.lastTotal);
}

void TestDriveScanner::linkLostEndsTheScan()
{
    FakeDrive drive;
    makeDrive(drive);
    drive.linkLostAfter = 275;
    DriveScanner scanner(drive, identified(), Language::English);
    ScanResult result;
    watch(scanner, result);
    scanner.start();
    QTRY_COMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;
    const int receivedAtEnd = int(drive.received.size());

    QVERIFY(!d.incompleteReason.isEmpty());
    QVERIFY(d.incompleteReason != QStringLiteral("cancelled"));
    QCOMPARE(d.identification, QStringLiteral("F5-M test drive 4.2"));
    QCOMPARE(d.groups.size(), 3);
    QVERIFY(d.parameterCount() > 0);
    QVERIFY(d.parameterCount() <= 7);
    for (const GroupDescription &group : d.groups) {
        for (const ParameterDescription &p : group.parameters)
            QVERIFY2(!p.error.contains(QStringLiteral("cable")), qPrintable(p.error));
    }

    // The requests already handed over end with LinkLost too; nothing new is sent.
    QTRY_COMPARE(drive.held(), 0);
    QCOMPARE(int(drive.received.size()), receivedAtEnd);
    QCOMPARE(result.finishedCount, 1);
}


void TestDriveScanner::readsSetsTogetherWhereTheyAgree_data()
{
    QTest::addColumn<QList<qint32>>("values");
    QTest::addColumn<int>("refusedSet"); // -1: none
    QTest::addColumn<int>("reads");      // service 0 requests for the parameter
    QTest::newRow("all equal") << QList<qint32>{7, 7, 7, 7, 7, 7, 7, 7} << -1 << 1;
    // FFh, 0Fh, F0h, then 4 pairs, then 8 single sets.
    QTest::newRow("all different") << QList<qint32>{0, 1, 2, 3, 4, 5, 6, 7} << -1 << 15;
    // FFh; 0Fh answers; F0h, 30h answers, C0h, 40h, 80h.
    QTest::newRow("set 7 differs") << QList<qint32>{5, 5, 5, 5, 5, 5, 5, 9} << -1 << 7;
    QTest::newRow("set 5 refused") << QList<qint32>{5, 5, 5, 5, 5, 5, 5, 5} << 5 << 7;
}

void TestDriveScanner::readsSetsTogetherWhereTheyAgree()
{
    QFETCH(QList<qint32>, values);
    QFETCH(int, refusedSet);
    QFETCH(int, reads);
    FakeDrive drive;
    makeDrive(drive);
    FakeParameter &display = drive.groups[0x05].parameters[1]; // ud.01, set-programmable
    std::copy(values.cbegin(), values.cend(), display.values.begin());
    display.refusedSet = refusedSet;

    ScanOptions options;
    options.onlyParameters = {0x0501};
    const ScanResult result = scan(drive, options);
    QCOMPARE(result.finishedCount, 1);
    const ParameterDescription *read = result.description->find(0x0501);
    QVERIFY(read);
    for (int set = 0; set < kParameterSets; ++set) {
        // What a read set by set gives: the drive's value, or nothing where it refused.
        const std::optional<qint32> expected
            = set == refusedSet ? std::nullopt : std::optional<qint32>(values.at(set));
        QCOMPARE(read->values[set], expected);
    }
    QCOMPARE(read->error.isEmpty(), refusedSet < 0);
    if (refusedSet >= 0)
        QVERIFY2(read->error.contains(QStringLiteral("set %1").arg(refusedSet)),
                 qPrintable(read->error));
    const auto valueReads = std::count_if(drive.received.cbegin(), drive.received.cend(),
                                          [](const Telegram &t) {
                                              const auto *v = t.as<ParameterValue>();
                                              return t.service == Service::ParameterValue && v
                                                     && v->address == 0x0501;
                                          });
    QCOMPARE(int(valueReads), reads);
}

void TestDriveScanner::asksService13OnlyWhereTheLinkFramesIt()
{
    FakeDrive drive;
    makeDrive(drive);
    drive.framesService13 = false; // HSP5 as seed 000 defines it
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    QVERIFY(result.description->incompleteReason.isEmpty());
    QCOMPARE(result.description->identification, QString());
    QVERIFY(std::none_of(drive.received.cbegin(), drive.received.cend(),
                         [](const Telegram &t) { return t.service == Service::Fieldbus; }));
    QCOMPARE(result.description->parameterCount(), 7);
}

void TestDriveScanner::asksService13OnlyWhenTheUserOptsIn()
{
    // DIN66019II frames it, but seed 003 marks it reserved.
    FakeDrive drive;
    makeDrive(drive);
    const ScanResult result = scan(drive, ScanOptions{});
    QCOMPARE(result.finishedCount, 1);
    QVERIFY(result.description->incompleteReason.isEmpty());
    QCOMPARE(result.description->identification, QString());
    QVERIFY(std::none_of(drive.received.cbegin(), drive.received.cend(),
                         [](const Telegram &t) { return t.service == Service::Fieldbus; }));
    QCOMPARE(result.description->parameterCount(), 7);
}

void TestDriveScanner::aNameReadThatTimesOutIsNeverAParameter()
{
    FakeDrive clean;
    makeDrive(clean);
    const ScanResult expected = scan(clean);

    // ru.02 does not exist; the drive would refuse it, but this time nothing came back. Taken
    // for a parameter, it would use up ru's count of 3 and ru.03 would never be asked.
    FakeDrive drive;
    makeDrive(drive);
    drive.silentNames = {0x0202};
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;
    QVERIFY2(d.incompleteReason.isEmpty(), qPrintable(d.incompleteReason));
    QVERIFY(!d.find(0x0202));
    QVERIFY(d.find(0x0203));
    QCOMPARE(d.groups, expected.description->groups);
}

void TestDriveScanner::aParameterWhoseNameGotNoAnswerMakesTheGroupIncomplete()
{
    FakeDrive drive;
    makeDrive(drive);
    drive.silentNames = {0x0203};
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;
    QVERIFY(!d.find(0x0203));
    QVERIFY2(d.incompleteReason.contains(QStringLiteral("2 of 3"))
                 && d.incompleteReason.contains(QStringLiteral("0203h")),
             qPrintable(d.incompleteReason));
}

void TestDriveScanner::onALineWithErrorsAnswersAreConfirmed()
{
    FakeDrive clean;
    makeDrive(clean);
    const ScanResult expected = scan(clean);

    // ru.00's name comes back garbled, unseen, while the line seems clean; then ru.02's read
    // gets no answer (an error on the line); then op.01's name comes back garbled too.
    FakeDrive drive;
    makeDrive(drive);
    drive.garbledNames = {0x0200, 0x0301};
    drive.silentNames = {0x0202};
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;
    // What was kept before the error is read again: the disagreement is named, not kept.
    QVERIFY2(d.incompleteReason.contains(QStringLiteral("not confirmed"))
                 && d.incompleteReason.contains(QStringLiteral("ru.00")),
             qPrintable(d.incompleteReason));
    // After it, a second read agreeing with a third settles the name.
    QCOMPARE(d.find(0x0301)->name, QStringLiteral("Set value"));
    // Every answer after the first error was read twice.
    QVERIFY(drive.received.size() > clean.received.size() * 3 / 2);
    // On the clean line nothing was read twice.
    QSet<QString> asked;
    for (const Telegram &t : std::as_const(clean.received))
        asked.insert(describe(t));
    QCOMPARE(asked.size(), clean.received.size());
}

void TestDriveScanner::anImplausibleAnswerIsReadAgain()
{
    FakeDrive clean;
    makeDrive(clean);
    const ScanResult expected = scan(clean);

    FakeDrive drive;
    makeDrive(drive);
    drive.swappedLimits = {0x0500};
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    QCOMPARE(*result.description, *expected.description);
    QCOMPARE(drive.received.size(), clean.received.size() + 1);
}

// Read while the line was clean, ru.03 (a live value) and op.00 (a setting) are kept; then the
// line shows an error and both are read again, each showing another value. The setting makes
// the scan incomplete; the live value is left unconfirmed and holds up no backup (on a line
// with 1 % flipped bytes, backups and verifies failed for "ru.00 not confirmed").
void TestDriveScanner::aLiveValueKeptBeforeTheLineShowedErrorsHoldsUpNothing()
{
    FakeDrive drive;
    makeDrive(drive);
    drive.groups[0x02].parameters[3].properties2 |= 1u << 9;
    drive.movingValues = {0x0203, 0x0300};
    drive.errorOnceValuesRead = {0x0203, 0x0300};
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;
    QCOMPARE(drive.errorsNoted, quint64(1));
    const ParameterDescription *live = d.find(0x0203);
    QVERIFY(live);
    QVERIFY(!live->values[0].has_value());
    QVERIFY2(live->error.contains(QStringLiteral("changes it by itself")), qPrintable(live->error));
    QVERIFY2(!d.incompleteReason.contains(QStringLiteral("ru.03")), qPrintable(d.incompleteReason));
    QVERIFY2(d.incompleteReason.contains(QStringLiteral("op.00")), qPrintable(d.incompleteReason));
}

void TestDriveScanner::aValueTheDriveChangesByItselfIsLeftUnconfirmedNotUnread()
{
    // An error on the line at once (ru.00's name gets no answer): from then on every answer is
    // confirmed by another. ru.03 and op.00 give another value at every read; only ru.03 says
    // (properties 2, bit 9) that the drive changes it by itself.
    FakeDrive drive;
    makeDrive(drive);
    drive.groups[0x02].parameters[3].properties2 |= 1u << 9;
    drive.silentNames = {0x0200};
    drive.movingValues = {0x0203, 0x0300};
    const ScanResult result = scan(drive);
    QCOMPARE(result.finishedCount, 1);
    const DriveDescription &d = *result.description;

    // The live value: no value shown as the drive's, in words why, and the scan not incomplete
    // for it.
    const ParameterDescription *live = d.find(0x0203);
    QVERIFY(live);
    QVERIFY(!live->values[0].has_value());
    QVERIFY2(live->error.contains(QStringLiteral("changes it by itself")), qPrintable(live->error));
    QVERIFY2(!d.incompleteReason.contains(QStringLiteral("ru.03")), qPrintable(d.incompleteReason));
    // A setting whose reads never agree is unread: the scan names it.
    const ParameterDescription *setting = d.find(0x0300);
    QVERIFY(setting);
    QVERIFY(!setting->values[0].has_value());
    QVERIFY(!setting->error.contains(QStringLiteral("changes it by itself")));
    QVERIFY2(d.incompleteReason.contains(QStringLiteral("op.00")), qPrintable(d.incompleteReason));
}

void TestDriveScanner::aDriveWithoutIdentityIsNeverCached()
{
    // The hand-made drive has no In group: nothing tells it from another kind.
    QTemporaryDir cache;
    ScanOptions options;
    options.metadata = MetadataSource::Cache;
    options.cacheDirectory = cache.path();
    for (int connection = 0; connection < 2; ++connection) {
        FakeDrive drive;
        makeDrive(drive);
        const ScanResult result = scan(drive, options);
        QCOMPARE(result.finishedCount, 1);
        QVERIFY(!result.description->metadataFromCache);
        QVERIFY(drive.count(Service::GroupProperties, 0x02) == 1); // read cold, every time
        QVERIFY(QDir(cache.path()).entryList(QDir::Files).isEmpty());
    }
}

void TestDriveScanner::variableMetadataIsReadAgainOnACachedKind()
{
    QTemporaryDir cache;
    ScanOptions options;
    options.metadata = MetadataSource::Cache;
    options.cacheDirectory = cache.path();
    constexpr quint32 kUpperLimitAlwaysVariable = 2u << 14;
    const auto makeIdentified = [](FakeDrive &drive) {
        makeDrive(drive);
        addIdentification(drive);
        // Only a scan without a failed metadata read is kept: this drive answers everything.
        drive.groups[0x02].name = "Run";
        drive.groups[0x02].parameters[1].propertiesRefused = false;
        drive.groups[0x03].parameters[1].limitsRefused = false;
        drive.groups[0x05].parameters[1].refusedSet = -1;
        drive.groups[0x05].parameters[0].properties1 |= kUpperLimitAlwaysVariable; // ud.00
    };

    FakeDrive first;
    makeIdentified(first);
    const ScanResult cold = scan(first, options);
    QVERIFY(cold.description && !cold.description->metadataFromCache);
    QCOMPARE(QDir(cache.path()).entryList(QDir::Files).size(), 1);

    // The same kind of drive, where ud.00's upper limit has moved since.
    FakeDrive second;
    makeIdentified(second);
    second.groups[0x05].parameters[0].upper = 5000;
    second.groups[0x05].parameters[1].upper = 999; // constant limits: the cache's stand
    const ScanResult warm = scan(second, options);
    QVERIFY(warm.description && warm.description->metadataFromCache);
    QCOMPARE(warm.description->find(0x0500)->maximum, 5000);
    QCOMPARE(warm.description->find(0x0501)->maximum, 100);
    const auto limitReads = std::count_if(second.received.cbegin(), second.received.cend(),
                                          [](const Telegram &t) {
                                              return t.service == Service::Limits;
                                          });
    QCOMPARE(int(limitReads), 1);
    QCOMPARE(second.count(Service::GroupProperties, 0x05), 0);
}

QTEST_GUILESS_MAIN(TestDriveScanner)
#include "tst_drivescanner.moc"
