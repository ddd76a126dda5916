#pragma once

#include "cli/CommandLine.h"

#include <QTextStream>

class QCommandLineParser;

namespace DriveDesk {

class ConnectionOptions;

// The options of the journal (docs/journal.md), added to the command line's parser:
// --journal PATH and --no-journal for every command, the journal command's filters.
void addJournalOptions(QCommandLineParser &parser);
// --journal and --no-journal into the request, and the filters refused where the command is
// not `journal`. False and *error naming the option otherwise.
bool parseJournalOptions(const QCommandLineParser &parser, CliRequest &request, QString *error);
// `journal [--drive D] [--parameter ID] [--since T] [--until T] [--user NAME] [--format F]`:
// read from the journal's file, no --connect; nothing and *error for arguments that do not
// make sense.
std::optional<CliRequest> parseJournalCommand(const QCommandLineParser &parser,
                                              const ConnectionOptions &connection,
                                              const QStringList &positional, QString *error);

// `journal revert ENTRY... | --since TIME [--dry-run]`, with --connect: the entries' values
// before written back to the drive through the download (CliRevert.cpp).
std::optional<CliRequest> parseJournalRevert(const QCommandLineParser &parser,
                                             const ConnectionOptions &connection,
                                             const QStringList &positional, QString *error);

// Prints the entries of the request's journal that its filter lets through, in its format.
// Returns the exit code: 0, or 2 with *error for a journal that cannot be read (missing where
// --journal named it, damaged, not a journal). The default journal not made yet holds nothing.
int printJournal(const CliRequest &request, QTextStream &out, QTextStream &err, QString *error);

} // namespace DriveDesk
