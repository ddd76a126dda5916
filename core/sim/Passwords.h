#pragma once

#include <QtGlobal>

#include <optional>

namespace DriveDesk::Sim {

// The password levels of properties 1 bits 0-2/3-5 (seed 002 2.6.1); reading the password
// parameter gives -1 - level.
enum PasswordLevel : int {
    CpReadOnly = 0,
    CpReadWrite = 1,
    CpService = 2,
    Application = 3,
    DriveMode = 4,
    Security = 6,
    Supervisor = 7,
};

constexpr int kPowerOnPasswordLevel = Application;

// The level a password (written to ud.01) opens; nothing for a wrong password. The numbers
// are this simulator's own (docs/simulated-drive.md): real ones were not found.
std::optional<int> passwordLevelFor(qint32 password);

} // namespace DriveDesk::Sim
