#pragma once

#include <QString>

#include <optional>

namespace DriveDesk {

// The password levels of properties 1 (bits 0-2 read, 3-5 write) and of group properties
// (bits 0-2), seed 002 2.6.1 and 2.12.1.
enum class PasswordLevel : quint8 {
    CpReadOnly = 0,
    CpReadWrite = 1,
    CpService = 2,
    Application = 3,
    DriveMode = 4,
    Unused = 5,
    Security = 6,
    Supervisor = 7,
};

QString passwordLevelName(PasswordLevel level);

// The password parameter ud.01: it reads the level in force, a password written to it changes
// the level.
inline constexpr quint16 kPasswordParameterAddress = 0x0801;

// What the password parameter reads while the level is in force: -1 (CP read only) .. -8.
qint32 passwordReadValue(PasswordLevel level);
std::optional<PasswordLevel> passwordLevelFromReadValue(qint32 value);

} // namespace DriveDesk
