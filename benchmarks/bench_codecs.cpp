// Codec throughput: telegrams per second, encode + decode, for each protocol.
#include "protocol/Codec.h"

#include <QElapsedTimer>
#include <QList>

#include <cstdio>

using namespace DriveDesk;

namespace {

// A realistic mix: what a scan and an editor send and receive.
QList<Telegram> sampleTelegrams(Protocol protocol)
{
    QList<Telegram> telegrams;
    auto add = [&](Service service, Access access, ServiceData data, bool withName = false) {
        Telegram request = Telegram::request(service, access, data);
        request.operatorInvoke = quint8(telegrams.size() % 15 + 1);
        Telegram response = request.response();
        if (withName) {
            if (auto *name = response.as<NameData>())
                name->text = QByteArrayLiteral("Actual frequency");
        }
        telegrams << request << response;
    };
    if (protocol == Protocol::Din66019) {
        add(Service::Legacy, Access::Read, ParameterValue{0x0203, 0, 1234});
        add(Service::Legacy, Access::Write, ParameterValue{0x0203, 0, 1234});
        return telegrams;
    }
    add(Service::ParameterValue, Access::Read, ParameterValue{0x0203, 0x01, -52250});
    add(Service::ParameterValue, Access::Write, ParameterValue{0x0203, 0xFF, 1000});
    add(Service::Limits, Access::Read, ParameterLimits{0x0203, -40000, 40000});
    add(Service::DefaultValue, Access::Read, DefaultValue{0x0203, 0});
    add(Service::Properties, Access::Read, PropertiesData{0x0203, 0x00000E5B, 0x0000000F});
    add(Service::DisplayScaling, Access::Read, DisplayScalingData{0x0203, 80, 1, 0, 0x0212});
    add(Service::ParameterName, Access::Read, NameData{0x0203, 0, {}}, true);
    add(Service::Scope, Access::Read, ScopeData{4711, {123456, -5}, {300, -300}});
    return telegrams;
}

void run(Protocol protocol)
{
    const auto codec = makeCodec(protocol);
    const QList<Telegram> telegrams = sampleTelegrams(protocol);
    QList<QByteArray> encoded;
    for (const Telegram &t : telegrams)
        encoded << codec->encode(t);

    constexpr int rounds = 20000;
    QElapsedTimer timer;

    timer.start();
    qsizetype bytes = 0;
    for (int round = 0; round < rounds; ++round) {
        for (const Telegram &t : telegrams)
            bytes += codec->encode(t).size();
    }
    const double encodeSeconds = timer.nsecsElapsed() / 1e9;

    auto operatorSide = codec->makeDecoder(Role::Operator);
    auto driveSide = codec->makeDecoder(Role::Drive);
    int decoded = 0;
    timer.restart();
    for (int round = 0; round < rounds; ++round) {
        for (int i = 0; i < encoded.size(); ++i) {
            FrameDecoder &decoder = (i % 2 == 0) ? *driveSide : *operatorSide;
            decoder.feed(encoded[i]);
            while (auto item = decoder.next())
                decoded += std::holds_alternative<Telegram>(*item) ? 1 : 0;
        }
    }
    const double decodeSeconds = timer.nsecsElapsed() / 1e9;

    const double count = double(rounds) * telegrams.size();
    std::printf("%-11s encode %10.0f telegrams/s  decode %10.0f telegrams/s  "
                "(%d of %.0f decoded, %.1f bytes each)\n",
                qPrintable(protocolName(protocol)), count / encodeSeconds, count / decodeSeconds,
                decoded, count, double(bytes) / count);
}

} // namespace

int main()
{
    for (Protocol protocol : {Protocol::Hsp5, Protocol::Din66019II, Protocol::Din66019})
        run(protocol);
    return 0;
}
