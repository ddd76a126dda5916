#pragma once

#include "cli/CommandLine.h"

#include <QList>
#include <QString>
#include <QTextStream>

class QCommandLineParser;

namespace DriveDesk {

struct Plant;
struct PlantDrive;

// A plant's backups as revisions of a git repository (docs/plant.md, "History"), on the
// command line: `plant backup --commit [--message TEXT]`, `plant history`, and
// `plant verify|download --at REV` (the revision's files: core's extractRevision()).

// --commit, --message and --at, added to the command line's parser.
void addPlantHistoryOptions(QCommandLineParser &parser);
// Any of them on a command that is not plant: false and *error naming it.
bool refusePlantHistoryOptions(const QCommandLineParser &parser, QString *error);
// The options into `plant`, each refused where its command does not take it (--commit and
// --message: backup; --at: verify and download; --drive and --parameter: history).
bool parsePlantHistoryOptions(const QCommandLineParser &parser, PlantRequest &plant,
                              QString *error);

// `plant history`: the revisions of the request's directory, newest first, each with its
// changes, filtered and in the request's format. Returns the exit code: 0, or 2 with *error
// for a directory that is no repository of backups or git failing or missing.
int printPlantHistory(const CliRequest &request, QTextStream &out, QString *error);

// After `plant backup --commit`: the files saved, and those of drives `plant` (as the run left
// it) no longer has, committed with the changes since the last commit, which are printed; no
// commit where no setting changed, and that said. False and *error when git fails.
bool commitAndPrintPlantBackup(const PlantRequest &request, const Plant &plant,
                               const QList<PlantDrive> &drives, QTextStream &out, QString *error);

} // namespace DriveDesk
