#include "Passwords.h"

namespace DriveDesk::Sim {

namespace {

struct PasswordEntry
{
    qint32 password;
    int level;
};

// 100..500 are the commonly quoted, unverified F5 numbers; 6060 and 7070 are made up.
constexpr PasswordEntry kPasswords[] = {
    { 100, CpReadOnly }, { 200, CpReadWrite }, { 330, CpService },   { 440, Application },
    { 500, DriveMode },  { 6060, Security },   { 7070, Supervisor },
};

} // namespace

std::optional<int> passwordLevelFor(qint32 password)
{
    for (const PasswordEntry &entry : kPasswords) {
        if (entry.password == password)
            return entry.level;
    }
    return std::nullopt;
}

} // namespace DriveDesk::Sim
