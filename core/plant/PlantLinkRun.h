#pragma once

#include "PlantRun.h"
#include "client/FindDrivesJob.h"
#include "session/DownloadRun.h"
#include "session/UploadRun.h"

#include <QFutureWatcher>
#include <QPointer>

#include <memory>

namespace DriveDesk {

// What a PlantRun asks of each of its links.
struct PlantJob
{
    PlantRun::Task task = PlantRun::Task::Find;
    QString directory; // the parameter files (backup, verify, download)
    LinkMaker makeLink;
    ClientOptions clientOptions;
    ScanOptions reading;
    Language language = Language::English;
    bool dryRun = false; // download: plan only
    bool force = false;  // download: write despite the checks
    EditJournal *journal = nullptr; // download: where each value written is journaled
};

// One link of a plant at work, over one connection and one client for every drive on it: a
// DIN66019II bus names its drive in each request, so the drives are asked one after another
// on the same line. A bus the plant lists no addresses for is searched first.
// Each step is a member called when the one before it ended; the drive at work is m_current.
// Thread: the caller's; the client's work runs in its own thread.
class PlantLinkRun : public QObject
{
    Q_OBJECT
public:
    PlantLinkRun(PlantLink link, const PlantJob &job, QObject *parent = nullptr);
    ~PlantLinkRun() override;

    void start();
    // Ends after the value on its way; drives not done are Stopped.
    void stop();
    bool isRunning() const { return m_running; }

    // The link, with the addresses its search found where it went to the end.
    const PlantLink &link() const { return m_link; }
    QList<PlantDrive> drives() const; // by address

signals:
    // The drive at `address` (-1: the link's search or its connection) and what it does.
    void progress(int address, int percent, const QString &what);
    void driveDone(const DriveDesk::PlantDrive &drive);
    // Always after start() and stop() have returned.
    void finished();

private:
    void onConnected();
    void search();
    void onFound(int index);
    void onSearchEnded();
    void next();
    void startDrive(int address);
    void upload(PlantDrive drive);
    void onUploaded(PlantDrive drive, const UploadResult &result);
    // The file in m_file to the drive (PlantLinkDownload.cpp).
    void download(PlantDrive drive);
    void onPlanned(PlantDrive drive, const DownloadPlan &plan);
    void onDownloaded(PlantDrive drive, const DownloadReport &report);
    void releaseDownload();
    // The drive at work is done; the next one's turn.
    void driveEnded(const PlantDrive &drive);
    void finishDrive(const PlantDrive &drive);
    // The line is gone: the drive at work and every drive after it cannot be reached.
    void failLink(const QString &reason);
    void end();
    PlantDrive driveAt(int address) const;
    ScanOptions readingOf(int address) const;

    PlantLink m_link;
    const PlantJob m_job;
    DriveClient *m_client = nullptr;
    QList<int> m_queue; // addresses still to do; -1 for the drive of an HSP5 link
    QList<PlantDrive> m_done;
    int m_current = -1;    // the drive at work, while m_atWork
    bool m_atWork = false;
    QString m_lost;     // why the line went, once it went
    QPointer<UploadRun> m_upload;
    QPointer<DownloadRun> m_downloading;
    std::shared_ptr<FindDrivesJob> m_search;
    QPointer<QFutureWatcher<FoundDrive>> m_searching;
    DriveDescription m_file; // verify, download: the file of the drive at work
    bool m_running = false;
    bool m_stopping = false;
};

} // namespace DriveDesk
