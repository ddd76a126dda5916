#pragma once

#include "link/ConnectionSettings.h"
#include "protocol/Telegram.h"

namespace DriveDesk {

// The telegrams that read, write and reset a parameter's value, built in one place for the
// client's conveniences and for every job.
namespace ValueRequests {

Telegram read(quint16 address, quint8 setMask);                 // service 0
Telegram write(quint16 address, qint32 value, quint8 setMask);  // service 0
// Service 1, "standard set": set 0 is the active set. DIN66019 carries only its legacy
// telegrams (service -1).
Telegram readStandard(Protocol protocol, quint16 address, quint8 set = 0);
Telegram writeStandard(Protocol protocol, quint16 address, qint32 value, quint8 set = 0);
Telegram resetToDefault(quint16 address, quint8 setMask);       // service 32 write
// The cheap request any drive answers, even with a refusal: service 0 read of set 1
// (DIN66019: its legacy read). The drive search and the baud rate search ask it.
Telegram presence(Protocol protocol, quint16 address = 0x0000);

} // namespace ValueRequests

} // namespace DriveDesk
