#include "PlantModel.h"

#include <QFileInfo>

#include <algorithm>

namespace DriveDesk {

namespace {

// internalId of a link row; a drive row carries its link's index + 1.
constexpr quintptr kLinkRow = 0;

bool answered(PlantDrive::Outcome outcome)
{
    switch (outcome) {
    case PlantDrive::Outcome::Found:
    case PlantDrive::Outcome::Saved:
    case PlantDrive::Outcome::Equal:
    case PlantDrive::Outcome::Different:
    case PlantDrive::Outcome::OtherKind:
    case PlantDrive::Outcome::Written:
    case PlantDrive::Outcome::Unchanged:
    case PlantDrive::Outcome::Planned:
        return true;
    default:
        return false;
    }
}

} // namespace

PlantModel::PlantModel(QObject *parent)
    : QAbstractItemModel(parent)
{ }

void PlantModel::setPlant(const Plant &plant)
{
    beginResetModel();
    m_plant = plant;
    readBackupTimes();
    endResetModel();
}

void PlantModel::openPlant(const Plant &plant, const QString &backupFolder)
{
    beginResetModel();
    m_plant = plant;
    m_known.clear();
    m_links.clear();
    m_directory = backupFolder;
    readBackupTimes();
    endResetModel();
}

void PlantModel::setBackupFolder(const QString &directory)
{
    m_directory = directory;
    readBackupTimes();
    allChanged();
}

// Every row, without a reset: the view keeps what is expanded and selected.
void PlantModel::allChanged()
{
    if (rowCount() > 0)
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    for (int row = 0; row < rowCount(); ++row) {
        const QModelIndex link = index(row, 0);
        if (rowCount(link) > 0)
            emit dataChanged(index(0, 0, link), index(rowCount(link) - 1, ColumnCount - 1, link));
    }
}

QList<int> PlantModel::rowsOf(const PlantLink &link) const
{
    if (link.protocol == Protocol::Hsp5)
        return { -1 };
    QList<int> addresses = link.addresses;
    std::sort(addresses.begin(), addresses.end());
    return addresses;
}

QString PlantModel::key(const QString &link, int address)
{
    PlantDrive drive;
    drive.link = link;
    drive.address = address;
    return drive.name();
}

void PlantModel::readBackupTimes()
{
    for (const PlantLink &link : std::as_const(m_plant.links)) {
        for (int address : rowsOf(link)) {
            const QFileInfo file(PlantRun::fileFor(m_directory, link, address));
            m_known[key(link.name, address)].backup
                = m_directory.isEmpty() || !file.exists() ? QDateTime() : file.lastModified();
        }
    }
}

void PlantModel::startJob()
{
    for (Known &known : m_known) {
        known.result.reset();
        known.percent = -1;
    }
    for (Known &link : m_links) {
        link.result.reset();
        link.percent = -1;
    }
    allChanged();
}

void PlantModel::setProgress(const QString &link, int address, int percent, const QString &what)
{
    const PlantLink *plantLink = m_plant.link(link);
    if (!plantLink)
        return;
    const bool ofLink = address < 0 && plantLink->protocol != Protocol::Hsp5;
    Known &known = ofLink ? m_links[link] : m_known[key(link, address)];
    known.percent = std::clamp(percent, 0, 100);
    known.what = what;
    rowChanged(ofLink ? index(int(plantLink - m_plant.links.constData()), 0)
                      : driveIndex(link, address));
}

void PlantModel::setDriveDone(const PlantDrive &drive)
{
    PlantLink *link = m_plant.link(drive.link);
    if (!link)
        return;
    const int linkRow = int(link - m_plant.links.data());
    if (drive.address < 0 && link->protocol != Protocol::Hsp5) {
        // The bus as a whole: no drive answered, it could not be opened, the search stopped.
        Known &known = m_links[drive.link];
        known.result = drive;
        known.percent = -1;
        if (drive.outcome == PlantDrive::Outcome::Unreachable)
            known.state = DriveState::Unreachable;
        rowChanged(index(linkRow, 0));
        return;
    }
    if (link->protocol != Protocol::Hsp5 && !link->addresses.contains(drive.address)) {
        // Found by a search: the drive shows as soon as it answered.
        const QList<int> rows = rowsOf(*link);
        const int row
            = int(std::lower_bound(rows.cbegin(), rows.cend(), drive.address) - rows.cbegin());
        beginInsertRows(index(linkRow, 0), row, row);
        link->addresses.append(drive.address);
        endInsertRows();
    }
    Known &known = m_known[drive.name()];
    known.result = drive;
    known.percent = -1;
    if (drive.outcome == PlantDrive::Outcome::Unreachable)
        known.state = DriveState::Unreachable;
    else if (answered(drive.outcome))
        known.state = DriveState::Answering;
    if (drive.outcome == PlantDrive::Outcome::Found)
        known.identification = drive.identification;
    updateLinkState(*link);
    rowChanged(driveIndex(drive.link, drive.address));
    rowChanged(index(linkRow, 0));
}

void PlantModel::updateLinkState(const PlantLink &link)
{
    const QList<int> rows = rowsOf(link);
    bool anyAnswering = false;
    bool allUnreachable = !rows.isEmpty();
    for (int address : rows) {
        const DriveState state = m_known.value(key(link.name, address)).state;
        anyAnswering = anyAnswering || state == DriveState::Answering;
        allUnreachable = allUnreachable && state == DriveState::Unreachable;
    }
    Known &known = m_links[link.name];
    if (anyAnswering)
        known.state = DriveState::Answering;
    else if (allUnreachable)
        known.state = DriveState::Unreachable;
}

void PlantModel::endJob()
{
    for (Known &known : m_known)
        known.percent = -1;
    for (Known &known : m_links)
        known.percent = -1;
    readBackupTimes();
    allChanged();
}

QModelIndex PlantModel::driveIndex(const QString &link, int address) const
{
    for (int row = 0; row < m_plant.links.size(); ++row) {
        if (m_plant.links.at(row).name != link)
            continue;
        const int driveRow = int(rowsOf(m_plant.links.at(row)).indexOf(address));
        return driveRow < 0 ? QModelIndex() : index(driveRow, 0, index(row, 0));
    }
    return {};
}

bool PlantModel::isDrive(const QModelIndex &index) const
{
    return index.isValid() && index.internalId() != kLinkRow;
}

const PlantLink *PlantModel::linkOf(const QModelIndex &index) const
{
    if (!index.isValid())
        return nullptr;
    const int row = isDrive(index) ? int(index.internalId() - 1) : index.row();
    return row < m_plant.links.size() ? &m_plant.links.at(row) : nullptr;
}

std::optional<PlantDrive> PlantModel::lastResult(const QString &link, int address) const
{
    return m_known.value(key(link, address)).result;
}

PlantModel::DriveState PlantModel::driveState(const QString &link, int address) const
{
    return m_known.value(key(link, address)).state;
}

QString PlantModel::stateText(DriveState state)
{
    switch (state) {
    case DriveState::NotSearched:
        return tr("not searched");
    case DriveState::Answering:
        return tr("answering");
    case DriveState::Unreachable:
        return tr("unreachable");
    }
    return {};
}

QModelIndex PlantModel::index(int row, int column, const QModelIndex &parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    if (!parent.isValid())
        return row < m_plant.links.size() ? createIndex(row, column, kLinkRow) : QModelIndex();
    if (isDrive(parent) || parent.row() >= m_plant.links.size()
        || row >= rowsOf(m_plant.links.at(parent.row())).size())
        return {};
    return createIndex(row, column, quintptr(parent.row()) + 1);
}

QModelIndex PlantModel::parent(const QModelIndex &child) const
{
    if (!isDrive(child))
        return {};
    return createIndex(int(child.internalId() - 1), 0, kLinkRow);
}

int PlantModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return int(m_plant.links.size());
    if (isDrive(parent) || parent.column() != 0 || parent.row() >= m_plant.links.size())
        return 0;
    return int(rowsOf(m_plant.links.at(parent.row())).size());
}

int PlantModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

void PlantModel::rowChanged(const QModelIndex &index)
{
    if (index.isValid())
        emit dataChanged(index.siblingAtColumn(0), index.siblingAtColumn(ColumnCount - 1));
}

} // namespace DriveDesk
