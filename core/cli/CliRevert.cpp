// drivedesk-cli journal revert: journal entries' values before, written back through the
// download (its checks, read-back and report), the rule of core's JournalRevert.
#include "CliJournal.h"
#include "CliRunner.h"

#include "journal/Journal.h"
#include "journal/JournalRevert.h"
#include "link/ConnectionOptions.h"
#include "session/DownloadRun.h"
#include "session/EditJournal.h"

#include <QCommandLineParser>
#include <QFileInfo>

namespace DriveDesk {

std::optional<CliRequest> parseJournalRevert(const QCommandLineParser &parser,
                                             const ConnectionOptions &connection,
                                             const QStringList &positional, QString *error)
{
    for (const char *name : { "drive", "parameter", "until", "user", "format", "values", "set",
                              "sets", "raw", "channels", "duration", "rate", "csv", "offline",
                              "force", "update", "no-journal" }) {
        if (parser.isSet(QLatin1String(name))) {
            *error = QStringLiteral("--%1 does not belong to journal revert").arg(QLatin1String(name));
            return std::nullopt;
        }
    }
    CliRequest request;
    request.command = CliRequest::Command::Revert;
    if (!connection.hasTarget(parser)) {
        *error = QStringLiteral("journal revert writes to a drive: it needs --connect");
        return std::nullopt;
    }
    if (!connection.settings(parser, &request.connection, error))
        return std::nullopt;
    const QStringList ids = positional.mid(2);
    const bool since = parser.isSet(QStringLiteral("since"));
    if (ids.isEmpty() == !since) {
        *error = QStringLiteral("journal revert takes entry numbers (12 15 or 12..15) or --since "
                                "TIME, one of the two");
        return std::nullopt;
    }
    if (since) {
        QString problem;
        if (!request.journalFilter.setSince(parser.value(QStringLiteral("since")), &problem)) {
            *error = QStringLiteral("--since: %1").arg(problem);
            return std::nullopt;
        }
    } else {
        const std::optional<QList<qint64>> entries = JournalRevert::parseIds(ids, error);
        if (!entries)
            return std::nullopt;
        request.revertEntries = *entries;
    }
    const QCommandLineOption timeout(QStringLiteral("timeout"), {}, QStringLiteral("ms"));
    if (!ConnectionOptions::integer(parser, timeout, 1, 600000, &request.timeoutMs, error))
        return std::nullopt;
    if (parser.isSet(QStringLiteral("password"))) {
        const QCommandLineOption password(QStringLiteral("password"), {}, QStringLiteral("n"));
        int number = 0;
        if (!ConnectionOptions::integer(parser, password, -8, 9999, &number, error))
            return std::nullopt;
        request.password = number;
    }
    request.setMask = 0xFF;
    request.dryRun = parser.isSet(QStringLiteral("dry-run"));
    request.quiet = parser.isSet(QStringLiteral("quiet"));
    request.useCache = !parser.isSet(QStringLiteral("no-cache"));
    if (!parseJournalOptions(parser, request, error))
        return std::nullopt;
    return request;
}

void CliRunner::runRevert()
{
    // The entries first: a journal that cannot be read writes nothing.
    Journal journal(m_request.journalPath);
    if (m_request.journalPath.isEmpty() && !QFileInfo::exists(journal.path()))
        return fail(2, tr("no journal yet at %1: there is nothing to revert").arg(journal.path()));
    if (!journal.open(Journal::Access::Read))
        return fail(2, journal.errorString());
    JournalFilter filter = m_request.journalFilter;
    if (!m_request.revertEntries.isEmpty())
        filter.setEntries(m_request.revertEntries);
    const std::optional<QList<JournalEntry>> found = journal.entries(filter);
    if (!found)
        return fail(2, journal.errorString());
    journal.close();
    // The drive as the journal names it, to tell its entries from another drive's.
    ScanOptions reading;
    reading.values = true;
    scan(reading, [this, entries = *found](const DriveDescription &drive) {
        const JournalDrive connected = EditJournal::driveOf(m_request.connection, drive);
        const JournalRevertPlan plan = m_request.revertEntries.isEmpty()
            ? JournalRevert::since(entries, connected, drive)
            : JournalRevert::ofEntries(m_request.revertEntries, entries, connected, drive);
        for (const QString &left : plan.leftOut)
            m_err << tr("left out: %1").arg(left) << '\n';
        for (const QString &refusal : plan.refusals)
            m_err << tr("refused: %1").arg(refusal) << '\n';
        if (!plan.refusals.isEmpty())
            return fail(2, tr("nothing was written"));
        if (plan.values.isEmpty())
            return fail(2, tr("no entry of this drive to revert; nothing was written"));
        DownloadOptions options;
        options.selection = true;
        options.journalJob = plan.job();
        if (!m_request.quiet)
            m_err << tr("%1: the values before, back to the drive").arg(plan.job()) << '\n';
        download(plan.selection(drive), options);
    });
}

} // namespace DriveDesk
