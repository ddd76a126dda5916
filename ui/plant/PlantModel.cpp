#include "PlantModel.h"

namespace DriveDesk {

namespace {

// internalId of a link row; a drive row carries its link's index + 1.
constexpr quintptr kLinkRow = 0;

} // namespace

PlantModel::PlantModel(const PlantState *state, QObject *parent)
    : QAbstractItemModel(parent)
    , m_state(state)
{
    takeRows();
    connect(m_state, &PlantState::reset, this, [this] {
        beginResetModel();
        takeRows();
        endResetModel();
    });
    connect(m_state, &PlantState::driveAdded, this, &PlantModel::addDrive);
    connect(m_state, &PlantState::driveChanged, this,
            [this](const QString &link, int address) { rowChanged(driveIndex(link, address)); });
    connect(m_state, &PlantState::linkChanged, this, [this](const QString &link) {
        const int row = linkRow(link);
        if (row >= 0)
            rowChanged(index(row, 0));
    });
}

void PlantModel::takeRows()
{
    m_rows.clear();
    for (const PlantLink &link : m_state->plant().links)
        m_rows.append({ link.name, PlantState::drivesOf(link) });
}

// Found by a search: the drive shows as soon as it answered.
void PlantModel::addDrive(const QString &link, int address)
{
    const int row = linkRow(link);
    const PlantLink *plantLink = m_state->plant().link(link);
    if (row < 0 || !plantLink)
        return;
    const QList<int> drives = PlantState::drivesOf(*plantLink);
    const int driveRow = int(drives.indexOf(address));
    if (driveRow < 0 || m_rows.at(row).drives.contains(address))
        return;
    beginInsertRows(index(row, 0), driveRow, driveRow);
    m_rows[row].drives.insert(driveRow, address);
    endInsertRows();
}

int PlantModel::linkRow(const QString &link) const
{
    for (int row = 0; row < m_rows.size(); ++row) {
        if (m_rows.at(row).link == link)
            return row;
    }
    return -1;
}

QModelIndex PlantModel::driveIndex(const QString &link, int address) const
{
    const int row = linkRow(link);
    const int driveRow = row < 0 ? -1 : int(m_rows.at(row).drives.indexOf(address));
    return driveRow < 0 ? QModelIndex() : index(driveRow, 0, index(row, 0));
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
    return row < m_rows.size() ? m_state->plant().link(m_rows.at(row).link) : nullptr;
}

QString PlantModel::stateText(PlantState::Reach reach)
{
    switch (reach) {
    case PlantState::Reach::NotSearched:
        return tr("not searched");
    case PlantState::Reach::Answering:
        return tr("answering");
    case PlantState::Reach::Unreachable:
        return tr("unreachable");
    }
    return {};
}

QModelIndex PlantModel::index(int row, int column, const QModelIndex &parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    if (!parent.isValid())
        return row < m_rows.size() ? createIndex(row, column, kLinkRow) : QModelIndex();
    if (isDrive(parent) || parent.row() >= m_rows.size()
        || row >= m_rows.at(parent.row()).drives.size())
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
        return int(m_rows.size());
    if (isDrive(parent) || parent.column() != 0 || parent.row() >= m_rows.size())
        return 0;
    return int(m_rows.at(parent.row()).drives.size());
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
