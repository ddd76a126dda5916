#pragma once

#include "cli/CommandLine.h"

class QCommandLineParser;
class QTextStream;

namespace DriveDesk {

class ConnectionOptions;

// `spectrum FILE [--channel NAME] [--from MS] [--to MS] [--peaks N] [--format json|table]`
// parsed from a parser that has read the arguments; nothing and *error for arguments that do
// not make sense. It reads a file, no drive: --connect and the options that go with it are
// refused, and so are the other commands' options.
std::optional<CliRequest> parseSpectrumCommand(const QCommandLineParser &parser,
                                               const ConnectionOptions &connection,
                                               const QStringList &positional, QString *error);

// Runs `drivedesk-cli spectrum`: reads a scope CSV export or a recording file (.ddscope, told
// apart by its first bytes), computes the chosen channel's amplitude spectrum over the window
// (computeScopeSpectrum()) and prints its highest peaks, frequency in Hz and amplitude in the
// channel's unit, as a table or JSON. Returns the exit code: 0 done, 2 bad input (a file that
// cannot be read, a channel it does not hold, a window outside the recording or with too few
// samples), each said on `err`.
int runSpectrumCommand(const CliRequest &request, QTextStream &out, QTextStream &err);

} // namespace DriveDesk
