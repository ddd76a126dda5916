#include "GroupTreeModel.h"

namespace DriveDesk {

QModelIndex GroupTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (row < 0 || column < 0 || column >= columnCount(parent))
        return {};
    if (!parent.isValid())
        return row < groupCount() ? createIndex(row, column, quintptr(0)) : QModelIndex();
    // Rows have no children; a group's are below its first column.
    if (!isGroup(parent) || parent.column() != 0 || row >= rowCountOf(parent.row()))
        return {};
    return rowIndex(parent.row(), row, column);
}

QModelIndex GroupTreeModel::parent(const QModelIndex &child) const
{
    const int group = groupOf(child);
    return group < 0 ? QModelIndex() : createIndex(group, 0, quintptr(0));
}

int GroupTreeModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return groupCount();
    if (!isGroup(parent) || parent.column() != 0)
        return 0;
    return rowCountOf(parent.row());
}

bool GroupTreeModel::hasChildren(const QModelIndex &parent) const
{
    return rowCount(parent) > 0;
}

} // namespace DriveDesk
