#include "PlantLinkRun.h"

#include "PlantVerify.h"
#include "parameters/ParameterDocument.h"

#include <QDir>
#include <QFileInfo>
#include <QTimer>

#include <algorithm>
#include <utility>

namespace DriveDesk {

PlantLinkRun::PlantLinkRun(PlantLink link, const PlantJob &job, QObject *parent)
    : QObject(parent)
    , m_link(std::move(link))
    , m_job(job)
{}

PlantLinkRun::~PlantLinkRun() = default;

QList<PlantDrive> PlantLinkRun::drives() const
{
    QList<PlantDrive> done = m_done;
    std::stable_sort(done.begin(), done.end(), [](const PlantDrive &a, const PlantDrive &b) {
        return a.address < b.address;
    });
    return done;
}

void PlantLinkRun::start()
{
    if (m_running)
        return;
    m_running = true;
    const bool find = m_job.task == PlantRun::Task::Find;
    if (m_link.protocol == Protocol::Hsp5 && !find) {
        m_queue = {-1};
    } else if (!find) {
        m_queue = m_link.addresses;
        std::sort(m_queue.begin(), m_queue.end());
    }
    // DIN66019 carries values only: each listed drive fails without a word on the line.
    if (m_link.protocol == Protocol::Din66019 && !m_queue.isEmpty())
        return next();
    // A drive without its file has nothing to be checked against or written: said at once,
    // and a link none of whose drives has one is not opened at all.
    if (m_job.task == PlantRun::Task::Verify || m_job.task == PlantRun::Task::Download) {
        const QList<int> listed = std::exchange(m_queue, {});
        for (int address : listed) {
            PlantDrive drive = driveAt(address);
            if (QFileInfo::exists(drive.file)) {
                m_queue.append(address);
                continue;
            }
            drive.outcome = PlantDrive::Outcome::NoFile;
            drive.reason = tr("%1 does not exist").arg(QDir::toNativeSeparators(drive.file));
            finishDrive(drive);
        }
        if (m_queue.isEmpty() && !listed.isEmpty())
            return end();
    }
    const int first = m_queue.isEmpty() ? 0 : std::max(m_queue.constFirst(), 0);
    ConnectionSettings settings = m_link.settings(first);
    settings.language = m_job.language;
    m_client = new DriveClient(settings, m_job.makeLink, m_job.clientOptions, this);
    connect(m_client, &DriveClient::connected, this, &PlantLinkRun::onConnected);
    connect(m_client, &DriveClient::connectionFailed, this, [this](const QString &reason) {
        failLink(tr("cannot connect: %1").arg(reason));
    });
    // What is at work fails with the line and ends on its own; the drives after it are
    // unreachable (next()).
    connect(m_client, &DriveClient::linkLost, this,
            [this](const QString &reason) { m_lost = reason; });
    emit progress(-1, 0, tr("connecting"));
    m_client->connectToDrive();
}

void PlantLinkRun::onConnected()
{
    if (m_stopping)
        return next();
    const bool needsSearch = m_job.task == PlantRun::Task::Find
        || (m_link.protocol != Protocol::Hsp5 && m_link.addresses.isEmpty());
    if (needsSearch && !m_search)
        return search();
    next();
}

// The bus is asked address by address; a search that went to the end names the drives on it.
void PlantLinkRun::search()
{
    m_search = std::make_shared<FindDrivesJob>(m_client->settings());
    auto *watcher = new QFutureWatcher<FoundDrive>(this);
    m_searching = watcher;
    connect(watcher, &QFutureWatcher<FoundDrive>::progressValueChanged, this,
            [this, watcher](int value) {
                emit progress(-1, value * 100 / std::max(1, watcher->progressMaximum()),
                              tr("searching"));
            });
    connect(watcher, &QFutureWatcher<FoundDrive>::resultReadyAt, this, &PlantLinkRun::onFound);
    connect(watcher, &QFutureWatcher<FoundDrive>::finished, this, &PlantLinkRun::onSearchEnded);
    watcher->setFuture(m_client->run(m_search));
}

void PlantLinkRun::onFound(int index)
{
    const FoundDrive found = m_searching->resultAt(index);
    const int address = m_link.protocol == Protocol::Hsp5 ? -1 : found.address;
    if (m_job.task != PlantRun::Task::Find) {
        m_queue.append(address);
        return;
    }
    PlantDrive drive;
    drive.link = m_link.name;
    drive.address = address;
    drive.outcome = PlantDrive::Outcome::Found;
    drive.identification = found.identification();
    finishDrive(drive);
}

void PlantLinkRun::onSearchEnded()
{
    QFutureWatcher<FoundDrive> *watcher = m_searching;
    watcher->deleteLater();
    const bool complete = !watcher->isCanceled()
        && watcher->progressValue() >= watcher->progressMaximum();
    QList<int> found = m_queue;
    for (const PlantDrive &drive : std::as_const(m_done))
        found.append(drive.address);
    if (complete && m_link.protocol != Protocol::Hsp5)
        m_link.addresses = found;
    if (complete && found.isEmpty()) {
        PlantDrive drive;
        drive.link = m_link.name;
        drive.outcome = PlantDrive::Outcome::Unreachable;
        drive.reason = tr("no drive answered");
        finishDrive(drive);
    }
    if (!complete && !m_stopping)
        return failLink(tr("the search stopped: %1").arg(watcher->progressText()));
    if (!complete && (m_job.task == PlantRun::Task::Find || m_queue.isEmpty())) {
        // Stopped: the bus may hold drives that were never asked.
        PlantDrive drive;
        drive.link = m_link.name;
        drive.outcome = PlantDrive::Outcome::Stopped;
        drive.reason = tr("the search was stopped after %1 of %2 addresses")
                           .arg(watcher->progressValue())
                           .arg(watcher->progressMaximum());
        finishDrive(drive);
    }
    if (m_job.task == PlantRun::Task::Find)
        return end();
    next(); // stopping: the drives found are named stopped
}

void PlantLinkRun::next()
{
    if (m_stopping) {
        for (int address : std::as_const(m_queue)) {
            PlantDrive drive = driveAt(address);
            drive.outcome = PlantDrive::Outcome::Stopped;
            drive.reason = tr("stopped before it was read");
            finishDrive(drive);
        }
        m_queue.clear();
    }
    if (!m_lost.isEmpty() && !m_queue.isEmpty())
        return failLink(tr("the connection was lost: %1").arg(m_lost));
    if (m_queue.isEmpty())
        return end();
    startDrive(m_queue.takeFirst());
}

PlantDrive PlantLinkRun::driveAt(int address) const
{
    PlantDrive drive;
    drive.link = m_link.name;
    drive.address = address;
    if (m_job.task != PlantRun::Task::Find)
        drive.file = PlantRun::fileFor(m_job.directory, m_link, address);
    return drive;
}

ScanOptions PlantLinkRun::readingOf(int address) const
{
    ScanOptions reading = m_job.reading;
    if (m_link.protocol != Protocol::Hsp5)
        reading.driveAddress = address;
    return reading;
}

void PlantLinkRun::startDrive(int address)
{
    m_current = address;
    m_atWork = true;
    PlantDrive drive = driveAt(address);
    if (m_link.protocol == Protocol::Din66019) {
        drive.outcome = PlantDrive::Outcome::Failed;
        drive.reason = tr("DIN66019 carries parameter values only: the drive has no parameter "
                          "list to read or write; use din66019ii");
        return driveEnded(drive);
    }
    if (m_job.task == PlantRun::Task::Verify || m_job.task == PlantRun::Task::Download) {
        if (!QFileInfo::exists(drive.file)) {
            drive.outcome = PlantDrive::Outcome::NoFile;
            drive.reason = tr("%1 does not exist").arg(QDir::toNativeSeparators(drive.file));
            return driveEnded(drive);
        }
        QString error;
        const std::optional<DriveDescription> file = ParameterDocument::load(drive.file, &error);
        if (!file) {
            drive.outcome = PlantDrive::Outcome::Failed;
            drive.reason = error;
            return driveEnded(drive);
        }
        m_file = *file;
    }
    if (m_job.task == PlantRun::Task::Download)
        return download(drive);
    upload(drive);
}

void PlantLinkRun::upload(PlantDrive drive)
{
    auto *run = new UploadRun(m_client, this);
    m_upload = run;
    connect(run, &UploadRun::progress, this,
            [this, address = drive.address](int value, int maximum, const QString &what) {
                emit progress(address, value * 100 / std::max(1, maximum), what);
            });
    connect(run, &UploadRun::finished, this, [this, run, drive](const UploadResult &result) {
        run->deleteLater();
        onUploaded(drive, result);
    });
    run->start(readingOf(drive.address));
}

void PlantLinkRun::onUploaded(PlantDrive drive, const UploadResult &result)
{
    if (result.outcome == UploadResult::Outcome::Cancelled) {
        drive.outcome = PlantDrive::Outcome::Stopped;
        drive.reason = tr("stopped before the drive was read whole; nothing saved");
    } else if (!result.isComplete()) {
        drive.outcome = PlantDrive::Outcome::Failed;
        drive.reason = result.summary();
    } else if (m_job.task == PlantRun::Task::Backup) {
        QString error;
        drive.outcome = saveUpload(drive.file, result, &error) ? PlantDrive::Outcome::Saved
                                                               : PlantDrive::Outcome::Failed;
        drive.reason = error;
        for (const GroupDescription &group : result.document.groups)
            drive.parameters += int(group.parameters.size());
    } else {
        judgeVerify(m_file, result.document, drive);
    }
    driveEnded(drive);
}

void PlantLinkRun::driveEnded(const PlantDrive &drive)
{
    finishDrive(drive);
    m_current = -1;
    m_atWork = false;
    // A drive that stopped answering leaves the client sending one request at a time until it
    // answers again: the next drive of the bus starts on a fresh connection, as if alone.
    if (m_client && m_client->isDriveSilent() && m_lost.isEmpty() && !m_stopping
        && !m_queue.isEmpty()) {
        m_client->disconnectFromDrive();
        m_client->connectToDrive(); // onConnected() goes on
        return;
    }
    next();
}

void PlantLinkRun::finishDrive(const PlantDrive &drive)
{
    m_done.append(drive);
    emit driveDone(drive);
}

void PlantLinkRun::failLink(const QString &reason)
{
    QList<int> addresses = m_queue;
    m_queue.clear();
    // Before any drive (connecting, searching), a link with nothing queued is one unreachable
    // entry of its own.
    if (m_atWork || addresses.isEmpty())
        addresses.prepend(m_current);
    for (int unreached : std::as_const(addresses)) {
        PlantDrive drive = driveAt(unreached);
        drive.outcome = PlantDrive::Outcome::Unreachable;
        drive.reason = reason;
        finishDrive(drive);
    }
    m_current = -1;
    m_atWork = false;
    for (QObject *work : std::initializer_list<QObject *>{ m_upload, m_downloading, m_searching }) {
        if (work) {
            work->disconnect(this);
            work->deleteLater();
        }
    }
    end();
}

void PlantLinkRun::end()
{
    if (!m_running)
        return;
    m_running = false;
    if (m_client) {
        m_client->disconnect(this);
        m_client->disconnectFromDrive();
        m_client->deleteLater();
        m_client = nullptr;
    }
    // Never from inside start() or stop(): the caller has not yet returned to its event loop.
    QTimer::singleShot(0, this, &PlantLinkRun::finished);
}

void PlantLinkRun::stop()
{
    if (m_stopping || !m_running)
        return;
    m_stopping = true;
    if (m_downloading)
        m_downloading->stop();
    else if (m_upload && m_upload->isRunning())
        m_upload->cancel();
    else if (m_searching && m_searching->isRunning())
        m_search->requestStop();
    else {
        // Still connecting: nothing on its way to wait for.
        if (m_queue.isEmpty())
            m_queue.append(m_current);
        next();
    }
}

} // namespace DriveDesk
