#include "Services.h"

#include "DriveState.h"
#include "F5Addresses.h"
#include "ParameterAccess.h"

namespace DriveDesk::Sim {

namespace {

constexpr quint16 kWriteFlag = 0x8000; // services 50/53: MSB of the parameter address

// Values for the write channels (Sy.24..Sy.31); a channel without a value is left alone.
using ChannelValues = std::array<std::optional<qint32>, 4>;

// Writes the process data out: every value is checked first, so either all are written or
// none (ack 3 outside the limits). Channels that are off take nothing.
Ack writeChannels(DriveState &state, const ChannelValues &values)
{
    ParameterAccess access(state);
    struct Pending
    {
        quint16 address;
        quint8 mask;
        qint32 value;
    };
    QList<Pending> pending;
    for (std::size_t channel = 0; channel < values.size(); ++channel) {
        if (!values[channel])
            continue;
        const qint32 address = state.setting(F5::kWriteChannel[channel], -1);
        if (address < 0)
            continue;
        const auto mask = quint8(state.setting(F5::kWriteChannel[channel] + 1, 1));
        const Ack ack
            = access.checkWrite(quint16(address), *values[channel], Permission::ProcessData);
        if (ack != Ack::Ok)
            return ack;
        pending.append({ quint16(address), mask, *values[channel] });
    }
    for (const Pending &p : std::as_const(pending))
        access.write(p.address, p.mask, p.value, Permission::ProcessData);
    return Ack::Ok;
}

ProcessData32 read32(const DriveState &state)
{
    const std::array<qint32, 4> in = state.readChannels();
    return ProcessData32 { { in[0], in[1] } };
}

ProcessData16 read16(const DriveState &state)
{
    const std::array<qint32, 4> in = state.readChannels();
    return ProcessData16 { { qint16(in[0]), qint16(in[1]), qint16(in[2]), qint16(in[3]) } };
}

Telegram answerSimplex(DriveState &state, const Telegram &request)
{
    switch (request.service) {
    case Service::ProcessData1:
    case Service::ProcessData4: {
        const auto *d = request.as<ProcessData32>();
        if (!d)
            return malformed(request);
        if (request.isWrite())
            return answer(request, writeChannels(state, { d->values[0], d->values[1], {}, {} }),
                          *d);
        return answer(request, Ack::Ok, read32(state));
    }
    case Service::ProcessData2:
    case Service::ProcessData5: {
        const auto *d = request.as<ProcessData16>();
        if (!d)
            return malformed(request);
        if (request.isWrite())
            return answer(
                request,
                writeChannels(state, { d->values[0], d->values[1], d->values[2], d->values[3] }),
                *d);
        return answer(request, Ack::Ok, read16(state));
    }
    case Service::Scope: {
        const auto *d = request.as<ScopeData>();
        if (!d)
            return malformed(request);
        if (request.isWrite())
            return answer(
                request,
                writeChannels(state, { d->wide[0], d->wide[1], d->narrow[0], d->narrow[1] }), *d);
        const std::array<qint32, 4> in = state.readChannels();
        return answer(request, Ack::Ok,
                      ScopeData { quint16(state.clockMs() & 0xFFFF),
                                  { in[0], in[1] },
                                  { qint16(in[2]), qint16(in[3]) } });
    }
    case Service::ScopeRecord: {
        const auto *d = request.as<ScopeRecordData>();
        if (!d)
            return malformed(request);
        ScopeRecordData result { d->mode, d->index, 0, {} };
        if (request.isWrite())
            return answer(request, Ack::ServiceNotAvailable, result);
        if (d->mode == 0) {
            result.timestamp = quint16(state.clockMs() & 0xFFFF);
            result.values = state.readChannels();
            return answer(request, Ack::Ok, result);
        }
        if (d->mode != 1 || d->index >= state.recordCount())
            return answer(request, Ack::DataInvalid, result);
        // Offline: the timestamp field carries the highest index there is.
        result.timestamp = quint16(state.recordCount() - 1);
        result.values = state.record(d->index).values;
        return answer(request, Ack::Ok, result);
    }
    default:
        break;
    }
    return answer(request, Ack::ServiceNotAvailable, emptyDataFor(request.service));
}

// Services 50/53: three process data values and one parameter access (standard set
// addressing, active set).
Telegram answerProcessParameter(DriveState &state, const Telegram &request)
{
    const auto *d = request.as<ProcessParameterData>();
    if (!d)
        return malformed(request);
    ProcessParameterData result = *d;
    result.parameterValue = 0;
    Ack ack = writeChannels(state, { d->value1, d->value2, d->value3, {} });
    if (ack == Ack::Ok && d->parameterAddress != 0) {
        ParameterAccess access(state);
        const auto address = quint16(d->parameterAddress & ~kWriteFlag);
        const auto mask = quint8(1u << state.activeSet());
        if (d->parameterAddress & kWriteFlag) {
            ack = access.write(address, mask, d->parameterValue);
        } else {
            const ValueResult read = access.read(address, mask);
            ack = read.ack;
            result.parameterValue = read.ack == Ack::Ok ? read.value : 0;
        }
    }
    const std::array<qint32, 4> in = state.readChannels();
    result.value1 = in[0];
    result.value2 = qint16(in[1]);
    result.value3 = qint16(in[2]);
    return answer(request, ack, result);
}

Telegram answerDuplex(DriveState &state, const Telegram &request)
{
    // Duplex services write and read in one telegram; there is no read-only form.
    if (!request.isWrite())
        return answer(request, Ack::ServiceNotAvailable, emptyDataFor(request.service));
    switch (request.service) {
    case Service::ProcessDataDuplex1:
    case Service::ProcessDataDuplex4: {
        const auto *d = request.as<ProcessData32>();
        if (!d)
            return malformed(request);
        const Ack ack = writeChannels(state, { d->values[0], d->values[1], {}, {} });
        return answer(request, ack, read32(state));
    }
    case Service::ProcessDataDuplex2:
    case Service::ProcessDataDuplex5: {
        const auto *d = request.as<ProcessData16>();
        if (!d)
            return malformed(request);
        const Ack ack
            = writeChannels(state, { d->values[0], d->values[1], d->values[2], d->values[3] });
        return answer(request, ack, read16(state));
    }
    case Service::ProcessDataDuplex3:
    case Service::ProcessDataDuplex6:
        return answerProcessParameter(state, request);
    default:
        break;
    }
    return answer(request, Ack::ServiceNotAvailable, emptyDataFor(request.service));
}

} // namespace

Telegram answerProcessDataService(DriveState &state, const Telegram &request)
{
    switch (request.service) {
    case Service::ProcessDataDuplex1:
    case Service::ProcessDataDuplex2:
    case Service::ProcessDataDuplex3:
    case Service::ProcessDataDuplex4:
    case Service::ProcessDataDuplex5:
    case Service::ProcessDataDuplex6:
        return answerDuplex(state, request);
    default:
        return answerSimplex(state, request);
    }
}

} // namespace DriveDesk::Sim
