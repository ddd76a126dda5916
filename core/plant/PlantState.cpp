#include "PlantState.h"

#include <QFileInfo>

#include <algorithm>

namespace DriveDesk {

PlantState::PlantState(QObject *parent)
    : QObject(parent)
{}

void PlantState::openPlant(const Plant &plant, const QString &backupFolder)
{
    ++m_opened;
    m_plant = plant;
    m_drives.clear();
    m_links.clear();
    m_directory = backupFolder;
    readBackupTimes();
    emit reset();
}

void PlantState::setPlant(const Plant &plant)
{
    m_plant = plant;
    // A drive or link the plant no longer has is forgotten: were it added again, what was
    // known of it would no longer be true.
    QHash<DriveKey, KnownDrive> drives;
    QHash<QString, KnownLink> links;
    for (const PlantLink &link : std::as_const(m_plant.links)) {
        if (const auto known = m_links.constFind(link.name); known != m_links.cend())
            links.insert(link.name, *known);
        for (int address : drivesOf(link)) {
            const DriveKey key { link.name, address };
            if (const auto known = m_drives.constFind(key); known != m_drives.cend())
                drives.insert(key, *known);
        }
    }
    m_drives = std::move(drives);
    m_links = std::move(links);
    readBackupTimes();
    emit reset();
}

void PlantState::setBackupFolder(const QString &directory)
{
    m_directory = directory;
    readBackupTimes();
    allChanged();
}

QList<int> PlantState::drivesOf(const PlantLink &link)
{
    if (link.protocol == Protocol::Hsp5)
        return { -1 };
    QList<int> addresses = link.addresses;
    std::sort(addresses.begin(), addresses.end());
    return addresses;
}

PlantState::KnownDrive PlantState::drive(const QString &link, int address) const
{
    return m_drives.value({ link, address });
}

PlantState::KnownLink PlantState::link(const QString &link) const
{
    return m_links.value(link);
}

PlantState::Reach PlantState::linkReach(const QString &link) const
{
    const PlantLink *plantLink = m_plant.link(link);
    if (!plantLink)
        return Reach::NotSearched;
    const QList<int> drives = drivesOf(*plantLink);
    const auto reachOf = [this, &link](int address) { return drive(link, address).reach; };
    if (m_links.value(link).unreachable
        || (!drives.isEmpty() && std::all_of(drives.cbegin(), drives.cend(), [&](int address) {
               return reachOf(address) == Reach::Unreachable;
           })))
        return Reach::Unreachable;
    const bool answering = std::any_of(drives.cbegin(), drives.cend(), [&](int address) {
        return reachOf(address) == Reach::Answering;
    });
    return answering ? Reach::Answering : Reach::NotSearched;
}

bool PlantState::noLinkAnswers() const
{
    return !m_plant.links.isEmpty()
        && std::all_of(m_plant.links.cbegin(), m_plant.links.cend(), [this](const PlantLink &link) {
               return linkReach(link.name) == Reach::Unreachable;
           });
}

void PlantState::follow(PlantRun *run, Keep keep, Explain explain)
{
    const quint64 opened = m_opened;
    if (keep == Keep::Results)
        clearResults();
    connect(run, &PlantRun::progress, this,
            [this, opened](const QString &link, int address, int percent, const QString &what) {
                if (opened == m_opened)
                    setProgress(link, address, percent, what);
            });
    if (keep == Keep::Results) {
        connect(run, &PlantRun::driveDone, this,
                [this, opened, explain = std::move(explain)](const PlantDrive &drive) {
                    if (opened == m_opened)
                        keepResult(explain ? explain(drive) : drive);
                });
    }
    connect(run, &PlantRun::finished, this, [this, opened, run, keep] {
        if (opened != m_opened)
            return;
        // As `plant find --update` writes them: the addresses found on the links searched to
        // the end, the drives listed there that did not answer gone.
        if (keep == Keep::Results && run->task() == PlantRun::Task::Find)
            setPlant(run->plant());
        endJob();
    });
}

void PlantState::clearResults()
{
    for (KnownDrive &known : m_drives) {
        known.result.reset();
        known.percent = -1;
    }
    for (KnownLink &known : m_links) {
        known.result.reset();
        known.percent = -1;
    }
    allChanged();
}

void PlantState::setProgress(const QString &link, int address, int percent, const QString &what)
{
    const PlantLink *plantLink = m_plant.link(link);
    if (!plantLink)
        return;
    // A DIN link's connection and search are the link's own; an HSP5 link's are its drive's.
    const int clamped = std::clamp(percent, 0, 100);
    if (address < 0 && plantLink->protocol != Protocol::Hsp5) {
        KnownLink &known = m_links[link];
        known.percent = clamped;
        known.what = what;
        emit linkChanged(link);
        return;
    }
    KnownDrive &known = m_drives[{ link, address }];
    known.percent = clamped;
    known.what = what;
    emit driveChanged(link, address);
}

void PlantState::keepResult(const PlantDrive &drive)
{
    PlantLink *link = m_plant.link(drive.link);
    if (!link)
        return;
    if (drive.address < 0 && link->protocol != Protocol::Hsp5) {
        // The bus as a whole: no drive answered, it could not be opened, the search stopped.
        KnownLink &known = m_links[drive.link];
        known.result = drive;
        known.percent = -1;
        if (drive.outcome == PlantDrive::Outcome::Unreachable)
            known.unreachable = true;
        emit linkChanged(drive.link);
        return;
    }
    const bool added
        = link->protocol != Protocol::Hsp5 && !link->addresses.contains(drive.address);
    if (added)
        link->addresses.append(drive.address); // found by a search: shown as soon as it answers
    KnownDrive &known = m_drives[{ drive.link, drive.address }];
    known.result = drive;
    known.percent = -1;
    if (drive.outcome == PlantDrive::Outcome::Unreachable) {
        known.reach = Reach::Unreachable;
        known.why = drive.reason;
    } else if (drive.answered()) {
        known.reach = Reach::Answering;
        known.why.clear();
        m_links[drive.link].unreachable = false;
    }
    if (drive.outcome == PlantDrive::Outcome::Found)
        known.identification = drive.identification;
    if (added)
        emit driveAdded(drive.link, drive.address);
    emit driveChanged(drive.link, drive.address);
    emit linkChanged(drive.link);
}

void PlantState::endJob()
{
    for (KnownDrive &known : m_drives)
        known.percent = -1;
    for (KnownLink &known : m_links)
        known.percent = -1;
    readBackupTimes();
    allChanged();
}

void PlantState::readBackupTimes()
{
    for (const PlantLink &link : std::as_const(m_plant.links)) {
        for (int address : drivesOf(link)) {
            const QFileInfo file(PlantRun::fileFor(m_directory, link, address));
            m_drives[{ link.name, address }].backup
                = m_directory.isEmpty() || !file.exists() ? QDateTime() : file.lastModified();
        }
    }
}

void PlantState::allChanged()
{
    for (const PlantLink &link : std::as_const(m_plant.links)) {
        for (int address : drivesOf(link))
            emit driveChanged(link.name, address);
        emit linkChanged(link.name);
    }
}

} // namespace DriveDesk
