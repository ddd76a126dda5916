#include "ParameterModel.h"

#include "parameters/ParameterId.h"
#include "state/EditCheck.h"
#include "parameters/SetList.h"

namespace DriveDesk {

ParameterModel::ParameterModel(DriveState *state, QObject *parent)
    : GroupTreeModel(parent)
    , m_state(state ? state : new DriveState(this))
{
    connect(m_state, &DriveState::aboutToReset, this, [this] {
        beginResetModel();
        m_groups.clear(); // the rows point into the state about to change
    });
    connect(m_state, &DriveState::reset, this, [this] {
        rebuild();
        endResetModel();
    });
    connect(m_state, &DriveState::cellsChanged, this, &ParameterModel::onCellsChanged);
    connect(m_state, &DriveState::parameterChanged, this, [this](quint16 address) {
        if (ParameterRow *row = rowAt(address)) {
            for (int cell = 0; cell < row->state().cellCount(); ++cell)
                row->invalidate(cell);
        }
        emitRowChanged(address);
    });
    connect(m_state, &DriveState::staleChanged, this, [this] {
        emitAllChanged({ Qt::ForegroundRole, Qt::FontRole, Qt::ToolTipRole, StaleRole });
    });
    connect(m_state, &DriveState::passwordLevelChanged, this, [this] { emitAllChanged(); });
    connect(m_state, &DriveState::activeSetChanged, this, [this] {
        emit headerDataChanged(Qt::Horizontal, FirstSetColumn, LastSetColumn);
    });
    rebuild();
}

void ParameterModel::rebuild()
{
    m_groups.clear();
    m_groups.resize(std::size_t(m_state->groupCount()));
    for (int g = 0; g < m_state->groupCount(); ++g) {
        Group &group = m_groups[std::size_t(g)];
        group.rows.reserve(std::size_t(m_state->parameterCount(g)));
        for (int row = 0; row < m_state->parameterCount(g); ++row) {
            group.rows.emplace_back(m_state->parameterAt(g, row));
            group.rows.back().searchText(m_raw); // built now, so that a keystroke only compares
        }
    }
}

void ParameterModel::onCellsChanged(quint16 address, int firstCell, int lastCell)
{
    ParameterRow *row = rowAt(address);
    if (!row)
        return;
    for (int cell = firstCell; cell <= lastCell; ++cell)
        row->invalidate(cell);
    emit dataChanged(indexOf(address, columnOfSet(firstCell)),
                     indexOf(address, columnOfSet(lastCell)));
}

const ParameterRow *ParameterModel::rowAt(const QModelIndex &index) const
{
    const int group = groupOf(index);
    return group < 0 ? nullptr : &m_groups[std::size_t(group)].rows[std::size_t(index.row())];
}

ParameterRow *ParameterModel::rowAt(quint16 address)
{
    const DriveState::Location location = m_state->locationOf(address);
    if (location.group < 0 || std::size_t(location.group) >= m_groups.size())
        return nullptr;
    return &m_groups[std::size_t(location.group)].rows[std::size_t(location.row)];
}

const ParameterRow *ParameterModel::rowAt(quint16 address) const
{
    return const_cast<ParameterModel *>(this)->rowAt(address);
}

bool ParameterModel::isStale(const ParameterRow &row) const
{
    return m_state->isStale(row.state());
}

bool ParameterModel::isAboveLevel(const ParameterRow &row) const
{
    return EditCheck::isAboveLevel(row.properties(), m_state->passwordLevel());
}

bool ParameterModel::isEditable(const ParameterRow &row) const
{
    return m_state->isEditable(row.state());
}

bool ParameterModel::requestWrite(quint16 address, quint8 setMask, qint32 raw, QString *error)
{
    const QString refusal = m_state->writeRefusal(address, setMask, raw);
    if (!refusal.isEmpty()) {
        if (error)
            *error = refusal;
        return false;
    }
    emit valueEdited(address, SetList::setsWritten(*m_state->parameter(address), setMask), raw);
    return true;
}

void ParameterModel::setShowRawValues(bool raw)
{
    if (raw == m_raw)
        return;
    m_raw = raw;
    emitAllChanged();
}

void ParameterModel::setFavourites(const QSet<quint16> &addresses)
{
    if (addresses == m_favourites)
        return;
    const QSet<quint16> changed = (m_favourites - addresses) + (addresses - m_favourites);
    m_favourites = addresses;
    for (quint16 address : changed)
        emitRowChanged(address);
    emit favouritesChanged();
}

void ParameterModel::setFavourite(quint16 address, bool favourite)
{
    if (favourite == m_favourites.contains(address))
        return;
    if (favourite)
        m_favourites.insert(address);
    else
        m_favourites.remove(address);
    emitRowChanged(address);
    emit favouritesChanged();
}

void ParameterModel::toggleFavourite(quint16 address)
{
    setFavourite(address, !isFavourite(address));
}

void ParameterModel::emitRowChanged(quint16 address)
{
    const QModelIndex first = indexOf(address, IdColumn);
    if (first.isValid())
        emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
}

void ParameterModel::emitAllChanged(const QList<int> &roles)
{
    for (std::size_t g = 0; g < m_groups.size(); ++g) {
        const int rows = int(m_groups[g].rows.size());
        if (rows == 0)
            continue;
        emit dataChanged(rowIndex(int(g), 0, 0), rowIndex(int(g), rows - 1, ColumnCount - 1),
                         roles);
    }
}

QModelIndex ParameterModel::indexOf(quint16 address, int column) const
{
    const DriveState::Location location = m_state->locationOf(address);
    if (location.group < 0 || std::size_t(location.group) >= m_groups.size() || column < 0
        || column >= ColumnCount)
        return {};
    return rowIndex(location.group, location.row, column);
}

QModelIndex ParameterModel::valueIndex(quint16 address, int set) const
{
    const ParameterState *parameter = m_state->find(address);
    if (!parameter || set < 0 || set >= kParameterSets)
        return {};
    return indexOf(address, columnOfSet(parameter->cellOf(set)));
}

int ParameterModel::setOfColumn(int column)
{
    return column >= FirstSetColumn && column <= LastSetColumn ? column - FirstSetColumn : -1;
}

int ParameterModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

} // namespace DriveDesk
