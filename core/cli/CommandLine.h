#pragma once

#include "journal/JournalFilter.h"
#include "link/ConnectionSettings.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

class QCommandLineParser;

namespace DriveDesk {

class ConnectionOptions;

// `drivedesk-cli plant`: every drive of a plant file (docs/plant.md), its links from the file.
struct PlantRequest {
    enum class Action : quint8 { Find, Backup, Verify, Download, History };
    Action action = Action::Find;
    QString plantFile;
    QString directory; // backup, verify, history: where the drives' parameter files are
    bool update = false; // find: write the addresses found into the plant file
    bool dryRun = false; // download: show what would be written
    bool force = false;  // download: write although the checks found problems
    // backup --commit [--message TEXT]: the backup committed to the directory's git repository
    bool commit = false;
    QString message;
    QString at;          // verify, download --at REV: the files as they were at a revision
    QString drive;       // history --drive NAME ("cabinet-5")
    QString parameter;   // history --parameter ID
};

// `drivedesk-cli spectrum`: a channel's spectrum from a scope CSV export or recording file.
struct SpectrumRequest {
    QString file;
    QString channel; // its number (1..), id or title; empty: the first
    // The window in ms from the recording's first sample; nothing: its start, its end.
    std::optional<double> fromMs;
    std::optional<double> toMs;
    int peaks = 5;
};

// What `drivedesk-cli` was asked to do, parsed and checked before anything is sent.
struct CliRequest {
    enum class Command : quint8 { Info, Scan, Read, Write, Diff, Upload, Download, Scope, Journal,
                                  Spectrum, Revert };
    enum class Format : quint8 { Table, Json, Csv };

    ConnectionSettings connection;
    Command command = Command::Info;
    Format format = Format::Table;
    bool values = false;      // scan: read the value of every set
    QString parameter;        // read/write: "ru.3", "ru.03", "0x0203"
    QString value;            // write: in display units or a plaintext, raw with --raw
    // diff: the two sides, each a file, "drive" or "defaults" (the other side's defaults);
    // upload, download: the one file
    QStringList files;
    std::optional<int> set;   // read --set N
    quint8 setMask = 0;       // write, download --sets LIST; write's 0: the active set (service 1)
    bool raw = false;
    bool dryRun = false;      // download: show what would be written, write nothing
    bool force = false;       // download: write although the checks found problems
    int timeoutMs = 0;
    bool quiet = false;       // no progress on stderr
    bool useCache = true;     // metadata of a known kind of drive from the metadata cache
    std::optional<qint32> password; // entered (ud.01) before the command
    // scope: the sources for channels 1..4 in order (empty: as the drive has them assigned; an
    // empty entry, from a --preset: that channel as the drive has it), how long to record, an
    // optional rate limit, and the CSV to write
    QStringList channels;
    qint64 durationMs = 10000;
    double rateHz = 0;
    bool offline = false; // the drive's offline records (service 21) instead of a recording
    QString csvFile;
    std::optional<PlantRequest> plant; // set for `plant`: the other command fields are unused
    // The journal of the values written (docs/journal.md), for every command: --journal PATH
    // (empty: Journal::defaultPath()); --no-journal (journalWrites false): the values this
    // command writes are not journaled.
    QString journalPath;
    bool journalWrites = true;
    JournalFilter journalFilter; // journal: which entries to print; revert --since: its time
    QList<qint64> revertEntries; // journal revert ENTRY...: the entries named (else --since)
    SpectrumRequest spectrum;          // `spectrum`: the other command fields are unused
};

// The usage text and the parse. Returns nothing and sets *error (naming the bad argument)
// when the arguments do not make sense; *helpText is set for --help.
std::optional<CliRequest> parseCommandLine(const QStringList &arguments, QString *error,
                                           QString *helpText);

// "10s", "500ms", "1.5s", "2min" or a bare number of seconds -> ms; nothing and *error on
// anything else or a duration outside 1 ms..24 h.
std::optional<qint64> parseDuration(const QString &text, QString *error);

// "0,2-4,7" or "all" -> bit mask of sets 0..7; nothing and *error on anything else.
std::optional<quint8> parseSetList(const QString &text, QString *error);

// A command that reads a file and no drive (journal, spectrum): refuses, naming it, any option
// that reaches a drive or belongs to the drive's commands. `what`: "reads a file".
bool refuseDriveOptions(const QCommandLineParser &parser, const ConnectionOptions &connection,
                        const QString &command, const QString &what, QString *error);

} // namespace DriveDesk
