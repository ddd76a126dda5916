// drivedesk-cli upload and download: a drive's parameter list to a file and back.
#include "CliRunner.h"

#include "parameters/ParameterDocument.h"
#include "parameters/ParameterList.h"
#include "session/DownloadPlan.h"
#include "session/DownloadReport.h"
#include "session/WriteChangesJob.h"

#include <QFutureWatcher>

#include <unistd.h>

namespace DriveDesk {

bool CliRunner::interrupt()
{
    if (!m_download || m_finished)
        return false;
    if (!m_interrupted) {
        m_interrupted = true;
        m_download->requestStop();
        m_err << '\n' << tr("stopping after the value on its way...") << '\n' << Qt::flush;
    }
    return true;
}

void CliRunner::progressLine(int percent, const QString &text)
{
    if (m_request.quiet || !isatty(STDERR_FILENO))
        return;
    m_err << QStringLiteral("\r\x1b[K");
    if (percent >= 0)
        m_err << QStringLiteral("[%1%] %2").arg(percent, 3).arg(text);
    m_err << Qt::flush;
}

void CliRunner::runUpload()
{
    ScanOptions options;
    options.values = true;
    options.parameterList = true;
    scan(options, [this](const DriveDescription &drive) {
        // A backup with holes the user does not know of is worse than none.
        if (!drive.incompleteReason.isEmpty()) {
            return fail(1, tr("the drive could not be read to the end (%1); no file was written")
                               .arg(drive.incompleteReason));
        }
        const QString &path = m_request.files.constFirst();
        QString error;
        if (!ParameterDocument::save(path, drive, &error))
            return fail(1, error);
        int parameters = 0;
        int values = 0;
        int writeOnly = 0;
        QStringList unread;
        for (const GroupDescription &group : drive.groups) {
            for (const ParameterDescription &parameter : group.parameters) {
                ++parameters;
                if (!ParameterList::isReadByUpload(parameter))
                    ++writeOnly;
                for (const std::optional<qint32> &value : parameter.values)
                    values += value ? 1 : 0;
                if (!parameter.error.isEmpty())
                    unread << QStringLiteral("%1 (%2)").arg(
                        parameterId(group.id, parameter.number()), parameter.error);
            }
        }
        m_out << tr("%1: %n parameter(s)", nullptr, parameters).arg(path) << QStringLiteral(", ")
              << tr("%n value(s)", nullptr, values);
        if (writeOnly)
            m_out << QStringLiteral(", ") << tr("%n write-only with the default", nullptr, writeOnly);
        m_out << '\n';
        if (!unread.isEmpty()) {
            return fail(1, tr("%n parameter(s) could not be read and have no value in the file: %1",
                              nullptr, int(unread.size()))
                               .arg(unread.join(QStringLiteral(", "))));
        }
        done();
    });
}

void CliRunner::runDownload()
{
    ScanOptions options;
    options.values = true;
    scan(options, [this](const DriveDescription &drive) {
        if (!drive.incompleteReason.isEmpty()) {
            return fail(1, tr("the drive could not be read (%1); nothing was written")
                               .arg(drive.incompleteReason));
        }
        DownloadOptions downloadOptions;
        downloadOptions.sets = m_request.setMask;
        downloadOptions.force = m_request.force;
        const DownloadPlan plan = planDownload(m_files.constFirst(), drive, downloadOptions);
        for (const QString &problem : plan.problems)
            m_err << (plan.forced ? tr("warning: %1") : tr("refused: %1")).arg(problem) << '\n';
        if (plan.isRefused())
            return fail(2, tr("nothing was written; --force writes the file all the same"));
        if (m_request.dryRun) {
            m_out << plan.text(drive);
            for (const DownloadSkip &skip : plan.skipped)
                m_out << tr("skipped  %1  %2: %3").arg(skip.id, skip.name, skip.reason) << '\n';
            m_out << tr("dry run: %n value(s) would be written", nullptr, plan.valueCount())
                  << QStringLiteral(", ") << tr("%n unchanged", nullptr, plan.unchanged)
                  << QStringLiteral(", ") << tr("%n skipped", nullptr, int(plan.skipped.size()))
                  << QStringLiteral("; ") << tr("nothing was written") << '\n';
            if (plan.readOnlyDiffering) {
                m_out << tr("%n read-only value(s) of the file differ from the drive's; they are "
                            "never written", nullptr, plan.readOnlyDiffering)
                      << '\n';
            }
            return done();
        }
        writeDownload(plan, drive);
    });
}

void CliRunner::writeDownload(const DownloadPlan &plan, const DriveDescription &drive)
{
    QList<ValueChange> changes;
    for (const DownloadItem &item : plan.items)
        changes << item.change;
    m_download = std::make_shared<WriteChangesJob>(m_request.connection.protocol, changes);
    auto *watcher = new QFutureWatcher<WriteOutcome>(this);
    connect(watcher, &QFutureWatcher<WriteOutcome>::progressValueChanged, this,
            [this, total = int(changes.size())](int written) {
                progressLine(written * 100 / std::max(1, total),
                             tr("writing %1 of %2").arg(written).arg(total));
            });
    connect(watcher, &QFutureWatcher<WriteOutcome>::finished, this, [this, watcher, plan, drive] {
        progressLine(-1, {});
        const QFuture<WriteOutcome> future = watcher->future();
        watcher->deleteLater();
        QList<std::optional<WriteOutcome>> outcomes(plan.items.size());
        QString stopReason;
        for (int i = 0; i < int(outcomes.size()); ++i) {
            if (!future.isResultReadyAt(i))
                continue;
            outcomes[i] = future.resultAt(i);
            if (outcomes[i]->connectionFailed)
                stopReason = outcomes[i]->error;
        }
        if (m_interrupted)
            stopReason = tr("stopped by the user");
        const DownloadReport report = reportDownload(plan, outcomes, stopReason, drive);
        m_download.reset();
        m_out << report.text();
        if (!report.isComplete())
            return fail(1, tr("the download did not write everything; the report says what "
                              "the drive holds"));
        done();
    });
    watcher->setFuture(m_client->run(m_download));
}

} // namespace DriveDesk
