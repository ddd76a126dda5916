#include "ParameterAccess.h"

#include "F5Addresses.h"
#include "Passwords.h"

#include <algorithm>

namespace DriveDesk::Sim {

namespace {

bool isReadChannelDefinition(quint16 address)
{
    return std::find(F5::kReadChannel.begin(), F5::kReadChannel.end(), address)
        != F5::kReadChannel.end();
}

bool isWriteChannelDefinition(quint16 address)
{
    return std::find(F5::kWriteChannel.begin(), F5::kWriteChannel.end(), address)
        != F5::kWriteChannel.end();
}

} // namespace

std::optional<quint8> ParameterAccess::standardSetMask(quint8 set) const
{
    if (set == 0)
        return quint8(1u << m_state.activeSet());
    if (set == 1)
        return quint8(1u << m_state.setPointer());
    return std::nullopt;
}

ValueResult ParameterAccess::read(quint16 address, quint8 setMask) const
{
    const int index = m_state.db().indexOf(address);
    if (index < 0)
        return { Ack::AddressInvalid, 0 };
    if (setMask == 0)
        return { Ack::SetInvalid, 0 };
    const SimParameter &p = m_state.db().parameters()[std::size_t(index)];
    if (p.readLevel() > m_state.passwordLevel())
        return { Ack::AddressOrPasswordInvalid, 0 };
    std::optional<qint32> value;
    for (int set = 0; set < kSets; ++set) {
        if (!(setMask & (1u << set)))
            continue;
        const qint32 v = m_state.value(index, set);
        if (value && *value != v)
            return { Ack::DataInvalid, 0 };
        value = v;
        if (!p.isSetProgrammable())
            break;
    }
    return { Ack::Ok, *value };
}

Ack ParameterAccess::checkWrite(quint16 address, qint32 value, Permission permission) const
{
    const int index = m_state.db().indexOf(address);
    return index < 0 ? Ack::AddressInvalid : checkWriteAt(index, value, permission);
}

Ack ParameterAccess::checkWriteAt(int index, qint32 value, Permission permission) const
{
    const SimParameter &p = m_state.db().parameters()[std::size_t(index)];
    if (p.isReadOnly())
        return Ack::WriteProtected;
    if (permission == Permission::PasswordLevel
        && (p.writeLevel() > m_state.passwordLevel() || p.readLevel() > m_state.passwordLevel()))
        return Ack::AddressOrPasswordInvalid;
    if (value < p.minimum || value > p.maximum)
        return Ack::DataInvalid;
    if (isReadChannelDefinition(p.address) || isWriteChannelDefinition(p.address))
        return validateChannel(p.address, value);
    return Ack::Ok;
}

Ack ParameterAccess::validateChannel(quint16 address, qint32 value) const
{
    if (value == -1)
        return Ack::Ok;
    const SimParameter *target = m_state.db().find(quint16(value));
    if (!target || !target->allowsProcessData())
        return Ack::DataInvalid;
    // A channel must not open a way round the password level in force.
    if (target->readLevel() > m_state.passwordLevel())
        return Ack::DataInvalid;
    if (isWriteChannelDefinition(address)
        && (target->isReadOnly() || target->writeLevel() > m_state.passwordLevel()))
        return Ack::DataInvalid;
    return Ack::Ok;
}

Ack ParameterAccess::write(quint16 address, quint8 setMask, qint32 value, Permission permission)
{
    const int index = m_state.db().indexOf(address);
    if (index < 0)
        return Ack::AddressInvalid;
    if (setMask == 0)
        return Ack::SetInvalid;
    const Ack ack = checkWriteAt(index, value, permission);
    if (ack != Ack::Ok)
        return ack;
    const SimParameter &p = m_state.db().parameters()[std::size_t(index)];
    switch (p.signal) {
    case LiveSignal::Password: {
        const std::optional<int> level = passwordLevelFor(value);
        if (!level)
            return Ack::PasswordInvalid;
        m_state.setPasswordLevel(*level);
        return Ack::Ok;
    }
    case LiveSignal::PeakCurrent:
        m_state.motor().setPeakCurrentA(value / 10.0);
        return Ack::Ok;
    case LiveSignal::PeakDcVoltage:
        m_state.motor().setPeakDcVoltageV(value);
        return Ack::Ok;
    case LiveSignal::ControlLong: {
        const int high = m_state.db().indexOf(F5::kControlWordHigh);
        const int low = m_state.db().indexOf(F5::kControlWordLow);
        if (high >= 0)
            m_state.store(high, 0xFF, qint32(quint32(value) >> 16));
        if (low >= 0)
            m_state.store(low, 0xFF, value & 0xFFFF);
        return Ack::Ok;
    }
    default:
        break;
    }
    m_state.store(index, setMask, value);
    return Ack::Ok;
}

Ack ParameterAccess::checkDefault(quint16 address, quint8 setMask) const
{
    const int index = m_state.db().indexOf(address);
    if (index < 0)
        return Ack::AddressInvalid;
    if (setMask == 0)
        return Ack::SetInvalid;
    const SimParameter &p = m_state.db().parameters()[std::size_t(index)];
    if (p.readLevel() > m_state.passwordLevel())
        return Ack::AddressOrPasswordInvalid;
    for (int set = 0; set < kSets; ++set) {
        if ((setMask & (1u << set)) && m_state.value(index, set) != p.defaultValue)
            return Ack::DataInvalid;
    }
    return Ack::Ok;
}

Ack ParameterAccess::setDefault(quint16 address, quint8 setMask)
{
    const SimParameter *p = m_state.db().find(address);
    if (!p)
        return Ack::AddressInvalid;
    return write(address, setMask, p->defaultValue);
}

} // namespace DriveDesk::Sim
