// A plant's parameter files downloaded, each to its drive.
#include "PlantLinkRun.h"

namespace DriveDesk {

// The one download of `drivedesk-cli download` and the window (DownloadRun), per drive; a drive
// whose settings already equal its file is not written to at all, not even the values a
// download writes whatever the drive holds.
void PlantLinkRun::download(PlantDrive drive)
{
    auto *run = new DownloadRun(m_client, m_link.protocol, m_file, this);
    m_downloading = run;
    DownloadOptions options;
    options.force = m_job.force;
    run->setOptions(options);
    run->setJournal(m_job.journal);
    connect(run, &DownloadRun::progress, this,
            [this, address = drive.address](int done, int total, const QString &what) {
                emit progress(address, done * 100 / std::max(1, total), what);
            });
    connect(run, &DownloadRun::failed, this, [this, drive](const QString &reason) mutable {
        releaseDownload();
        drive.outcome = m_stopping ? PlantDrive::Outcome::Stopped : PlantDrive::Outcome::Failed;
        drive.reason = reason;
        driveEnded(drive);
    });
    connect(run, &DownloadRun::planned, this,
            [this, drive](const DownloadPlan &plan) { onPlanned(drive, plan); });
    connect(run, &DownloadRun::finished, this,
            [this, drive](const DownloadReport &report) { onDownloaded(drive, report); });
    run->start(readingOf(drive.address));
}

void PlantLinkRun::onPlanned(PlantDrive drive, const DownloadPlan &plan)
{
    const DriveDescription read = m_downloading->drive();
    if (compareDescriptions(m_file, read).isEqual()) {
        drive.outcome = PlantDrive::Outcome::Unchanged;
    } else if (plan.isRefused()) {
        drive.outcome = PlantDrive::Outcome::Failed;
        drive.reason = tr("refused, nothing written: %1").arg(plan.problems.join(QStringLiteral("; ")));
    } else if (m_job.dryRun || m_stopping) {
        drive.outcome = m_stopping ? PlantDrive::Outcome::Stopped : PlantDrive::Outcome::Planned;
        drive.reason = plan.summary();
        drive.details = plan.text(read);
    } else {
        return m_downloading->write();
    }
    releaseDownload();
    driveEnded(drive);
}

void PlantLinkRun::onDownloaded(PlantDrive drive, const DownloadReport &report)
{
    releaseDownload();
    drive.details = report.text();
    if (report.isComplete()) {
        drive.outcome = PlantDrive::Outcome::Written;
    } else {
        drive.outcome = m_stopping ? PlantDrive::Outcome::Stopped : PlantDrive::Outcome::Failed;
        drive.reason = report.stopReason.isEmpty()
                           ? tr("not everything was written; the report says what the drive holds")
                           : report.stopReason;
    }
    driveEnded(drive);
}

void PlantLinkRun::releaseDownload()
{
    if (!m_downloading)
        return;
    m_downloading->disconnect(this);
    m_downloading->deleteLater();
    m_downloading = nullptr;
}

} // namespace DriveDesk
