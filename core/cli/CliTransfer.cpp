// drivedesk-cli upload and download: a drive's parameter list to a file and back.
#include "CliRunner.h"

#include "cli/CliPlant.h"
#include "journal/Journal.h"
#include "parameters/ParameterList.h"
#include "session/DownloadRun.h"
#include "session/EditJournal.h"
#include "session/ScopeRecorder.h"
#include "session/UploadRun.h"

#include <QFileInfo>

#include <unistd.h>

namespace DriveDesk {

bool CliRunner::interrupt()
{
    if (m_plant)
        return m_plant->interrupt();
    if (m_recorder && m_recorder->isRecording() && !m_finished) {
        m_recorder->stop();
        return true;
    }
    if (!m_download || m_finished)
        return false;
    if (m_download->stage() == DownloadRun::Stage::Writing)
        m_err << '\n' << tr("stopping after the value on its way...") << '\n' << Qt::flush;
    m_download->stop();
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

// The window's File > Save Drive to File runs the same UploadRun: the drive read afresh, a
// backup only when the read is whole.
void CliRunner::runUpload()
{
    auto *upload = new UploadRun(m_client.get(), this);
    connect(upload, &UploadRun::progress, this, [this](int value, int maximum, const QString &what) {
        progressLine(value * 100 / std::max(1, maximum), what);
    });
    connect(upload, &UploadRun::finished, this, [this, upload](const UploadResult &result) {
        progressLine(-1, {});
        upload->deleteLater();
        noteScan(result.document, {});
        const QString &path = m_request.files.constFirst();
        if (!result.isComplete()) {
            // A backup with holes the user does not know of is worse than none.
            for (const QString &line : result.details())
                m_err << tr("not read: %1").arg(line) << '\n';
            return fail(1, result.summary());
        }
        QString error;
        if (!saveUpload(path, result, &error))
            return fail(1, error);
        int parameters = 0;
        int values = 0;
        int writeOnly = 0;
        for (const GroupDescription &group : result.document.groups) {
            for (const ParameterDescription &parameter : group.parameters) {
                ++parameters;
                if (!ParameterList::isReadByUpload(parameter))
                    ++writeOnly;
                for (const std::optional<qint32> &value : parameter.values)
                    values += value ? 1 : 0;
            }
        }
        m_out << tr("%1: %n parameter(s)", nullptr, parameters).arg(path) << QStringLiteral(", ")
              << tr("%n value(s)", nullptr, values);
        if (writeOnly)
            m_out << QStringLiteral(", ") << tr("%n write-only with the default", nullptr, writeOnly);
        m_out << '\n';
        done();
    });
    ScanOptions reading;
    reading.metadata = m_request.useCache ? MetadataSource::Cache : MetadataSource::RefreshCache;
    upload->start(reading);
}

// The window's download runs the same DownloadRun: read the drive, plan, write, report.
void CliRunner::runDownload()
{
    DownloadOptions options;
    options.sets = m_request.setMask;
    options.force = m_request.force;
    download(m_files.constFirst(), options);
}

// A journal revert downloads the values before as a selection (CliRevert.cpp).
void CliRunner::download(const DriveDescription &file, const DownloadOptions &options)
{
    m_download = new DownloadRun(m_client.get(), m_request.connection.protocol, file, this);
    m_download->setOptions(options);
    if (m_request.journalWrites && !m_request.dryRun) {
        // Before the drive is read: a journal that cannot be written stops the download
        // before anything is.
        QString error;
        if (!openJournal(&error))
            return fail(1, tr("nothing was written: %1 (--no-journal downloads without it)")
                               .arg(error));
        // A revert names its entries; a download its file.
        const QString job = !options.journalJob.isEmpty() ? options.journalJob
            : tr("download of %1").arg(QFileInfo(m_request.files.value(0)).fileName());
        m_editJournal = std::make_unique<EditJournal>(m_journal.get(), JournalDrive {}, job);
        m_editJournal->setRemedy(tr("--no-journal downloads without it"));
        m_download->setJournal(m_editJournal.get());
    }
    connect(m_download, &DownloadRun::progress, this,
            [this](int done, int total, const QString &what) {
                progressLine(done * 100 / std::max(1, total), what);
            });
    connect(m_download, &DownloadRun::failed, this, [this](const QString &reason) {
        progressLine(-1, {});
        fail(1, reason);
    });
    connect(m_download, &DownloadRun::planned, this, [this](const DownloadPlan &plan) {
        progressLine(-1, {});
        noteScan(m_download->drive(), {});
        for (const QString &problem : plan.problems)
            m_err << (plan.forced ? tr("warning: %1") : tr("refused: %1")).arg(problem) << '\n';
        if (plan.isRefused() && m_request.command == CliRequest::Command::Revert)
            return fail(2, tr("nothing was written"));
        if (plan.isRefused())
            return fail(2, tr("nothing was written; --force writes the file all the same"));
        if (!m_request.dryRun)
            return m_download->write();
        m_out << plan.text(m_download->drive());
        for (const DownloadSkip &skip : plan.skipped)
            m_out << tr("skipped  %1  %2: %3").arg(skip.id, skip.name, skip.reason) << '\n';
        m_out << tr("dry run: %1; nothing was written").arg(plan.summary()) << '\n';
        done();
    });
    connect(m_download, &DownloadRun::finished, this, [this](const DownloadReport &report) {
        progressLine(-1, {});
        m_out << report.text();
        if (!report.isComplete())
            return fail(1, tr("the download did not write everything; the report says what "
                              "the drive holds"));
        done();
    });
    ScanOptions reading;
    reading.metadata = m_request.useCache ? MetadataSource::Cache : MetadataSource::RefreshCache;
    m_download->start(reading);
}

} // namespace DriveDesk
