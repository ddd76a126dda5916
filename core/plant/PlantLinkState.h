#pragma once

#include "PlantRun.h"
#include "client/FindDrivesJob.h"
#include "session/DownloadRun.h"
#include "session/UploadRun.h"

#include <QFutureWatcher>
#include <QPointer>

namespace DriveDesk {

// One link at work: its client (one drive at a time), what is left and what is done.
struct PlantRun::LinkState
{
    qsizetype index = 0; // in m_plant.links
    QList<int> queue;    // addresses still to do; -1 for the drive of an HSP5 link
    QList<PlantDrive> done;
    DriveClient *client = nullptr;
    QPointer<UploadRun> upload;
    QPointer<DownloadRun> downloading;
    std::shared_ptr<FindDrivesJob> search;
    QPointer<QFutureWatcher<FoundDrive>> searching;
    DriveDescription file; // verify, download: the file of the drive at work
    int current = -1;
    bool running = false;
};

} // namespace DriveDesk
