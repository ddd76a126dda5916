#pragma once

#include <QString>

namespace DriveDesk {

// drivedesk-cli's --help: the commands, the connection options and the exit status.
QString cliUsage();
// One command's part of cliUsage() (`drivedesk-cli scan --help`): its lines under "Commands:",
// empty for a name that is no command.
QString cliCommandUsage(const QString &command);

} // namespace DriveDesk
