#include "ComparisonFilterModel.h"

#include "ComparisonModel.h"

#include "model/ParameterModel.h"

namespace DriveDesk {

ComparisonFilterModel::ComparisonFilterModel(QObject *parent)
    : ParameterFilterModel(parent)
{ }

void ComparisonFilterModel::setStateShown(ComparisonRow::State state, bool shown)
{
    if (shown == isStateShown(state))
        return;
    m_states = shown ? quint8(m_states | bit(state)) : quint8(m_states & ~bit(state));
    invalidateRowsFilter();
}

void ComparisonFilterModel::setGroup(const QString &groupId)
{
    if (groupId == m_group)
        return;
    m_group = groupId;
    invalidateRowsFilter();
}

void ComparisonFilterModel::setChosenOnly(bool on)
{
    if (on == m_chosenOnly)
        return;
    m_chosenOnly = on;
    invalidateRowsFilter();
}

bool ComparisonFilterModel::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    // A group stays while any of its rows does (recursive filtering).
    if (index.data(ParameterModel::IsGroupRole).toBool())
        return false;
    if (!isStateShown(ComparisonRow::State(index.data(ComparisonModel::StateRole).toInt())))
        return false;
    if (!m_group.isEmpty() && index.data(ParameterModel::GroupIdRole).toString() != m_group)
        return false;
    if (m_chosenOnly && index.data(Qt::CheckStateRole).toInt() != Qt::Checked)
        return false;
    return ParameterFilterModel::filterAcceptsRow(sourceRow, sourceParent);
}

} // namespace DriveDesk
