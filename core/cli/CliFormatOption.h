#pragma once

#include "CommandLine.h"

class QCommandLineParser;

namespace DriveDesk {

// --format, where given: one of `allowed` (of "table", "json" and "csv"), any case, into
// request->format. False, with an error naming the words `command` writes, for any other.
bool parseFormatOption(const QCommandLineParser &parser, const QString &command,
                       const QStringList &allowed, CliRequest *request, QString *error);

} // namespace DriveDesk
