#pragma once

#include "cli/CommandLine.h"

class QCommandLineParser;

namespace DriveDesk {

// The scope command's options into `request`: --csv (needed), --channels, --duration, --rate,
// --offline, and --preset FILE, read here (a bad preset is refused before the drive is
// reached) for the channels and the rate limit the others do not give. Another command given
// one of them is refused. False with *error for what does not make sense.
bool parseScopeOptions(const QCommandLineParser &parser, CliRequest &request, QString *error);

} // namespace DriveDesk
