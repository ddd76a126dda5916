#pragma once

#include <QString>

namespace DriveDesk {

// The acknowledge code every response carries (seed 002, 1.2); 0 is success.
enum class Ack : quint8 {
    Ok = 0,
    NotReady = 1,
    AddressOrPasswordInvalid = 2,
    DataInvalid = 3,
    WriteProtected = 4,
    BccError = 5,
    Busy = 6,
    ServiceNotAvailable = 7,
    PasswordInvalid = 8,
    FramingError = 9,
    TransmissionError = 10,
    SetInvalid = 11,
    LanguageInvalid = 12,
    AddressInvalid = 13,
    OperationNotPossible = 14,
    Free = 15,
};

// The drive's reason in words, as the service description gives it, in the user's language.
QString ackText(Ack ack);

// Whether repeating the same request may succeed (busy, BCC and transmission errors).
bool isTransient(Ack ack);

} // namespace DriveDesk
