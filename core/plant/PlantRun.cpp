#include "PlantRun.h"

#include "PlantLinkState.h"
#include "client/FindDrivesJob.h"
#include "parameters/DriveIdentity.h"
#include "parameters/MetadataMatch.h"
#include "parameters/ParameterDocument.h"
#include "session/DownloadRun.h"
#include "session/UploadRun.h"

#include <QDir>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QTimer>

#include <algorithm>

namespace DriveDesk {

PlantRun::PlantRun(Plant plant, Task task, QString directory, LinkMaker makeLink, QObject *parent)
    : QObject(parent)
    , m_plant(std::move(plant))
    , m_task(task)
    , m_directory(std::move(directory))
    , m_makeLink(std::move(makeLink))
{}

PlantRun::~PlantRun() = default;

QString PlantRun::fileFor(const QString &directory, const PlantLink &link, int address)
{
    const QString name = link.protocol == Protocol::Hsp5 || address < 0
                             ? link.name
                             : QStringLiteral("%1-%2").arg(link.name).arg(address);
    return QDir(directory).filePath(name + QStringLiteral(".json"));
}

bool PlantRun::isRunning() const
{
    return std::any_of(m_links.cbegin(), m_links.cend(),
                       [](const std::shared_ptr<LinkState> &state) { return state->running; });
}

QList<PlantDrive> PlantRun::drives() const
{
    QList<PlantDrive> all;
    for (const std::shared_ptr<LinkState> &state : m_links) {
        QList<PlantDrive> done = state->done;
        std::stable_sort(done.begin(), done.end(), [](const PlantDrive &a, const PlantDrive &b) {
            return a.address < b.address;
        });
        all += done;
    }
    return all;
}

void PlantRun::start()
{
    if (m_started)
        return;
    m_started = true;
    for (qsizetype i = 0; i < m_plant.links.size(); ++i) {
        auto state = std::make_shared<LinkState>();
        state->index = i;
        state->running = true;
        m_links.append(state);
    }
    for (const std::shared_ptr<LinkState> &state : std::as_const(m_links))
        startLink(*state);
}

void PlantRun::startLink(LinkState &state)
{
    const PlantLink &link = m_plant.links.at(state.index);
    if (link.protocol == Protocol::Hsp5 && m_task != Task::Find) {
        state.queue = {-1};
        return nextDrive(state);
    }
    if (m_task == Task::Find || link.addresses.isEmpty())
        return search(state);
    state.queue = link.addresses;
    std::sort(state.queue.begin(), state.queue.end());
    nextDrive(state);
}

DriveClient *PlantRun::makeClient(LinkState &state, int address)
{
    const PlantLink &link = m_plant.links.at(state.index);
    ConnectionSettings settings = link.settings(std::max(address, 0));
    settings.language = m_language;
    state.client = new DriveClient(settings, m_makeLink, m_clientOptions, this);
    state.current = address;
    connect(state.client, &DriveClient::connectionFailed, this,
            [this, &state](const QString &reason) {
                failLink(state, state.current, tr("cannot connect: %1").arg(reason));
            });
    return state.client;
}

void PlantRun::dropClient(LinkState &state)
{
    if (!state.client)
        return;
    state.client->disconnect(this);
    state.client->disconnectFromDrive();
    state.client->deleteLater();
    state.client = nullptr;
}

// The bus is asked address by address; a search that went to the end names the drives on it.
void PlantRun::search(LinkState &state)
{
    const PlantLink &link = m_plant.links.at(state.index);
    DriveClient *client = makeClient(state, -1);
    emit progress(link.name, -1, 0, tr("connecting"));
    connect(client, &DriveClient::connected, this, [this, &state, client] {
        state.search = std::make_shared<FindDrivesJob>(client->settings());
        auto *watcher = new QFutureWatcher<FoundDrive>(this);
        state.searching = watcher;
        const QString linkName = m_plant.links.at(state.index).name;
        const bool hsp5 = m_plant.links.at(state.index).protocol == Protocol::Hsp5;
        connect(watcher, &QFutureWatcher<FoundDrive>::progressValueChanged, this,
                [this, watcher, linkName](int value) {
                    emit progress(linkName, -1, value * 100 / std::max(1, watcher->progressMaximum()),
                                  tr("searching"));
                });
        connect(watcher, &QFutureWatcher<FoundDrive>::resultReadyAt, this,
                [this, &state, watcher, linkName, hsp5](int index) {
                    const FoundDrive found = watcher->resultAt(index);
                    const int address = hsp5 ? -1 : found.address;
                    if (m_task != Task::Find) {
                        state.queue.append(address);
                        return;
                    }
                    PlantDrive drive;
                    drive.link = linkName;
                    drive.address = address;
                    drive.outcome = PlantDrive::Outcome::Found;
                    drive.identification = found.identification();
                    finishDrive(state, drive);
                });
        connect(watcher, &QFutureWatcher<FoundDrive>::finished, this,
                [this, &state, watcher, hsp5] {
                    watcher->deleteLater();
                    const bool complete = !watcher->isCanceled()
                        && watcher->progressValue() >= watcher->progressMaximum();
                    const QString why = watcher->progressText();
                    QList<int> found = state.queue;
                    for (const PlantDrive &drive : std::as_const(state.done))
                        found.append(drive.address);
                    if (complete && !hsp5)
                        m_plant.links[state.index].addresses = found;
                    if (complete && found.isEmpty()) {
                        PlantDrive drive;
                        drive.link = m_plant.links.at(state.index).name;
                        drive.outcome = PlantDrive::Outcome::Unreachable;
                        drive.reason = tr("no drive answered");
                        finishDrive(state, drive);
                    }
                    if (!complete && !m_stopping)
                        return failLink(state, -1, tr("the search stopped: %1").arg(why));
                    if (!complete && (m_task == Task::Find || state.queue.isEmpty())) {
                        // Stopped: the bus may hold drives that were never asked.
                        PlantDrive drive;
                        drive.link = m_plant.links.at(state.index).name;
                        drive.outcome = PlantDrive::Outcome::Stopped;
                        drive.reason = tr("the search was stopped after %1 of %2 addresses")
                                           .arg(watcher->progressValue())
                                           .arg(watcher->progressMaximum());
                        finishDrive(state, drive);
                    }
                    dropClient(state);
                    if (m_task == Task::Find)
                        return endLink(state);
                    nextDrive(state); // stopping: the drives found are named stopped
                });
        watcher->setFuture(client->run(state.search));
    });
    client->connectToDrive();
}

void PlantRun::nextDrive(LinkState &state)
{
    if (m_stopping) {
        for (int address : std::as_const(state.queue)) {
            PlantDrive drive;
            drive.link = m_plant.links.at(state.index).name;
            drive.address = address;
            drive.outcome = PlantDrive::Outcome::Stopped;
            drive.reason = tr("stopped before it was read");
            finishDrive(state, drive);
        }
        state.queue.clear();
    }
    if (state.queue.isEmpty())
        return endLink(state);
    readDrive(state, state.queue.takeFirst());
}

void PlantRun::readDrive(LinkState &state, int address)
{
    const PlantLink &link = m_plant.links.at(state.index);
    PlantDrive drive;
    drive.link = link.name;
    drive.address = address;
    drive.file = fileFor(m_directory, link, address);
    if (link.protocol == Protocol::Din66019) {
        drive.outcome = PlantDrive::Outcome::Failed;
        drive.reason = tr("DIN66019 carries parameter values only: the drive has no parameter "
                          "list to read or write; use din66019ii");
        finishDrive(state, drive);
        return nextDrive(state);
    }
    if (m_task == Task::Verify || m_task == Task::Download) {
        if (!QFileInfo::exists(drive.file)) {
            drive.outcome = PlantDrive::Outcome::NoFile;
            drive.reason = tr("%1 does not exist").arg(QDir::toNativeSeparators(drive.file));
            finishDrive(state, drive);
            return nextDrive(state);
        }
        QString error;
        const std::optional<DriveDescription> file = ParameterDocument::load(drive.file, &error);
        if (!file) {
            drive.outcome = PlantDrive::Outcome::Failed;
            drive.reason = error;
            finishDrive(state, drive);
            return nextDrive(state);
        }
        state.file = *file;
    }
    DriveClient *client = makeClient(state, address);
    emit progress(link.name, address, 0, tr("connecting"));
    connect(client, &DriveClient::connected, this, [this, &state, client, drive]() mutable {
        if (m_stopping) {
            dropClient(state);
            drive.outcome = PlantDrive::Outcome::Stopped;
            drive.reason = tr("stopped before it was read");
            finishDrive(state, drive);
            return nextDrive(state);
        }
        if (m_task == Task::Download)
            return download(state, client, drive);
        auto *upload = new UploadRun(client, this);
        state.upload = upload;
        connect(upload, &UploadRun::progress, this,
                [this, drive](int value, int maximum, const QString &what) {
                    emit progress(drive.link, drive.address, value * 100 / std::max(1, maximum),
                                  what);
                });
        connect(upload, &UploadRun::finished, this,
                [this, &state, upload, drive](const UploadResult &result) mutable {
                    upload->deleteLater();
                    dropClient(state);
                    if (result.outcome == UploadResult::Outcome::Cancelled) {
                        drive.outcome = PlantDrive::Outcome::Stopped;
                        drive.reason = tr("stopped before the drive was read whole; nothing "
                                          "saved");
                    } else if (!result.isComplete()) {
                        drive.outcome = PlantDrive::Outcome::Failed;
                        drive.reason = result.summary();
                    } else if (m_task == Task::Backup) {
                        QString error;
                        drive.outcome = saveUpload(drive.file, result, &error)
                                            ? PlantDrive::Outcome::Saved
                                            : PlantDrive::Outcome::Failed;
                        drive.reason = error;
                        for (const GroupDescription &group : result.document.groups)
                            drive.parameters += int(group.parameters.size());
                    } else {
                        const auto fileKind = DriveIdentity::kind(state.file);
                        const auto driveKind = DriveIdentity::kind(result.document);
                        // Without a kind on one side, the metadata says whether it is one.
                        const auto difference = fileKind && driveKind
                            ? std::nullopt
                            : MetadataMatch::firstDifference(state.file, result.document);
                        if (fileKind && driveKind && *fileKind != *driveKind) {
                            drive.outcome = PlantDrive::Outcome::OtherKind;
                            drive.reason = tr("the file is of %1, the drive %2")
                                               .arg(DriveIdentity::summary(state.file),
                                                    DriveIdentity::summary(result.document));
                        } else if (difference) {
                            drive.outcome = PlantDrive::Outcome::OtherKind;
                            drive.reason = tr("the file's metadata is not the drive's: %1")
                                               .arg(MetadataMatch::text(*difference));
                        } else {
                            drive.differences
                                = compareDescriptions(state.file, result.document).differences;
                            drive.outcome = drive.differences.isEmpty()
                                                ? PlantDrive::Outcome::Equal
                                                : PlantDrive::Outcome::Different;
                        }
                    }
                    finishDrive(state, drive);
                    nextDrive(state);
                });
        upload->start(m_reading);
    });
    client->connectToDrive();
}

void PlantRun::finishDrive(LinkState &state, PlantDrive drive)
{
    state.done.append(drive);
    emit driveDone(drive);
}

// The line is gone: the drive at work and every drive after it on this link cannot be reached.
void PlantRun::failLink(LinkState &state, int address, const QString &reason)
{
    const PlantLink &link = m_plant.links.at(state.index);
    QList<int> addresses = state.queue;
    state.queue.clear();
    if (address >= 0 || link.protocol == Protocol::Hsp5 || addresses.isEmpty())
        addresses.prepend(address);
    for (int unreached : std::as_const(addresses)) {
        PlantDrive drive;
        drive.link = link.name;
        drive.address = unreached;
        drive.outcome = PlantDrive::Outcome::Unreachable;
        drive.reason = reason;
        if (m_task != Task::Find)
            drive.file = fileFor(m_directory, link, unreached);
        finishDrive(state, drive);
    }
    if (state.upload)
        state.upload->disconnect(this);
    if (state.downloading)
        state.downloading->disconnect(this);
    dropClient(state);
    endLink(state);
}

void PlantRun::endLink(LinkState &state)
{
    if (!state.running)
        return;
    state.running = false;
    // Never from inside start() or stop(): the caller has not yet returned to its event loop.
    if (!isRunning())
        QTimer::singleShot(0, this, &PlantRun::finished);
}

void PlantRun::stop()
{
    if (m_stopping || !isRunning())
        return;
    m_stopping = true;
    for (const std::shared_ptr<LinkState> &state : std::as_const(m_links)) {
        if (!state->running)
            continue;
        if (state->downloading) {
            state->downloading->stop();
        } else if (state->upload && state->upload->isRunning()) {
            state->upload->cancel();
        } else if (state->searching && state->searching->isRunning()) {
            state->search->requestStop();
        } else if (state->client) {
            // Still connecting: nothing on its way to wait for.
            const int address = state->current;
            dropClient(*state);
            state->queue.prepend(address);
            nextDrive(*state);
        }
    }
}

} // namespace DriveDesk
