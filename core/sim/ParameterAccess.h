#pragma once

#include "DriveState.h"
#include "protocol/Acknowledge.h"

#include <optional>

namespace DriveDesk::Sim {

struct ValueResult
{
    Ack ack = Ack::Ok;
    qint32 value = 0; // valid only with Ack::Ok
};

// Whether an access goes through the password levels (parameter services) or not (the
// process data channels, which are set up by parameters that are themselves protected).
enum class Permission : quint8 { PasswordLevel, ProcessData };

// Reads and writes parameter values the way the drive's value services do: set masks, password
// levels, read-only, limits, and the parameters with side effects (password, channel
// definitions, peak values, control word long).
//   ack 13 unknown address, 11 set mask 0, 2 above the password level in force, 4 read-only,
//   3 outside the limits / sets that differ / invalid channel address, 8 wrong password.
class ParameterAccess
{
public:
    explicit ParameterAccess(DriveState &state)
        : m_state(state)
    { }

    ValueResult read(quint16 address, quint8 setMask) const;
    Ack write(quint16 address, quint8 setMask, qint32 value,
              Permission permission = Permission::PasswordLevel);
    // Services 32/33: ack 3 when a selected set does not hold the default.
    Ack checkDefault(quint16 address, quint8 setMask) const;
    Ack setDefault(quint16 address, quint8 setMask);

    // Whether write() would accept the value, without writing it (process data checks every
    // channel before it writes any).
    Ack checkWrite(quint16 address, qint32 value, Permission permission) const;

    // Standard set addressing (services 1, 33, 50, 53): 0 the active set, 1 the set Fr.09
    // points at; nothing (ack 11) otherwise.
    std::optional<quint8> standardSetMask(quint8 set) const;

private:
    Ack checkWriteAt(int index, qint32 value, Permission permission) const;
    Ack validateChannel(quint16 address, qint32 value) const;

    DriveState &m_state;
};

} // namespace DriveDesk::Sim
