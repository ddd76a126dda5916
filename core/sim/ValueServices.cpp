#include "Services.h"

#include "DriveState.h"
#include "ParameterAccess.h"

namespace DriveDesk::Sim {

Telegram answer(const Telegram &request, Ack ack, ServiceData data)
{
    Telegram response = request.response(ack);
    response.data = std::move(data);
    return response;
}

Telegram malformed(const Telegram &request)
{
    return answer(request, Ack::FramingError, emptyDataFor(request.service));
}

namespace {

// The set mask a value service addresses; nothing (ack 11) for an invalid set.
std::optional<quint8> setMaskFor(const ParameterAccess &access, const DriveState &state,
                                 Service service, quint8 set)
{
    switch (service) {
    case Service::Legacy:
        return quint8(1u << state.setPointer()); // indirect, through Fr.09
    case Service::ParameterValue:
    case Service::CheckDefault:
        return set;
    case Service::ParameterValueStandard:
    case Service::CheckDefaultStandard:
        return access.standardSetMask(set);
    case Service::SubindexValue:
        if (set < kSets)
            return quint8(1u << set);
        return std::nullopt;
    default:
        return std::nullopt;
    }
}

Telegram answerValue(DriveState &state, const Telegram &request)
{
    const auto *data = request.as<ParameterValue>();
    if (!data)
        return malformed(request);
    ParameterAccess access(state);
    ParameterValue result = *data;
    const std::optional<quint8> mask = setMaskFor(access, state, request.service, data->set);
    if (!state.db().find(data->address))
        return answer(request, Ack::AddressInvalid, ParameterValue { data->address, data->set, 0 });
    if (!mask)
        return answer(request, Ack::SetInvalid, ParameterValue { data->address, data->set, 0 });
    if (request.isWrite())
        return answer(request, access.write(data->address, *mask, data->value), result);
    const ValueResult read = access.read(data->address, *mask);
    result.value = read.ack == Ack::Ok ? read.value : 0;
    if (request.service == Service::Legacy)
        result.value = qint16(result.value); // a 16-bit value on the legacy line
    return answer(request, read.ack, result);
}

Telegram answerDefault(DriveState &state, const Telegram &request)
{
    const auto *data = request.as<DefaultCheckData>();
    if (!data)
        return malformed(request);
    ParameterAccess access(state);
    if (!state.db().find(data->address))
        return answer(request, Ack::AddressInvalid, *data);
    const std::optional<quint8> mask = setMaskFor(access, state, request.service, data->set);
    if (!mask)
        return answer(request, Ack::SetInvalid, *data);
    const Ack ack = request.isWrite() ? access.setDefault(data->address, *mask)
                                      : access.checkDefault(data->address, *mask);
    return answer(request, ack, *data);
}

} // namespace

Telegram answerValueService(DriveState &state, const Telegram &request)
{
    if (request.service == Service::CheckDefault
        || request.service == Service::CheckDefaultStandard)
        return answerDefault(state, request);
    return answerValue(state, request);
}

} // namespace DriveDesk::Sim
