// A plant's parameter files downloaded, each to its drive.
#include "PlantRun.h"

#include "PlantLinkState.h"

namespace DriveDesk {

// The one download of `drivedesk-cli download` and the window (DownloadRun), per drive; a drive
// whose settings already equal its file is not written to at all, not even the values a
// download writes whatever the drive holds.
void PlantRun::download(LinkState &state, DriveClient *client, PlantDrive drive)
{
    auto *run = new DownloadRun(client, m_plant.links.at(state.index).protocol, state.file, this);
    state.downloading = run;
    DownloadOptions options;
    options.force = m_force;
    run->setOptions(options);
    run->setJournal(m_journal);
    const auto end = [this, &state, run](const PlantDrive &done) {
        run->disconnect(this);
        run->deleteLater();
        dropClient(state);
        finishDrive(state, done);
        nextDrive(state);
    };
    connect(run, &DownloadRun::progress, this,
            [this, drive](int done, int total, const QString &what) {
                emit progress(drive.link, drive.address, done * 100 / std::max(1, total), what);
            });
    connect(run, &DownloadRun::failed, this, [this, drive, end](const QString &reason) mutable {
        drive.outcome = m_stopping ? PlantDrive::Outcome::Stopped : PlantDrive::Outcome::Failed;
        drive.reason = reason;
        end(drive);
    });
    connect(run, &DownloadRun::planned, this,
            [this, &state, run, drive, end](const DownloadPlan &plan) mutable {
                if (compareDescriptions(state.file, run->drive()).isEqual()) {
                    drive.outcome = PlantDrive::Outcome::Unchanged;
                    return end(drive);
                }
                if (plan.isRefused()) {
                    drive.outcome = PlantDrive::Outcome::Failed;
                    drive.reason = tr("refused, nothing written: %1")
                                       .arg(plan.problems.join(QStringLiteral("; ")));
                    return end(drive);
                }
                if (m_dryRun || m_stopping) {
                    drive.outcome = m_stopping ? PlantDrive::Outcome::Stopped
                                               : PlantDrive::Outcome::Planned;
                    drive.reason = plan.summary();
                    drive.details = plan.text(run->drive());
                    return end(drive);
                }
                run->write();
            });
    connect(run, &DownloadRun::finished, this,
            [this, drive, end](const DownloadReport &report) mutable {
                drive.details = report.text();
                if (report.isComplete()) {
                    drive.outcome = PlantDrive::Outcome::Written;
                } else {
                    drive.outcome = m_stopping ? PlantDrive::Outcome::Stopped
                                               : PlantDrive::Outcome::Failed;
                    drive.reason = report.stopReason.isEmpty()
                                       ? tr("not everything was written; the report says what "
                                            "the drive holds")
                                       : report.stopReason;
                }
                end(drive);
            });
    run->start(m_reading);
}

} // namespace DriveDesk
