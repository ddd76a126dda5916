// drivedesk-cli journal: the values written, read from the journal's file.
#include "CliJournal.h"

#include "CliFormatOption.h"

#include "journal/Journal.h"
#include "journal/JournalFormat.h"
#include "link/ConnectionOptions.h"

#include <QCommandLineParser>
#include <QFileInfo>

namespace DriveDesk {

namespace {

// The journal command's own options, each naming what it filters.
const char *const kFilterOptions[] = { "drive", "parameter", "since", "until", "user" };

class CliJournalText
{
    Q_DECLARE_TR_FUNCTIONS(CliJournalText)
};

} // namespace

void addJournalOptions(QCommandLineParser &parser)
{
    parser.addOption(QCommandLineOption(QStringLiteral("journal"), {}, QStringLiteral("path")));
    parser.addOption(QCommandLineOption(QStringLiteral("no-journal")));
    for (const char *name : kFilterOptions)
        parser.addOption(QCommandLineOption(QLatin1String(name), {}, QLatin1String(name)));
}

bool parseJournalOptions(const QCommandLineParser &parser, CliRequest &request, QString *error)
{
    const bool reading = request.command == CliRequest::Command::Journal;
    // plant history filters its revisions by drive and parameter as the journal its entries;
    // journal revert takes --since (its own check refuses the other filters).
    const bool history = request.plant && request.plant->action == PlantRequest::Action::History;
    const bool reverting = request.command == CliRequest::Command::Revert;
    if (!reading) {
        for (const char *name : kFilterOptions) {
            const bool historyFilter = qstrcmp(name, "drive") == 0 || qstrcmp(name, "parameter") == 0;
            if ((history && historyFilter) || (reverting && qstrcmp(name, "since") == 0))
                continue;
            if (parser.isSet(QLatin1String(name))) {
                *error = QStringLiteral("--%1 belongs to journal").arg(QLatin1String(name));
                return false;
            }
        }
    }
    const bool path = parser.isSet(QStringLiteral("journal"));
    request.journalWrites = !parser.isSet(QStringLiteral("no-journal"));
    if (!request.journalWrites && reading) {
        *error = QStringLiteral("--no-journal does not apply to journal, which reads the journal");
        return false;
    }
    if (!request.journalWrites && path) {
        *error = QStringLiteral("--journal and --no-journal exclude each other");
        return false;
    }
    if (path) {
        request.journalPath = parser.value(QStringLiteral("journal"));
        if (request.journalPath.trimmed().isEmpty()) {
            *error = QStringLiteral("--journal takes the path of a journal file");
            return false;
        }
    }
    return true;
}

std::optional<CliRequest> parseJournalCommand(const QCommandLineParser &parser,
                                              const ConnectionOptions &connection,
                                              const QStringList &positional, QString *error)
{
    if (positional.value(1).compare(QLatin1String("revert"), Qt::CaseInsensitive) == 0)
        return parseJournalRevert(parser, connection, positional, error);
    if (!refuseDriveOptions(parser, connection, QStringLiteral("journal"),
                            QStringLiteral("reads the journal's file"), error))
        return std::nullopt;
    if (positional.size() != 1) {
        *error = QStringLiteral("journal takes no arguments but revert: filter with --drive, "
                                "--parameter, --since, --until or --user");
        return std::nullopt;
    }
    CliRequest request;
    request.command = CliRequest::Command::Journal;
    if (!parseFormatOption(parser, QStringLiteral("journal"),
                           { QStringLiteral("table"), QStringLiteral("json"), QStringLiteral("csv") },
                           &request, error))
        return std::nullopt;
    JournalFilter &filter = request.journalFilter;
    const auto option = [&parser](const char *name) { return parser.value(QLatin1String(name)); };
    const auto given = [&parser](const char *name) { return parser.isSet(QLatin1String(name)); };
    // Each filter option's value, checked by JournalFilter; the message names the option.
    using Setter = bool (JournalFilter::*)(const QString &, QString *);
    const auto apply = [&](const char *name, Setter set) {
        QString problem;
        if (!given(name) || (filter.*set)(option(name), &problem))
            return true;
        *error = QStringLiteral("--%1: %2").arg(QLatin1String(name), problem);
        return false;
    };
    if (!apply("drive", &JournalFilter::setDrive)
        || !apply("parameter", &JournalFilter::setParameter)
        || !apply("since", &JournalFilter::setSince) || !apply("until", &JournalFilter::setUntil))
        return std::nullopt;
    if (given("user")) {
        if (option("user").trimmed().isEmpty()) {
            *error = QStringLiteral("--user takes a login name");
            return std::nullopt;
        }
        filter.setUser(option("user").trimmed());
    }
    if (filter.since().isValid() && filter.until().isValid() && filter.until() <= filter.since()) {
        *error = QStringLiteral("--until %1 is not after --since %2")
                     .arg(option("until"), option("since"));
        return std::nullopt;
    }
    std::optional<Language> language;
    if (!connection.language(parser, &language, error))
        return std::nullopt;
    if (language)
        request.connection.language = *language;
    request.quiet = parser.isSet(QStringLiteral("quiet"));
    if (!parseJournalOptions(parser, request, error))
        return std::nullopt;
    return request;
}

int printJournal(const CliRequest &request, QTextStream &out, QTextStream &err, QString *error)
{
    Journal journal(request.journalPath);
    QList<JournalEntry> entries;
    if (request.journalPath.isEmpty() && !QFileInfo::exists(journal.path())) {
        // Nothing has been written on this account yet: an empty journal, not a mistake.
        if (!request.quiet)
            err << CliJournalText::tr("no journal yet at %1: nothing was written")
                       .arg(journal.path())
                << Qt::endl;
    } else {
        if (!journal.open(Journal::Access::Read)) {
            *error = journal.errorString();
            return 2;
        }
        const std::optional<QList<JournalEntry>> found = journal.entries(request.journalFilter);
        if (!found) {
            *error = journal.errorString();
            return 2;
        }
        entries = *found;
    }
    switch (request.format) {
    case CliRequest::Format::Json:
        out << QString::fromUtf8(JournalFormat::json(entries));
        break;
    case CliRequest::Format::Csv:
        out << QString::fromUtf8(JournalFormat::csv(entries));
        break;
    case CliRequest::Format::Table:
        out << JournalFormat::table(entries);
        break;
    }
    out.flush();
    return 0;
}

} // namespace DriveDesk
