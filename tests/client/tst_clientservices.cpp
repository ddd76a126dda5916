#include "ClientTestSupport.h"

#include "bus/LinkFactory.h"

#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::ClientTest;

Q_DECLARE_METATYPE(DriveDesk::Protocol)

// Every service through the real client to the simulated drive in process, in HSP5 and in
// DIN66019II, checked against what the simulated F5 holds (core/sim/data).
class TestClientServices : public QObject
{
    Q_OBJECT
private:
    static void protocols()
    {
        QTest::addColumn<Protocol>("protocol");
        QTest::newRow("hsp5") << Protocol::Hsp5;
        QTest::newRow("din66019ii") << Protocol::Din66019II;
    }

    static ConnectionSettings settings()
    {
        QFETCH(Protocol, protocol);
        return simulated(protocol, fast());
    }

private slots:
    void theApplicationChoosesTheLinks()
    {
        // A program that offers no simulated drive hands the client no link for it.
        int asked = 0;
        DriveClient client(simulated(Protocol::Hsp5), [&asked](const ConnectionSettings &) {
            ++asked;
            return std::unique_ptr<Link>();
        });
        QSignalSpy failed(&client, &DriveClient::connectionFailed);
        client.connectToDrive();
        QVERIFY(failed.wait(kWaitMs));
        QCOMPARE(asked, 1);
        QVERIFY2(failed.constFirst().at(0).toString().contains(QStringLiteral("cannot open")),
                 qPrintable(failed.constFirst().at(0).toString()));
        QCOMPARE(client.state(), DriveClient::State::Disconnected);
        const Reply reply = replyOf(client.readValue(kMaxSpeedForward, 1));
        QCOMPARE(reply.status, Reply::Status::NotConnected);
    }

    void connects_data() { protocols(); }
    void connects()
    {
        DriveClient client(settings(), everyLink());
        QSignalSpy connected(&client, &DriveClient::connected);
        QSignalSpy states(&client, &DriveClient::stateChanged);
        QCOMPARE(client.state(), DriveClient::State::Disconnected);
        client.connectToDrive();
        QTRY_COMPARE(connected.size(), 1);
        QCOMPARE(client.state(), DriveClient::State::Connected);
        QCOMPARE(states.first().at(0).value<DriveClient::State>(), DriveClient::State::Connecting);
        client.disconnectFromDrive();
        QTRY_COMPARE(client.state(), DriveClient::State::Disconnected);
    }

    void requestWithoutConnectionFailsAtOnce_data() { protocols(); }
    void requestWithoutConnectionFailsAtOnce()
    {
        DriveClient client(settings(), everyLink());
        const Reply reply = replyOf(client.readValue(kMaxSpeedForward, 1));
        QCOMPARE(reply.status, Reply::Status::NotConnected);
        QCOMPARE(reply.message(), QStringLiteral("not connected to a drive"));
    }

    void valueWriteAndReadBack_data() { protocols(); }
    void valueWriteAndReadBack()
    {
        Session s(settings());
        QVERIFY(s.connected());
        Reply read = s.call(s.client->readValue(kMaxSpeedForward, 0x01));
        QVERIFY2(read.ok(), qPrintable(describeReply(read)));
        QCOMPARE(read.data<ParameterValue>()->value, kMaxSpeedDefault);
        QCOMPARE(read.data<ParameterValue>()->address, kMaxSpeedForward);

        const Reply written = s.call(s.client->writeValue(kMaxSpeedForward, 2500, 0x01));
        QVERIFY2(written.ok(), qPrintable(describeReply(written)));
        read = s.call(s.client->readValue(kMaxSpeedForward, 0x01));
        QCOMPARE(read.data<ParameterValue>()->value, 2500);
        // Set 1 kept its value.
        read = s.call(s.client->readValue(kMaxSpeedForward, 0x02));
        QCOMPARE(read.data<ParameterValue>()->value, kMaxSpeedDefault);
        // Sets 0 and 1 differ: a read over both is refused with "data invalid".
        read = s.call(s.client->readValue(kMaxSpeedForward, 0x03));
        QCOMPARE(read.status, Reply::Status::Refused);
        QCOMPARE(read.ack(), Ack::DataInvalid);
    }

    void standardSetAddressing_data() { protocols(); }
    void standardSetAddressing()
    {
        Session s(settings());
        QVERIFY(s.connected());
        QVERIFY(s.call(s.client->writeValueStandard(kCurrentLimit, 120, 0)).ok());
        const Reply read = s.call(s.client->readValueStandard(kCurrentLimit, 0));
        QVERIFY2(read.ok(), qPrintable(describeReply(read)));
        QCOMPARE(read.data<ParameterValue>()->value, 120);
        const Reply enhanced = s.call(s.client->readValue(kCurrentLimit, 0x01));
        QCOMPARE(enhanced.data<ParameterValue>()->value, 120);
    }

