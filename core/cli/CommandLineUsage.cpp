// The usage text of drivedesk-cli, the one source of --help, each command's --help, the man
// page's check (tst_manpages) and the completion's.
#include "CommandLineUsage.h"

#include <QStringList>

namespace DriveDesk {

QString cliUsage()
{
    return QStringLiteral(
        "Usage: drivedesk-cli --connect TARGET [options] COMMAND [arguments]\n"
        "\n"
        "Talks to a KEB drive over HSP5, DIN66019II or DIN66019.\n"
        "\n"
        "Connection:\n"
        "  --connect TARGET     tcp:HOST:PORT, serial:DEVICE or sim (the simulated drive)\n"
        "  --protocol NAME      hsp5 (default), din66019ii or din66019\n"
        "  --address N          drive address on a DIN66019(II) bus, 0..239 (default 1)\n"
        "  --baud N|auto        baud rate; auto (the default on a serial line) tries\n"
        "                       38400, 19200, 9600, 57600, 115200 (HSP5 also 55500, 100000,\n"
        "                       125000, 250000) and takes the one the drive answers at;\n"
        "                       elsewhere 38400\n"
        "  --language en|de     language of the drive's texts and of messages (default en)\n"
        "  --hsp5-extensions    the drive has DriveDesk's HSP5 services 13, 14, 19-21 and\n"
        "                       51-53 (off: only the services of the HSP5 specification)\n"
        "  --timeout MS         answer timeout per request (default: from the baud rate)\n"
        "  --no-cache           read the drive's metadata, not the cached metadata of its kind\n"
        "  --password N         enter a password (ud.01) before the command: opens the\n"
        "                       password level it belongs to\n"
        "  --journal PATH       the journal of the values written (default\n"
        "                       ~/.local/share/DriveDesk/journal.sqlite)\n"
        "  --no-journal         do not journal the values this command writes\n"
        "  --quiet              no progress on standard error\n"
        "  --version            print the version and exit\n"
        "\n"
        "Commands:\n"
        "  info                         identification, groups and parameter counts\n"
        "  scan [--format json|table|csv] [--values]\n"
        "                               every parameter with its metadata (and values);\n"
        "                               csv: id, name, unit and the value of each set\n"
        "  read PARAM [--set N]         one value; PARAM is ru.3, ru.03 or 0x0203\n"
        "  write PARAM VALUE [--sets LIST] [--raw]\n"
        "                               VALUE in display units (12.50) or a plaintext,\n"
        "                               raw with --raw; LIST like 0,2-4 or all\n"
        "  upload FILE                  back the drive up to a parameter file: every\n"
        "                               parameter a parameter list holds, with its values\n"
        "  download FILE [--dry-run] [--force] [--sets LIST]\n"
        "                               write the file's values that differ to the drive,\n"
        "                               each read back; refused for a file of another kind\n"
        "                               of drive, with parameters missing or values outside\n"
        "                               the drive's limits unless --force; --dry-run shows\n"
        "                               what would be written. Ctrl+C stops after the value\n"
        "                               on its way and reports what was written\n"
        "  diff A B [--format json|table]\n"
        "                               every value that differs between A and B, each a\n"
        "                               parameter file, drive (needs --connect) or defaults\n"
        "                               (the other side's defaults). Exit 0 equal,\n"
        "                               1 different, 2 a file that cannot be read\n"
        "  scope --csv FILE [--channels ru.3,ru.9,...] [--duration 10s] [--rate HZ]\n"
        "                               record the drive's scope data (service 18) and\n"
        "                               write it as CSV: time in ms, then one column per\n"
        "                               channel in display units. --channels puts up to\n"
        "                               four parameters on channels 1..4 (an F5's Sy.16..\n"
        "                               Sy.23; channels 3 and 4 carry 16 bits; op.11@2\n"
        "                               reads set 2) and turns the others off; without\n"
        "                               it the channels stay as the drive has them.\n"
        "                               --duration: 10s, 500ms, 2min; --rate limits the\n"
        "                               polls a second. Ctrl+C stops early and writes\n"
        "                               what was recorded\n"
        "  scope --csv FILE --preset PRESET [--duration 10s]\n"
        "                               the channels and the rate limit of a scope\n"
        "                               preset saved in the window (a .json file);\n"
        "                               --channels and --rate given override it\n"
        "  scope --offline --csv FILE   the drive's offline records (service 21,\n"
        "                               DIN66019II) as CSV, one a millisecond assumed\n"
        "  spectrum FILE [--channel NAME] [--from MS] [--to MS] [--peaks N]\n"
        "                [--format json|table]\n"
        "                               the highest peaks of a channel's amplitude\n"
        "                               spectrum, frequency in Hz and amplitude in the\n"
        "                               channel's unit; FILE is a scope CSV export or a\n"
        "                               recording file (.ddscope); no --connect.\n"
        "                               --channel: its id (ru.3), title or number\n"
        "                               (default: the first); --from, --to: the window in\n"
        "                               ms from the recording's start (default: all of\n"
        "                               it); --peaks: how many (default 5)\n"
        "\n"
        "A machine of many drives (no --connect: the links come from the plant file,\n"
        "docs/plant.md; every link at once, the drives of one bus one after another):\n"
        "  plant find PLANT [--update]  every drive on every link, with its address and\n"
        "                               identification; --update writes the addresses\n"
        "                               found into the plant file\n"
        "  plant backup PLANT DIR [--commit [--message TEXT]]\n"
        "                               one parameter file a drive, DIR/LINK-ADDRESS.json\n"
        "                               (DIR/LINK.json on HSP5), saved only when complete;\n"
        "                               --commit makes DIR a git repository and commits the\n"
        "                               backup, its message the settings changed since the\n"
        "                               last commit (none changed: no commit)\n"
        "  plant verify PLANT DIR [--format json|table] [--at REV]\n"
        "                               each drive against its file, settings only; exit 0\n"
        "                               all equal, 1 a difference or a drive not checked;\n"
        "                               --at: the files as they were at a revision\n"
        "  plant download PLANT DIR [--dry-run] [--force] [--at REV]\n"
        "                               the download for every drive; nothing is written\n"
        "                               to a drive whose settings equal its file. REV: a\n"
        "                               commit id, a tag or a day like 2026-11-24 (the\n"
        "                               last commit on or before it)\n"
        "  plant history PLANT DIR [--drive NAME] [--parameter ID] [--format table|json]\n"
        "                               the revisions of DIR, newest first: id, time,\n"
        "                               author and the settings each changed, per drive\n"
        "\n"
        "The values DriveDesk wrote (no --connect but for revert: read from the journal):\n"
        "  journal [--drive SERIAL|LINK[@ADDRESS]] [--parameter ID] [--since TIME]\n"
        "          [--until TIME] [--user NAME] [--format table|json|csv]\n"
        "                               each value written, oldest first: time, user,\n"
        "                               drive, parameter, set, the value before, written\n"
        "                               and read back, the outcome. TIME is local, like\n"
        "                               2026-11-24 or 2026-11-24T10:42; --until takes\n"
        "                               the whole day or minute it names\n"
        "  journal revert ENTRY...|--since TIME [--dry-run]\n"
        "                               with --connect: the entries' values before, written\n"
        "                               back through the download (its checks, read-back\n"
        "                               and report); ENTRY is 12 or 12..15; where several\n"
        "                               touch one value, the oldest one's value before.\n"
        "                               Refused for another drive's entries and passwords\n"
        "\n"
        "Exit status:\n"
        "  0  done\n"
        "  1  the drive refused, or the work was not completed\n"
        "  2  bad input: nothing was sent\n"
        "  3  no connection, or the drive stopped answering on the way: 4 requests in a\n"
        "     row without a byte from the drive after every attempt (a few seconds; the\n"
        "     message says how far the command got)\n");
}

// One command's part of cliUsage(): its lines under "Commands:" (and the plant commands), each
// starting at two spaces with the command's name, with the lines indented below it.
QString cliCommandUsage(const QString &command)
{
    if (command.isEmpty() || command.startsWith(QLatin1Char('-')))
        return {};
    const QStringList lines = cliUsage().split(QLatin1Char('\n'));
    const QString start = QStringLiteral("  ") + command;
    QStringList block;
    bool inBlock = false;
    for (const QString &line : lines) {
        const bool starts = line.startsWith(start)
                            && (line.size() == start.size() || line.at(start.size()) == QLatin1Char(' '));
        if (starts)
            inBlock = true;
        else if (!line.startsWith(QStringLiteral("   ")))
            inBlock = false;
        if (inBlock)
            block << line;
    }
    if (block.isEmpty())
        return {};
    return QStringLiteral("Usage: drivedesk-cli %1 ...\n\n%2\n\nConnection options and exit "
                          "status: drivedesk-cli --help\n")
        .arg(command, block.join(QLatin1Char('\n')));
}

} // namespace DriveDesk
