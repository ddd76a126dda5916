#include "CommandLine.h"

#include "cli/CliJournal.h"
#include "cli/CliPlant.h"
#include "cli/CliPlantHistory.h"
#include "cli/CliScopeOptions.h"
#include "cli/CliSpectrum.h"
#include "cli/CommandLineUsage.h"
#include "link/ConnectionOptions.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QRegularExpression>

namespace DriveDesk {

std::optional<quint8> parseSetList(const QString &text, QString *error)
{
    const QString list = text.trimmed().toLower();
    if (list == QLatin1String("all"))
        return quint8(0xFF);
    quint8 mask = 0;
    for (const QString &part : list.split(QLatin1Char(','))) {
        const QStringList bounds = part.trimmed().split(QLatin1Char('-'));
        bool okFirst = false;
        bool okLast = false;
        const int first = bounds.value(0).toInt(&okFirst);
        const int last = bounds.size() == 2 ? bounds[1].toInt(&okLast) : first;
        okLast = bounds.size() == 2 ? okLast : okFirst;
        if (bounds.size() > 2 || !okFirst || !okLast || first < 0 || last > 7 || first > last) {
            *error = QStringLiteral("'%1' is not a set list: use sets 0..7 like 0,2-4 or all")
                         .arg(text);
            return std::nullopt;
        }
        for (int set = first; set <= last; ++set)
            mask |= quint8(1u << set);
    }
    return mask;
}

std::optional<qint64> parseDuration(const QString &text, QString *error)
{
    static const QRegularExpression pattern(
        QStringLiteral("^\\s*([0-9]+(?:[.,][0-9]+)?)\\s*(ms|s|min|m|h)?\\s*$"),
        QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch match = pattern.match(text);
    if (match.hasMatch()) {
        const double number = match.captured(1).replace(QLatin1Char(','), QLatin1Char('.')).toDouble();
        const QString unit = match.captured(2).toLower();
        const double factor = unit == QLatin1String("ms")                              ? 1.0
                              : unit == QLatin1String("min") || unit == QLatin1String("m") ? 60000.0
                              : unit == QLatin1String("h")                               ? 3600000.0
                                                                                         : 1000.0;
        const double ms = number * factor;
        if (ms >= 1 && ms <= 24 * 3600000.0)
            return qint64(ms + 0.5);
    }
    *error = QStringLiteral("'%1' is not a duration: use e.g. 10s, 500ms or 2min (at most 24 h)")
                 .arg(text);
    return std::nullopt;
}

std::optional<CliRequest> parseCommandLine(const QStringList &arguments, QString *error,
                                           QString *helpText)
{
    QCommandLineParser parser;
    parser.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("help"));
    const ConnectionOptions connection;
    const QCommandLineOption timeout(QStringLiteral("timeout"), {}, QStringLiteral("ms"));
    const QCommandLineOption quiet(QStringLiteral("quiet"), QStringLiteral("quiet"));
    const QCommandLineOption format(QStringLiteral("format"), {}, QStringLiteral("format"));
    const QCommandLineOption values(QStringLiteral("values"), QStringLiteral("values"));
    const QCommandLineOption set(QStringLiteral("set"), {}, QStringLiteral("n"));
    const QCommandLineOption sets(QStringLiteral("sets"), {}, QStringLiteral("list"));
    const QCommandLineOption raw(QStringLiteral("raw"), QStringLiteral("raw"));
    connection.addTo(parser);
    const QCommandLineOption noCache(QStringLiteral("no-cache"));
    const QCommandLineOption password(QStringLiteral("password"), {}, QStringLiteral("n"));
    const QCommandLineOption dryRun(QStringLiteral("dry-run"));
    const QCommandLineOption force(QStringLiteral("force"));
    const QCommandLineOption channels(QStringLiteral("channels"), {}, QStringLiteral("list"));
    const QCommandLineOption duration(QStringLiteral("duration"), {}, QStringLiteral("time"));
    const QCommandLineOption rate(QStringLiteral("rate"), {}, QStringLiteral("hz"));
    const QCommandLineOption csv(QStringLiteral("csv"), {}, QStringLiteral("file"));
    const QCommandLineOption offline(QStringLiteral("offline"));
    const QCommandLineOption preset(QStringLiteral("preset"), {}, QStringLiteral("file"));
    const QCommandLineOption version(QStringLiteral("version"));
    const QCommandLineOption update(QStringLiteral("update")); // plant find
    // spectrum
    const QCommandLineOption channel(QStringLiteral("channel"), {}, QStringLiteral("name"));
    const QCommandLineOption from(QStringLiteral("from"), {}, QStringLiteral("ms"));
    const QCommandLineOption to(QStringLiteral("to"), {}, QStringLiteral("ms"));
    const QCommandLineOption peaks(QStringLiteral("peaks"), {}, QStringLiteral("n"));
    parser.addOptions({help, timeout, quiet, format, values, set, sets, raw, noCache, password,
                       dryRun, force, channels, duration, rate, csv, offline, preset, version,
                       update, channel, from, to, peaks});
    addJournalOptions(parser);
    addPlantHistoryOptions(parser);
    *helpText = cliUsage();

    // A negative value ("write uF.07 -5") is not an option: shield such words from the parser.
    QStringList shielded = arguments;
    QStringList negatives;
    static const QRegularExpression negativeNumber(QStringLiteral("^-[0-9.,]"));
    for (qsizetype i = 1; i < shielded.size(); ++i) {
        if (negativeNumber.match(shielded[i]).hasMatch()) {
            negatives << shielded[i];
            shielded[i] = QStringLiteral("\x01%1").arg(negatives.size() - 1);
        }
    }
    if (!parser.parse(shielded)) {
        *error = parser.errorText();
        return std::nullopt;
    }
    if (parser.isSet(help)) {
        // `drivedesk-cli scope --help`: that command's part; anything else the whole text.
        const QString part = cliCommandUsage(parser.positionalArguments().value(0).toLower());
        if (!part.isEmpty())
            *helpText = part;
        error->clear();
        return std::nullopt;
    }
    if (parser.isSet(version)) { // printed as the help is
        error->clear();
        *helpText = QStringLiteral("%1 %2\n").arg(QCoreApplication::applicationName(),
                                                  QCoreApplication::applicationVersion());
        return std::nullopt;
    }
    helpText->clear();
    // A plant's links come from its file, not from --connect (core/cli/CliPlant.cpp).
    const QString first = parser.positionalArguments().value(0).toLower();
    if (first == QLatin1String("plant")) {
        auto plant = parsePlantCommand(parser, connection, parser.positionalArguments(), error);
        if (plant && !parseJournalOptions(parser, *plant, error))
            return std::nullopt;
        return plant;
    }
    if (!refusePlantHistoryOptions(parser, error))
        return std::nullopt;
    // The journal is read from its file, not from a drive (core/cli/CliJournal.cpp).
    if (first == QLatin1String("journal"))
        return parseJournalCommand(parser, connection, parser.positionalArguments(), error);
    // A spectrum reads a file, no drive (core/cli/CliSpectrum.cpp).
    if (first == QLatin1String("spectrum"))
        return parseSpectrumCommand(parser, connection, parser.positionalArguments(), error);
    for (const QCommandLineOption &option : {channel, from, to, peaks}) {
        if (parser.isSet(option)) {
            *error = QStringLiteral("--%1 belongs to spectrum").arg(option.names().constFirst());
            return std::nullopt;
        }
    }
    if (parser.isSet(update)) {
        *error = QStringLiteral("--update belongs to plant find");
        return std::nullopt;
    }

    CliRequest request;
    // Two files are compared without a drive: the connection is needed only when given, or
    // when a side is the drive.
    const QStringList words = parser.positionalArguments();
    const bool diff = words.value(0).compare(QLatin1String("diff"), Qt::CaseInsensitive) == 0;
    const bool diffWithDrive = words.mid(1).contains(QStringLiteral("drive"), Qt::CaseInsensitive);
    if (diff && diffWithDrive && !parser.isSet(QStringLiteral("connect"))) {
        *error = QStringLiteral("diff with the drive needs --connect");
        return std::nullopt;
    }
    if ((!diff || diffWithDrive || parser.isSet(QStringLiteral("connect")))
        && !connection.settings(parser, &request.connection, error))
        return std::nullopt;
    int setNumber = -1;
    if (!ConnectionOptions::integer(parser, timeout, 1, 600000, &request.timeoutMs, error)
        || !ConnectionOptions::integer(parser, set, 0, 7, &setNumber, error))
        return std::nullopt;
    if (setNumber >= 0)
        request.set = setNumber;
    if (parser.isSet(password)) {
        // ud.01's range: the drive refuses anything else before it looks at the password.
        int number = 0;
        if (!ConnectionOptions::integer(parser, password, -8, 9999, &number, error))
            return std::nullopt;
        request.password = number;
    }
    if (parser.isSet(format)) {
        const QString f = parser.value(format).toLower();
        if (f != QLatin1String("json") && f != QLatin1String("table")
            && f != QLatin1String("csv")) {
            *error = QStringLiteral("unknown format '%1': use json, table or csv").arg(f);
            return std::nullopt;
        }
        request.format = f == QLatin1String("json")  ? CliRequest::Format::Json
                         : f == QLatin1String("csv") ? CliRequest::Format::Csv
                                                     : CliRequest::Format::Table;
    }
    if (parser.isSet(sets)) {
        const auto mask = parseSetList(parser.value(sets), error);
        if (!mask)
            return std::nullopt;
        request.setMask = *mask;
    }
    request.values = parser.isSet(values);
    request.raw = parser.isSet(raw);
    request.dryRun = parser.isSet(dryRun);
    request.force = parser.isSet(force);
    request.quiet = parser.isSet(quiet);
    request.useCache = !parser.isSet(noCache);

    QStringList positional = parser.positionalArguments();
    for (QString &word : positional) {
        if (word.startsWith(QStringLiteral("\x01")))
            word = negatives.value(word.mid(1).toInt());
    }
    const QString command = positional.value(0).toLower();
    const qsizetype expected = command == QLatin1String("read")    ? 2
                               : command == QLatin1String("write") ? 3
                               : command == QLatin1String("diff")  ? 3
                               : command == QLatin1String("upload") || command == QLatin1String("download")
                                   ? 2
                                   : 1;
    if (command == QLatin1String("info")) {
        request.command = CliRequest::Command::Info;
    } else if (command == QLatin1String("scan")) {
        request.command = CliRequest::Command::Scan;
    } else if (command == QLatin1String("read")) {
        request.command = CliRequest::Command::Read;
    } else if (command == QLatin1String("write")) {
        request.command = CliRequest::Command::Write;
    } else if (command == QLatin1String("diff")) {
        request.command = CliRequest::Command::Diff;
    } else if (command == QLatin1String("upload")) {
        request.command = CliRequest::Command::Upload;
    } else if (command == QLatin1String("download")) {
        request.command = CliRequest::Command::Download;
    } else if (command == QLatin1String("scope")) {
        request.command = CliRequest::Command::Scope;
    } else {
        const QString commands
            = QStringLiteral("info, scan, read, write, upload, download, diff, scope, spectrum, "
                             "plant or journal");
        *error = command.isEmpty()
            ? QStringLiteral("no command: use %1").arg(commands)
            : QStringLiteral("unknown command '%1': use %2").arg(positional.value(0), commands);
        return std::nullopt;
    }
    if (positional.size() != expected) {
        *error = command == QLatin1String("read")
                     ? QStringLiteral("read takes one parameter, e.g. read ru.03")
                 : command == QLatin1String("write")
                     ? QStringLiteral("write takes a parameter and a value, e.g. write uF.07 70.0")
                 : command == QLatin1String("diff")
                     ? QStringLiteral("diff takes two sides, e.g. diff a.json b.json or diff drive "
                                      "a.json")
                 : command == QLatin1String("upload") || command == QLatin1String("download")
                     ? QStringLiteral("%1 takes a parameter file, e.g. %1 drive.json").arg(command)
                     : QStringLiteral("%1 takes no arguments").arg(command);
        return std::nullopt;
    }
    request.parameter = positional.value(1);
    request.value = positional.value(2);
    if (request.command == CliRequest::Command::Diff) {
        request.parameter.clear();
        request.value.clear();
        request.files = { positional.value(1), positional.value(2) };
        for (QString &side : request.files) {
            if (side.compare(QLatin1String("drive"), Qt::CaseInsensitive) == 0)
                side = QStringLiteral("drive");
            else if (side.compare(QLatin1String("defaults"), Qt::CaseInsensitive) == 0)
                side = QStringLiteral("defaults");
        }
        if (request.files[0] == request.files[1]
            && (request.files[0] == QLatin1String("drive")
                || request.files[0] == QLatin1String("defaults"))) {
            *error = QStringLiteral("diff compares two different sides");
            return std::nullopt;
        }
    }
    if (request.command == CliRequest::Command::Upload
        || request.command == CliRequest::Command::Download) {
        request.files = { positional.value(1) };
        request.parameter.clear();
    }
    const bool download = request.command == CliRequest::Command::Download;
    if (!download && (request.dryRun || request.force)) {
        *error = QStringLiteral("--dry-run and --force belong to download");
        return std::nullopt;
    }
    if (download && !parser.isSet(sets))
        request.setMask = 0xFF;
    if (request.command != CliRequest::Command::Write && request.raw) {
        *error = QStringLiteral("--raw belongs to write");
        return std::nullopt;
    }
    if (request.command != CliRequest::Command::Write && !download && parser.isSet(sets)) {
        *error = QStringLiteral("--sets belongs to write and download");
        return std::nullopt;
    }
    if (request.command != CliRequest::Command::Scan
        && request.format == CliRequest::Format::Csv) {
        *error = QStringLiteral("--format csv belongs to scan");
        return std::nullopt;
    }
    if (!parseScopeOptions(parser, request, error))
        return std::nullopt;
    if (request.command != CliRequest::Command::Read && request.set) {
        *error = QStringLiteral("--set belongs to read (write takes --sets)");
        return std::nullopt;
    }
    if (!parseJournalOptions(parser, request, error))
        return std::nullopt;
    return request;
}

bool refuseDriveOptions(const QCommandLineParser &parser, const ConnectionOptions &connection,
                        const QString &command, const QString &what, QString *error)
{
    if (connection.hasTarget(parser) || connection.hasTargetDetails(parser)) {
        *error = QStringLiteral("%1 %2: --connect, --protocol, --address, --baud and "
                                "--hsp5-extensions do not apply")
                     .arg(command, what);
        return false;
    }
    for (const char *name :
         { "values", "set", "sets", "raw", "password", "channels", "duration", "rate", "csv",
           "offline", "preset", "dry-run", "force", "update", "no-cache", "timeout" }) {
        if (parser.isSet(QLatin1String(name))) {
            *error = QStringLiteral("--%1 does not belong to %2").arg(QLatin1String(name), command);
            return false;
        }
    }
    return true;
}

} // namespace DriveDesk
