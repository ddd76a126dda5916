#pragma once

#include <QAbstractItemModel>

namespace DriveDesk {

// A tree of two levels, groups and the rows of each, as the parameter table and the compare
// window show a drive: the indexes and their parents, once for both models. A group's index
// carries the internal id 0, a row's its group's row + 1. A subclass says how many groups and
// rows there are, and its columns.
class GroupTreeModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    using QAbstractItemModel::QAbstractItemModel;

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    bool hasChildren(const QModelIndex &parent = {}) const override;

protected:
    virtual int groupCount() const = 0;
    virtual int rowCountOf(int group) const = 0;

    // A valid index of a group (not of a row).
    static bool isGroup(const QModelIndex &index)
    {
        return index.isValid() && index.internalId() == 0;
    }
    // The group of a row's index; -1 for a group's index or an invalid one.
    static int groupOf(const QModelIndex &index)
    {
        return index.isValid() && index.internalId() != 0 ? int(index.internalId() - 1) : -1;
    }
    // The index of row `row` of group `group`, unchecked.
    QModelIndex rowIndex(int group, int row, int column) const
    {
        return createIndex(row, column, quintptr(group) + 1);
    }
};

} // namespace DriveDesk
