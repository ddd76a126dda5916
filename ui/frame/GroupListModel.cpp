#include "GroupListModel.h"

#include "model/ParameterModel.h"

#include <QSortFilterProxyModel>
#include <QStandardItemModel>

namespace DriveDesk {

namespace {

// The group rows of the parameter model without their parameters, the second column holding
// how many parameters each group has.
class GroupCountModel : public QSortFilterProxyModel
{
public:
    explicit GroupCountModel(ParameterModel *model, QObject *parent)
        : QSortFilterProxyModel(parent)
    {
        setSourceModel(model);
        // A group gaining or losing parameters changes its count.
        const auto countChanged = [this](const QModelIndex &sourceParent) {
            const QModelIndex group = mapFromSource(sourceParent);
            if (sourceParent.isValid() && group.isValid()) {
                const QModelIndex count = group.siblingAtColumn(GroupListModel::CountColumn);
                emit dataChanged(count, count, { Qt::DisplayRole });
            }
        };
        connect(model, &QAbstractItemModel::rowsInserted, this, countChanged);
        connect(model, &QAbstractItemModel::rowsRemoved, this, countChanged);
    }

    QVariant data(const QModelIndex &index, int role) const override
    {
        if (!index.isValid())
            return {};
        const QModelIndex group = mapToSource(index.siblingAtColumn(0));
        if (role == Qt::FontRole)
            return {}; // plain here: only "All parameters" stands out in the list
        if (index.column() == GroupListModel::CountColumn) {
            if (role == Qt::DisplayRole)
                return sourceModel()->rowCount(group);
            if (role == Qt::TextAlignmentRole)
                return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        }
        return group.data(role);
    }

    Qt::ItemFlags flags(const QModelIndex &index) const override
    {
        return index.isValid() ? Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemNeverHasChildren
                               : Qt::NoItemFlags;
    }

protected:
    bool filterAcceptsRow(int, const QModelIndex &sourceParent) const override
    {
        return !sourceParent.isValid();
    }

    bool filterAcceptsColumn(int sourceColumn, const QModelIndex &) const override
    {
        return sourceColumn < GroupListModel::ColumnCount;
    }
};

} // namespace

GroupListModel::GroupListModel(ParameterModel *model, QObject *parent)
    : QConcatenateTablesProxyModel(parent)
    , m_model(model)
{
    m_all = new QStandardItemModel(1, ColumnCount, this);
    auto *all = new QStandardItem(tr("All parameters"));
    QFont bold = all->font();
    bold.setBold(true);
    all->setFont(bold);
    all->setEditable(false);
    m_all->setItem(0, GroupColumn, all);
    auto *total = new QStandardItem;
    total->setEditable(false);
    total->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_all->setItem(0, CountColumn, total);
    m_groups = new GroupCountModel(model, this);
    addSourceModel(m_all);
    addSourceModel(m_groups);

    connect(m_model, &QAbstractItemModel::modelReset, this, &GroupListModel::updateTotal);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &GroupListModel::updateTotal);
    connect(m_model, &QAbstractItemModel::rowsRemoved, this, &GroupListModel::updateTotal);
    updateTotal();
}

QModelIndex GroupListModel::sourceGroup(const QModelIndex &row) const
{
    if (!row.isValid())
        return {};
    const QModelIndex source = mapToSource(row.siblingAtColumn(GroupColumn));
    return source.model() == m_groups ? m_groups->mapToSource(source) : QModelIndex();
}

QModelIndex GroupListModel::rowOf(const QModelIndex &sourceGroup) const
{
    const QModelIndex source = sourceGroup.isValid()
        ? m_groups->mapFromSource(sourceGroup.siblingAtColumn(0))
        : m_all->index(0, GroupColumn);
    return mapFromSource(source);
}

QVariant GroupListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QConcatenateTablesProxyModel::headerData(section, orientation, role);
    switch (section) {
    case GroupColumn:
        return tr("Group");
    case CountColumn:
        return tr("Parameters");
    default:
        return {};
    }
}

void GroupListModel::updateTotal()
{
    int total = 0;
    for (int row = 0; row < m_model->rowCount(); ++row)
        total += m_model->rowCount(m_model->index(row, 0));
    m_all->setData(m_all->index(0, CountColumn), total, Qt::DisplayRole);
}

} // namespace DriveDesk
