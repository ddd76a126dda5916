// PlantDock: the plant's jobs, each a PlantRun of core, and what the view makes of their end.
#include "PlantDock.h"

#include "PlantModel.h"
#include "PlantReportDialog.h"

#include "bus/LinkFactory.h"
#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"
#include "frame/RunJournal.h"
#include "frame/WindowFeature.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QTime>
#include <QTreeView>

#include <algorithm>

namespace DriveDesk {

void PlantDock::startJob(Job job, const Plant &plant, const QString &directory)
{
    if (m_run || plant.links.isEmpty())
        return;
    const PlantRun::Task task = job == Job::Find           ? PlantRun::Task::Find
        : job == Job::Verify                               ? PlantRun::Task::Verify
        : job == Job::DownloadLook || job == Job::Download ? PlantRun::Task::Download
                                                           : PlantRun::Task::Backup;
    auto *run = new PlantRun(plant, task, directory, everyLink(), this);
    run->setClientOptions(m_clientOptions);
    ScanOptions reading;
    reading.metadata = MetadataSource::Cache; // a kind of drive read before is quick
    run->setReading(reading);
    run->setLanguage(m_frame.language());
    run->setDownloadOptions(job == Job::DownloadLook, false);
    if (job == Job::Download && m_journaled && m_journaled()) {
        // A restore says which revision its values came from, as the journal is read later.
        const QString plantFile = QFileInfo(m_path).fileName();
        run->setJournal(RunJournal::attach(
            run, m_revision.isEmpty()
                     ? tr("plant download of %1").arg(plantFile)
                     : tr("plant download of %1 at revision %2").arg(plantFile, m_revision)));
    }
    // A comparison reads into files of its own: the drives' last results stay as they were.
    m_state->follow(run,
                    job == Job::CompareRead ? PlantState::Keep::ProgressOnly
                                            : PlantState::Keep::Results,
                    [this](const PlantDrive &drive) { return explained(drive); });
    connect(run, &PlantRun::finished, this, &PlantDock::onJobFinished);
    m_run = run;
    m_job = job;
    m_jobPlant = plant;
    m_jobDirectory = directory;
    switch (job) {
    case Job::Find:
        showMessage(tr("Searching every link for its drives..."));
        break;
    case Job::Backup:
        showMessage(tr("Backing up every drive..."));
        break;
    case Job::Verify:
        showMessage(tr("Verifying every drive against its file..."));
        break;
    case Job::DownloadLook:
        showMessage(tr("Reading every drive to see what a download would write..."));
        break;
    case Job::Download:
        showMessage(tr("Downloading to every drive..."));
        break;
    case Job::CompareRead:
        showMessage(tr("Reading the two drives to compare..."));
        break;
    case Job::None:
        break;
    }
    updateActions();
    run->start();
}

void PlantDock::restoreRevision(std::shared_ptr<QTemporaryDir> files, const QString &revision)
{
    if (m_run)
        return showMessage(tr("A job is running on the plant; restore once it is done."));
    m_revisionFiles = std::move(files);
    m_revision = revision;
    startJob(Job::DownloadLook, m_state->plant(), m_revisionFiles->path());
    if (m_job == Job::DownloadLook)
        showMessage(tr("Reading every drive to see what restoring %1 would write...").arg(revision));
}

void PlantDock::onJobFinished()
{
    PlantRun *run = m_run;
    const Job job = m_job;
    m_run = nullptr;
    m_job = Job::None;
    run->deleteLater();
    QList<PlantDrive> drives = run->drives();
    for (PlantDrive &drive : drives)
        drive = explained(drive);
    switch (job) {
    case Job::Find:
        findFinished(*run);
        break;
    case Job::Backup: {
        const QString summary
            = PlantDrive::summary(drives, PlantDrive::outcomeText(PlantDrive::Outcome::Saved));
        showMessage(summary);
        if (m_commitAction->isChecked())
            commitBackup(run->plant(), drives, summary);
        break;
    }
    case Job::Verify:
        showMessage(PlantDrive::summary(drives, PlantDrive::outcomeText(PlantDrive::Outcome::Equal)));
        break;
    case Job::DownloadLook:
        downloadPlanned(drives);
        break;
    case Job::Download: {
        const QString text = PlantDrive::summary(drives, tr("downloaded or already equal"));
        const QString title = m_revision.isEmpty() ? tr("Download All: Report")
                                                   : tr("Restore to %1: Report").arg(m_revision);
        m_revisionFiles.reset();
        m_revision.clear();
        auto *report = new PlantReportDialog(title, text, drives, false, this);
        m_report = report;
        report->setAttribute(Qt::WA_DeleteOnClose);
        report->show();
        showMessage(text);
        break;
    }
    case Job::CompareRead:
        compareRead(drives);
        break;
    case Job::None:
        break;
    }
    fitColumns();
    updateActions();
}

void PlantDock::findFinished(const PlantRun &run)
{
    const QList<PlantDrive> drives = run.drives();
    QString text
        = PlantDrive::summary(run.drives(), PlantDrive::outcomeText(PlantDrive::Outcome::Found));
    // As `plant find --update`: the addresses found on the links searched to the end go into
    // the plant file, and nothing else in it changes.
    if (!m_state->noLinkAnswers() && run.plant() != m_jobPlant) {
        QString error;
        // The summary is a sentence of its own, without its full stop on the command line.
        if (PlantFile::save(m_path, run.plant(), &error))
            text = tr("%1. The addresses found were written to %2.")
                       .arg(text, QDir::toNativeSeparators(m_path));
        else
            text = tr("%1. The plant file was not changed: %2").arg(text, error);
    }
    showMessage(text);
}

void PlantDock::downloadPlanned(const QList<PlantDrive> &drives)
{
    const qsizetype toWrite
        = std::count_if(drives.cbegin(), drives.cend(), [](const PlantDrive &d) {
              return d.outcome == PlantDrive::Outcome::Planned;
          });
    const QString text = toWrite == 0
        ? tr("No drive would be written to: each is already equal to its file, or cannot "
             "take it (see why).")
        : tr("%n drive(s) would be written to. Look at what each gets, then write.", nullptr,
             int(toWrite));
    const QString title = m_revision.isEmpty() ? tr("Download All: Last Look")
                                               : tr("Restore to %1: Last Look").arg(m_revision);
    auto *look = new PlantReportDialog(title, text, drives, toWrite > 0, this);
    m_report = look;
    look->setAttribute(Qt::WA_DeleteOnClose);
    // What is written is what was looked at: the same folder (a revision's files stay while
    // their last look is open), whatever was started since.
    connect(look, &PlantReportDialog::accepted, this,
            [this, directory = m_jobDirectory, files = m_revisionFiles, revision = m_revision] {
                if (m_run)
                    return showMessage(tr("A job is running on the plant; start again once it "
                                          "is done."));
                m_revisionFiles = files;
                m_revision = revision;
                startJob(Job::Download, m_state->plant(), directory);
            });
    look->show();
    showMessage(text);
}

PlantDrive PlantDock::explained(PlantDrive drive) const
{
    // A line the editor holds cannot be opened a second time (a serial port, a gateway that
    // serves one connection): its drives fail, and the user needs to know what to do.
    const DriveSession *session = m_frame.session();
    const PlantLink *link = m_state->plant().link(drive.link);
    if (drive.isGood() || !session || !link
        || session->state() == DriveClient::State::Disconnected
        || link->settings(std::max(drive.address, 0)).target() != session->settings().target())
        return drive;
    drive.reason = tr("the editor is connected to this line (%1): disconnect it (Drive > "
                      "Disconnect) and start again; %2")
                       .arg(session->settings().target(), drive.reason);
    return drive;
}

void PlantDock::compareSelected()
{
    const QList<QModelIndex> drives = selectedDrives();
    if (drives.size() != 2 || m_run)
        return showMessage(tr("Select two drives to compare."));
    m_compareWith = {};
    readToCompare(drives);
}

void PlantDock::compareWithDrive(const QString &file, const QString &name, const QString &drive)
{
    if (m_run)
        return showMessage(tr("A job is running on the plant; compare once it is done."));
    for (const QModelIndex &index : driveRows()) {
        if (index.data().toString() == drive) {
            m_compareWith = {file, name};
            return readToCompare({index});
        }
    }
    showMessage(tr("The plant has no drive %1.").arg(drive));
}

void PlantDock::readToCompare(const QList<QModelIndex> &drives)
{
    // Only these drives, each read whole as a backup reads it, into files of their own.
    Plant pair;
    pair.name = m_state->plant().name;
    for (const QModelIndex &drive : drives) {
        const PlantLink *link = m_model->linkOf(drive);
        PlantLink *taken = pair.link(link->name);
        if (!taken) {
            pair.links.append(*link);
            taken = &pair.links.last();
            taken->addresses.clear();
        }
        if (link->protocol != Protocol::Hsp5)
            taken->addresses.append(drive.data(PlantModel::AddressRole).toInt());
    }
    m_compareFiles = std::make_unique<QTemporaryDir>();
    if (!m_compareFiles->isValid())
        return showMessage(m_compareFiles->errorString());
    startJob(Job::CompareRead, pair, m_compareFiles->path());
}

void PlantDock::compareRead(const QList<PlantDrive> &drives)
{
    // A file to compare with the drive read (a revision's) is side A.
    QStringList files = m_compareWith.isEmpty() ? QStringList() : QStringList{m_compareWith[0]};
    QStringList names = m_compareWith.isEmpty() ? QStringList() : QStringList{m_compareWith[1]};
    QStringList problems;
    const QString time = QLocale().toString(QTime::currentTime(), QLocale::ShortFormat);
    for (const PlantDrive &drive : drives) {
        if (drive.outcome == PlantDrive::Outcome::Saved) {
            files << drive.file;
            names << tr("%1 as read at %2").arg(drive.name(), time);
        } else {
            problems << tr("%1: %2").arg(
                drive.name(),
                drive.reason.isEmpty() ? PlantDrive::outcomeText(drive.outcome) : drive.reason);
        }
    }
    if (files.size() != 2)
        return showMessage(
            tr("The drives could not be compared: %1").arg(problems.join(QStringLiteral("; "))));
    if (m_compareWith.isEmpty())
        showMessage(tr("%1 and %2 read; the compare window shows them side by side.")
                        .arg(drives.at(0).name(), drives.at(1).name()));
    else
        showMessage(tr("%1 and %2 side by side in the compare window.").arg(names.at(0), names.at(1)));
    emit compareRequested(files.at(0), names.at(0), files.at(1), names.at(1));
}

} // namespace DriveDesk
