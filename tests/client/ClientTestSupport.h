#pragma once

#include "bus/LinkFactory.h"
#include "bus/SimulatorServer.h"
#include "client/DriveClient.h"
#include "protocol/Codec.h"

#include <QCoreApplication>
#include <QFuture>
#include <QSignalSpy>
#include <QTest>

#include <memory>

// What the client tests share: settings for the simulated drive, a connected client, waiting
// for futures in the test's event loop.
namespace DriveDesk::ClientTest {

constexpr int kWaitMs = 15000;

// Parameters of the simulated F5 (core/sim/data/sim_f5_parameters.csv) the tests rely on.
constexpr quint16 kMaxSpeedForward = 0x030B; // op.11, 0..4000, default 3000, 8 sets
constexpr qint32 kMaxSpeedDefault = 3000;
constexpr quint16 kMotorVoltage = 0x0604;    // dr.04, 120..500, default 400, 8 sets
constexpr quint16 kCurrentLimit = 0x0418;    // Pn.24, 0..200, default 150, 8 sets
constexpr quint16 kRatedCurrent = 0x0E01;    // In.01, read-only, 10.5 A = raw 105
constexpr quint16 kInverterType = 0x0E00;    // In.00, read-only, 0F50h

// The simulated drive behind a TCP port on loopback, as behind a serial-to-Ethernet gateway.
inline ConnectionSettings tcpTo(const SimulatorServer &server, Protocol protocol = Protocol::Hsp5)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Tcp;
    settings.host = QStringLiteral("127.0.0.1");
    settings.port = server.tcpPort();
    settings.protocol = protocol;
    return settings;
}

inline ConnectionSettings simulated(Protocol protocol, SimulationOptions simulation = {})
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.protocol = protocol;
    settings.simulation = simulation;
    settings.driveAddress = simulation.driveAddresses.value(0, 1);
    return settings;
}

// Simulation without latency: many requests in little time.
inline SimulationOptions fast(SimulationOptions options = {})
{
    options.replyLatencyUs = 0;
    return options;
}

template<typename T>
bool waitFinished(const QFuture<T> &future, int timeoutMs = kWaitMs)
{
    return QTest::qWaitFor([&future] { return future.isFinished(); }, timeoutMs);
}

// The reply, or a Reply saying why there is none (still running, cancelled).
inline Reply replyOf(const QFuture<Reply> &future, int timeoutMs = kWaitMs)
{
    Reply missing;
    missing.status = Reply::Status::Cancelled;
    if (!waitFinished(future, timeoutMs)) {
        missing.detail = QStringLiteral("the test gave up waiting");
        return missing;
    }
    if (future.isCanceled() || future.resultCount() == 0) {
        missing.detail = QStringLiteral("the future has no result");
        return missing;
    }
    return future.result();
}

// A started client, connected (check state()), with its traffic recorded.
struct Session {
    std::unique_ptr<DriveClient> client;
    std::unique_ptr<QSignalSpy> traffic;

    explicit Session(const ConnectionSettings &settings, ClientOptions options = {})
        : client(std::make_unique<DriveClient>(settings, everyLink(), options))
        , traffic(std::make_unique<QSignalSpy>(client.get(), &DriveClient::traffic))
    {
        client->connectToDrive();
        // Whether it worked, connected() tells.
        [[maybe_unused]] const bool up = QTest::qWaitFor(
            [this] { return client->state() == DriveClient::State::Connected; }, kWaitMs);
    }

    bool connected() const { return client->state() == DriveClient::State::Connected; }
    Reply call(const QFuture<Reply> &future) const { return replyOf(future); }

    Reply request(Service service, Access access, ServiceData data, int driveAddress = -1) const
    {
        Telegram telegram = Telegram::request(service, access, std::move(data));
        telegram.driveAddress = driveAddress;
        return replyOf(client->send(telegram));
    }

    QList<TrafficRecord> records() const
    {
        // The records come from the worker thread as queued signals: take in those on the way,
        // or a reply that finished a moment ago may be missing the record of its request.
        QCoreApplication::processEvents();
        QList<TrafficRecord> list;
        for (const QList<QVariant> &arguments : *traffic)
            list.append(arguments.at(0).value<TrafficRecord>());
        return list;
    }
};

// The services of the requests in `records`, read back as a drive reads them with `codec`.
inline QList<Service> sentServices(const QList<TrafficRecord> &records, const ProtocolCodec &codec)
{
    const auto decoder = codec.makeDecoder(Role::Drive);
    QList<Service> services;
    for (const TrafficRecord &record : records) {
        if (record.kind != TrafficRecord::Kind::Sent)
            continue;
        decoder->feed(record.bytes);
        while (const std::optional<Decoded> item = decoder->next()) {
            if (const auto *telegram = std::get_if<Telegram>(&*item))
                services.append(telegram->service);
        }
    }
    return services;
}

// The value a read answered, or -1 when it did not answer with one (the test then fails on it).
inline qint32 valueOf(const Reply &reply)
{
    const auto *value = reply.data<ParameterValue>();
    return value ? value->value : -1;
}

inline QString describeReply(const Reply &reply)
{
    return QStringLiteral("%1: %2").arg(statusName(reply.status), reply.message());
}

} // namespace DriveDesk::ClientTest
