#pragma once

#include <QConcatenateTablesProxyModel>

class QSortFilterProxyModel;
class QStandardItemModel;

namespace DriveDesk {

class ParameterModel;

// The list of groups beside the parameter table: "All parameters" first, then the group rows of
// the parameter model itself, in the drive's order, each with its number of parameters.
class GroupListModel : public QConcatenateTablesProxyModel
{
    Q_OBJECT
public:
    enum Column { GroupColumn, CountColumn, ColumnCount };

    explicit GroupListModel(ParameterModel *model, QObject *parent = nullptr);

    // The group's row in the parameter model (column 0); invalid for "All parameters".
    QModelIndex sourceGroup(const QModelIndex &row) const;
    // The row that shows a group of the parameter model; "All parameters" for an invalid index.
    QModelIndex rowOf(const QModelIndex &sourceGroup) const;

    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    void updateTotal();

    ParameterModel *m_model = nullptr;
    QStandardItemModel *m_all = nullptr; // the one row "All parameters"
    QSortFilterProxyModel *m_groups = nullptr; // the top-level rows of m_model
};

} // namespace DriveDesk