    void refusalsCarryTheDrivesAck_data() { protocols(); }
    void refusalsCarryTheDrivesAck()
    {
        Session s(settings());
        QVERIFY(s.connected());
        const Reply outOfLimits = s.call(s.client->writeValue(kMaxSpeedForward, 5000, 0x01));
        QCOMPARE(outOfLimits.status, Reply::Status::Refused);
        QCOMPARE(outOfLimits.ack(), Ack::DataInvalid);
        QCOMPARE(outOfLimits.message(), QStringLiteral("drive refused: data invalid"));

        const Reply readOnly = s.call(s.client->writeValue(kRatedCurrent, 50, 0x01));
        QCOMPARE(readOnly.status, Reply::Status::Refused);
        QCOMPARE(readOnly.ack(), Ack::WriteProtected);
        QCOMPARE(readOnly.message(), QStringLiteral("drive refused: parameter write protected"));

        const Reply badSet = s.call(s.client->readValue(kMaxSpeedForward, 0x00));
        QCOMPARE(badSet.status, Reply::Status::Refused);
        QCOMPARE(badSet.ack(), Ack::SetInvalid);
        QCOMPARE(s.call(s.client->writeValueStandard(kMaxSpeedForward, 10, 2)).ack(),
                 Ack::SetInvalid);

        // After refusals the drive still answers (DIN66019II: the selection is renewed).
        const Reply after = s.call(s.client->readValue(kRatedCurrent, 0x01));
        QVERIFY2(after.ok(), qPrintable(describeReply(after)));
        QCOMPARE(after.data<ParameterValue>()->value, 105);
    }

    void metadata_data() { protocols(); }
    void metadata()
    {
        Session s(settings());
        QVERIFY(s.connected());
        const Reply limits = s.request(Service::Limits, Access::Read,
                                       ParameterLimits{kMaxSpeedForward, 0, 0});
        QVERIFY2(limits.ok(), qPrintable(describeReply(limits)));
        QCOMPARE(limits.data<ParameterLimits>()->lower, 0);
        QCOMPARE(limits.data<ParameterLimits>()->upper, 4000);

        const Reply defaultValue = s.request(Service::DefaultValue, Access::Read,
                                             DefaultValue{kMotorVoltage, 0});
        QCOMPARE(defaultValue.data<DefaultValue>()->value, 400);

        const Reply properties = s.request(Service::Properties, Access::Read,
                                           PropertiesData{kMaxSpeedForward, 0, 0});
        QVERIFY2(properties.ok(), qPrintable(describeReply(properties)));
        QVERIFY(properties.data<PropertiesData>()->properties1 & (1u << 11)); // set-programmable
        const Reply fixedProperties = s.request(Service::Properties, Access::Read,
                                                PropertiesData{kRatedCurrent, 0, 0});
        QVERIFY(!(fixedProperties.data<PropertiesData>()->properties1 & (1u << 11)));

        const Reply scaling = s.request(Service::DisplayScaling, Access::Read,
                                        DisplayScalingData{kRatedCurrent});
        QVERIFY2(scaling.ok(), qPrintable(describeReply(scaling)));
        QCOMPARE(scaling.data<DisplayScalingData>()->address, kRatedCurrent);

        const Reply name = s.request(Service::ParameterName, Access::Read,
                                     NameData{kMaxSpeedForward, 0, {}});
        QVERIFY2(name.ok(), qPrintable(describeReply(name)));
        QCOMPARE(name.data<NameData>()->text, QByteArrayLiteral("Maximum speed forward"));
        const Reply german = s.request(Service::ParameterName, Access::Read,
                                       NameData{kMaxSpeedForward, 1, {}});
        QCOMPARE(german.data<NameData>()->text, QByteArrayLiteral("Max. Drehzahl rechts"));
        QCOMPARE(german.data<NameData>()->language, quint8(1));
    }

    void groups_data() { protocols(); }
    void groups()
    {
        Session s(settings());
        QVERIFY(s.connected());
        const Reply properties = s.request(Service::GroupProperties, Access::Read,
                                           GroupPropertiesData{0x0300});
        QVERIFY2(properties.ok(), qPrintable(describeReply(properties)));
        const GroupPropertiesData *group = properties.data<GroupPropertiesData>();
        QCOMPARE(QByteArray(group->id.data(), 2), QByteArrayLiteral("op"));
        QCOMPARE(group->shortcut, 'o');

        const Reply name = s.request(Service::GroupName, Access::Read, NameData{0x0300, 0, {}});
        QCOMPARE(name.data<NameData>()->text, QByteArrayLiteral("Operational parameters"));
    }

