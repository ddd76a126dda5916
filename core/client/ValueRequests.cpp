#include "ValueRequests.h"

namespace DriveDesk::ValueRequests {

namespace {

Service standardService(Protocol protocol)
{
    return protocol == Protocol::Din66019 ? Service::Legacy : Service::ParameterValueStandard;
}

} // namespace

Telegram read(quint16 address, quint8 setMask)
{
    return Telegram::request(Service::ParameterValue, Access::Read,
                             ParameterValue{address, setMask, 0});
}

Telegram write(quint16 address, qint32 value, quint8 setMask)
{
    return Telegram::request(Service::ParameterValue, Access::Write,
                             ParameterValue{address, setMask, value});
}

Telegram readStandard(Protocol protocol, quint16 address, quint8 set)
{
    return Telegram::request(standardService(protocol), Access::Read,
                             ParameterValue{address, set, 0});
}

Telegram writeStandard(Protocol protocol, quint16 address, qint32 value, quint8 set)
{
    return Telegram::request(standardService(protocol), Access::Write,
                             ParameterValue{address, set, value});
}

Telegram resetToDefault(quint16 address, quint8 setMask)
{
    return Telegram::request(Service::CheckDefault, Access::Write,
                             DefaultCheckData{address, setMask});
}

Telegram presence(Protocol protocol, quint16 address)
{
    return protocol == Protocol::Din66019 ? readStandard(protocol, address) : read(address, 1);
}

} // namespace DriveDesk::ValueRequests
