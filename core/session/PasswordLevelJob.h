#pragma once

#include "client/RequestJob.h"
#include "parameters/PasswordLevel.h"
#include "protocol/Codec.h"

#include <QString>

#include <optional>

namespace DriveDesk {

// What the drive said of its password level.
struct PasswordLevelOutcome
{
    bool passwordAccepted = false;   // a password was written and the drive took it
    std::optional<qint32> readValue; // what ud.01 read afterwards
    // The level in force, when the value read names one (the drive reads -1 - level).
    std::optional<PasswordLevel> level;
    QString error; // the refusal of the password, or why ud.01 could not be read, in words
};

// Reads the level in force from the password parameter ud.01 (service 1, set 0), after writing a
// password to it if one is given: the window's password dialog and the command line's
// --password both. A refused password is not followed by a read.
class PasswordLevelJob : public RequestJob<PasswordLevelOutcome>
{
public:
    PasswordLevelJob(Protocol protocol, std::optional<qint32> password = std::nullopt);

private:
    void start() override;
    void readLevel();
    void finish();

    const Protocol m_protocol;
    const std::optional<qint32> m_password;
    PasswordLevelOutcome m_outcome;
};

} // namespace DriveDesk
