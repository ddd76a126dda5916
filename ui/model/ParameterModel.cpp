#include "ParameterModel.h"

#include "parameters/ParameterAccess.h"
#include "parameters/ParameterId.h"
#include "parameters/SetList.h"
#include "session/ValueChange.h"

#include <QDateTime>

#include <algorithm>

namespace DriveDesk {

ParameterModel::ParameterModel(QObject *parent)
    : GroupTreeModel(parent)
{ }

void ParameterModel::setDescription(const DriveDescription &drive)
{
    beginResetModel();
    m_groups.clear();
    m_locations.clear();
    m_drive = drive;
    m_drive.groups = {};
    m_groups.reserve(std::size_t(drive.groups.size()));
    m_locations.reserve(drive.parameterCount());
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    for (const GroupDescription &source : drive.groups) {
        Group group;
        group.description = source;
        group.description.parameters = {};
        group.rows.reserve(std::size_t(source.parameters.size()));
        const int groupRow = int(m_groups.size());
        for (const ParameterDescription &parameter : source.parameters) {
            m_locations.insert(parameter.address, { groupRow, int(group.rows.size()) });
            group.rows.emplace_back(parameter,
                                    ParameterId::format(parameter.address,
                                                        GroupAddress{ source.id, source.address }));
            group.rows.back().searchText(m_raw); // built now, so that a keystroke only compares
            const auto &values = parameter.values;
            if (std::any_of(values.begin(), values.end(), [](const auto &v) { return v.has_value(); }))
                group.rows.back().markRead(now);
        }
        m_groups.push_back(std::move(group));
    }
    endResetModel();
}

DriveDescription ParameterModel::description() const
{
    DriveDescription drive = m_drive;
    for (const Group &group : m_groups) {
        GroupDescription description = group.description;
        description.parameters.reserve(qsizetype(group.rows.size()));
        for (const ParameterRow &row : group.rows)
            description.parameters << row.description();
        drive.groups << description;
    }
    return drive;
}

void ParameterModel::clear()
{
    setDescription({});
}

const ParameterRow *ParameterModel::rowAt(const QModelIndex &index) const
{
    const int group = groupOf(index);
    return group < 0 ? nullptr : &m_groups[std::size_t(group)].rows[std::size_t(index.row())];
}

ParameterRow *ParameterModel::rowAt(quint16 address)
{
    const auto it = m_locations.constFind(address);
    if (it == m_locations.constEnd())
        return nullptr;
    return &m_groups[std::size_t(it->group)].rows[std::size_t(it->row)];
}

const ParameterRow *ParameterModel::rowAt(quint16 address) const
{
    return const_cast<ParameterModel *>(this)->rowAt(address);
}

const ParameterDescription *ParameterModel::parameter(quint16 address) const
{
    const ParameterRow *row = rowAt(address);
    return row ? &row->description() : nullptr;
}

bool ParameterModel::setValue(quint16 address, int set, qint32 raw)
{
    ParameterRow *row = rowAt(address);
    if (!row || set < 0 || set >= kParameterSets)
        return false;
    const int cell = row->cellOf(set);
    const bool wasStale = m_staleSinceMs != 0 && isStale(*row);
    row->markRead(QDateTime::currentMSecsSinceEpoch());
    if (row->setValue(cell, raw) || wasStale) {
        if (wasStale) {
            emitRowChanged(address);
        } else {
            const QModelIndex changed = indexOf(address, columnOfSet(cell));
            emit dataChanged(changed, changed);
        }
    }
    return true;
}

void ParameterModel::setStaleSince(qint64 msecsSinceEpoch)
{
    if (msecsSinceEpoch == m_staleSinceMs)
        return;
    m_staleSinceMs = msecsSinceEpoch;
    emitAllChanged({ Qt::ForegroundRole, Qt::FontRole, Qt::ToolTipRole, StaleRole });
}

bool ParameterModel::isStale(quint16 address) const
{
    const ParameterRow *row = rowAt(address);
    return row && isStale(*row);
}

bool ParameterModel::isStale(const ParameterRow &row) const
{
    return m_staleSinceMs != 0 && row.readAtMs() != 0 && row.readAtMs() < m_staleSinceMs;
}

bool ParameterModel::setValues(quint16 address, quint8 setMask, qint32 raw)
{
    ParameterRow *row = rowAt(address);
    if (!row || setMask == 0)
        return false;
    for (int set = 0; set < kParameterSets; ++set) {
        if (setMask & (1u << set))
            setValue(address, set, raw);
    }
    return true;
}

bool ParameterModel::putValue(quint16 address, int set, std::optional<qint32> raw)
{
    ParameterRow *row = rowAt(address);
    if (!row || set < 0 || set >= kParameterSets)
        return false;
    const int cell = row->cellOf(set);
    const bool changed = row->setValue(cell, raw);
    if (row->clearEditState(cell) || changed) {
        const QModelIndex index = indexOf(address, columnOfSet(cell));
        emit dataChanged(index, index);
    }
    return true;
}

std::optional<qint32> ParameterModel::value(quint16 address, int set) const
{
    const ParameterRow *row = rowAt(address);
    if (!row || set < 0 || set >= kParameterSets)
        return std::nullopt;
    return row->value(row->cellOf(set));
}

bool ParameterModel::isAboveLevel(const ParameterRow &row) const
{
    const ParameterProperties &properties = row.properties();
    return !isReadable(properties, m_level)
        || (!properties.isReadOnly() && !isWritable(properties, m_level));
}

bool ParameterModel::isEditable(const ParameterRow &row) const
{
    return isWritable(row.properties(), m_level);
}

bool ParameterModel::isAboveLevel(quint16 address) const
{
    const ParameterRow *row = rowAt(address);
    return row && isAboveLevel(*row);
}

bool ParameterModel::isEditable(quint16 address) const
{
    const ParameterRow *row = rowAt(address);
    return row && isEditable(*row);
}

QString ParameterModel::editRefusal(const ParameterRow &row) const
{
    if (row.properties().isReadOnly())
        return tr("%1 is read-only").arg(row.id());
    if (isAboveLevel(row)) {
        const PasswordLevel needed
            = std::max(row.properties().readLevel(), row.properties().writeLevel());
        return tr("%1 needs password level %2 (in force: %3)")
            .arg(row.id(), passwordLevelName(needed), passwordLevelName(m_level));
    }
    return {};
}

bool ParameterModel::requestWrite(quint16 address, quint8 setMask, qint32 raw, QString *error)
{
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    const ParameterRow *row = rowAt(address);
    if (!row)
        return fail(tr("this drive has no parameter %1").arg(ParameterId::hexAddress(address)));
    if (const QString refusal = editRefusal(*row); !refusal.isEmpty())
        return fail(refusal);
    if (setMask == 0)
        return fail(tr("%1: no set chosen").arg(row->id()));
    if (!row->format().isWithinLimits(raw))
        return fail(tr("%1: %2").arg(row->id(), row->format().limitsProblem(raw)));
    emit valueEdited(address, SetList::setsWritten(row->description(), setMask), raw);
    return true;
}

EditText ParameterModel::editText(quint16 address) const
{
    const ParameterRow *row = rowAt(address);
    return row ? EditText(row->id(), &row->description())
               : EditText(ParameterId::hexAddress(address), nullptr);
}

void ParameterModel::setPasswordLevel(PasswordLevel level)
{
    if (level == m_level)
        return;
    m_level = level;
    emitAllChanged();
    emit passwordLevelChanged(level);
}

void ParameterModel::setActiveSet(int set)
{
    if (set < 0 || set >= kParameterSets)
        set = -1;
    if (set == m_activeSet)
        return;
    m_activeSet = set;
    emit headerDataChanged(Qt::Horizontal, FirstSetColumn, LastSetColumn);
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
    const auto it = m_locations.constFind(address);
    if (it == m_locations.constEnd() || column < 0 || column >= ColumnCount)
        return {};
    return rowIndex(it->group, it->row, column);
}

QModelIndex ParameterModel::valueIndex(quint16 address, int set) const
{
    const ParameterRow *row = rowAt(address);
    if (!row || set < 0 || set >= kParameterSets)
        return {};
    return indexOf(address, columnOfSet(row->cellOf(set)));
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