    void plaintexts_data() { protocols(); }
    void plaintexts()
    {
        Session s(settings());
        QVERIFY(s.connected());
        constexpr quint16 rotationSource = 0x0328; // op.40, 4 texts
        const Reply indices = s.request(Service::PlaintextIndices, Access::Read,
                                        PlaintextIndicesData{rotationSource});
        QVERIFY2(indices.ok(), qPrintable(describeReply(indices)));
        const PlaintextIndicesData index = *indices.data<PlaintextIndicesData>();
        QCOMPARE(index.combivisCount, quint16(1));

        PlaintextDefinitionData askDefinition;
        askDefinition.index = index.combivisIndex;
        const Reply definition = s.request(Service::PlaintextDefinition, Access::Read,
                                           askDefinition);
        QVERIFY2(definition.ok(), qPrintable(describeReply(definition)));
        QCOMPARE(definition.data<PlaintextDefinitionData>()->count, quint8(4));

        CombivisPlaintextData askText;
        askText.index = index.combivisIndex;
        askText.subindex = 2;
        const Reply text = s.request(Service::CombivisPlaintext, Access::Read, askText);
        QVERIFY2(text.ok(), qPrintable(describeReply(text)));
        QCOMPARE(text.data<CombivisPlaintextData>()->value, 2);
        QCOMPARE(text.data<CombivisPlaintextData>()->text, QByteArrayLiteral("always forward"));

        askText.subindex = 9;
        const Reply beyond = s.request(Service::CombivisPlaintext, Access::Read, askText);
        QCOMPARE(beyond.status, Reply::Status::Refused);
        QCOMPARE(beyond.ack(), Ack::DataInvalid);

        const Reply display = s.request(Service::DisplayPlaintext, Access::Read,
                                        DisplayPlaintextData{index.displayIndex, 3, 0});
        QVERIFY2(display.ok(), qPrintable(describeReply(display)));
        QCOMPARE(display.data<DisplayPlaintextData>()->value, 3);
        // HSP5 carries the display's 7-segment patterns, DIN66019II its five characters.
        const auto segments = display.data<DisplayPlaintextData>()->segments;
        const bool printable = std::all_of(segments.begin(), segments.end(),
                                           [](quint8 c) { return c >= 0x20 && c < 0x7F; });
        if (qstrcmp(QTest::currentDataTag(), "din66019ii") == 0)
            QVERIFY(printable);
    }

    void defaults_data() { protocols(); }
    void defaults()
    {
        Session s(settings());
        QVERIFY(s.connected());
        const auto check = [&s] {
            return s.request(Service::CheckDefault, Access::Read,
                             DefaultCheckData{kMotorVoltage, 0x01});
        };
        QVERIFY2(check().ok(), qPrintable(describeReply(check())));
        QVERIFY(s.call(s.client->writeValue(kMotorVoltage, 230, 0x01)).ok());
        const Reply changed = check();
        QCOMPARE(changed.status, Reply::Status::Refused);
        QCOMPARE(changed.ack(), Ack::DataInvalid);

        const Reply reset = s.call(s.client->resetToDefault(kMotorVoltage, 0x01));
        QVERIFY2(reset.ok(), qPrintable(describeReply(reset)));
        QCOMPARE(valueOf(s.call(s.client->readValue(kMotorVoltage, 0x01))),
                 400);
    }

    void processDataAndScope_data() { protocols(); }
    void processDataAndScope()
    {
        Session s(settings());
        QVERIFY(s.connected());
        const Reply scope = s.call(s.client->readScope());
        QVERIFY2(scope.ok(), qPrintable(describeReply(scope)));
        QVERIFY(scope.data<ScopeData>());

        const Reply wide = s.request(Service::ProcessData1, Access::Read, ProcessData32{});
        QVERIFY2(wide.ok(), qPrintable(describeReply(wide)));
        const Reply narrow = s.request(Service::ProcessData2, Access::Read, ProcessData16{});
        QVERIFY2(narrow.ok(), qPrintable(describeReply(narrow)));
        const Reply duplex = s.request(Service::ProcessDataDuplex1, Access::Write,
                                       ProcessData32{{1500, 0}});
        QVERIFY2(duplex.ok(), qPrintable(describeReply(duplex)));
    }

    void unsupportedRequestIsRefusedBeforeSending_data() { protocols(); }
    void unsupportedRequestIsRefusedBeforeSending()
    {
        Session s(settings());
        QVERIFY(s.connected());
        // A text longer than 24 characters cannot be encoded.
        const Reply tooLong = s.request(Service::ParameterName, Access::Write,
                                        NameData{kMaxSpeedForward, 0, QByteArray(40, 'x')});
        QCOMPARE(tooLong.status, Reply::Status::Unsupported);
        QVERIFY(!tooLong.detail.isEmpty());
        QCOMPARE(tooLong.attempts, 0);
    }

    void trafficShowsEveryTelegram_data() { protocols(); }
    void trafficShowsEveryTelegram()
    {
        Session s(settings());
        QVERIFY(s.connected());
        QVERIFY(s.call(s.client->readValue(kMaxSpeedForward, 0x01)).ok());
        QTRY_COMPARE(s.traffic->size(), 2);
        const QList<TrafficRecord> records = s.records();
        QCOMPARE(records.at(0).kind, TrafficRecord::Kind::Sent);
        QCOMPARE(records.at(1).kind, TrafficRecord::Kind::Received);
        QVERIFY(!records.at(0).bytes.isEmpty());
        QVERIFY(records.at(1).meaning.contains(QStringLiteral("3000")));
    }
};

QTEST_GUILESS_MAIN(TestClientServices)
#include "tst_clientservices.moc"
