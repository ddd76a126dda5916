#pragma once

#include "model/GroupTreeModel.h"
#include "parameters/ParameterComparison.h"

#include <QList>

#include <vector>

namespace DriveDesk {

// A comparison of two sides as a tree: groups in side A's order (then B's others), the rows of
// ComparisonTable below, each with a check box where a value may be written into a side. It
// answers ParameterModel's roles for what ParameterFilterModel reads (groups, addresses, the
// search text), so the compare view searches as the parameter table does.
class ComparisonModel : public GroupTreeModel
{
    Q_OBJECT
public:
    enum Column { IdColumn, NameColumn, SetColumn, AColumn, BColumn, StateColumn, ColumnCount };
    enum Role {
        StateRole = Qt::UserRole + 100, // int: ComparisonRow::State of a row
        DiffersRole, // bool: the row's values differ
    };

    explicit ComparisonModel(QObject *parent = nullptr);

    // Replaces everything; nothing is chosen. `a` and `b` are the descriptions compared, for the
    // groups' names and the search text.
    void setComparison(const ComparisonTable &table, const DriveDescription &a,
                       const DriveDescription &b);
    const ComparisonTable &comparison() const { return m_table; }
    // The column headers: "A: b.json".
    void setSideNames(const QString &a, const QString &b);
    // Raw integers instead of the values as the drive shows them.
    void setShowRawValues(bool raw);
    bool showsRawValues() const { return m_raw; }

    // The rows a user ticked, by address and set.
    QList<ComparisonRow> chosenRows() const;
    void setChosen(const QModelIndex &index, bool chosen);
    void clearChosen();
    // A row whose value may be written into one side or the other (ComparisonRow::isWritableTo):
    // only these have a check box.
    bool isChoosable(const QModelIndex &index) const;

    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    void chosenChanged();

protected:
    int groupCount() const override { return int(m_groups.size()); }
    int rowCountOf(int group) const override
    {
        return int(m_groups[std::size_t(group)].rows.size());
    }

private:
    struct Group
    {
        QString id;
        QString name;
        quint16 address = 0;
        QList<int> rows; // indices into m_table.rows
    };

    const ComparisonRow *rowAt(const QModelIndex &index) const;
    int tableRowAt(const QModelIndex &index) const; // -1 for a group
    QVariant groupData(const Group &group, int column, int role) const;
    QVariant rowData(int tableRow, int column, int role) const;
    QString valueText(const ComparisonRow &row, bool a) const;

    ComparisonTable m_table;
    std::vector<Group> m_groups;
    std::vector<QString> m_searchTexts; // per table row, lower-case
    std::vector<bool> m_chosen; // per table row
    QString m_nameA; // empty until compared
    QString m_nameB;
    bool m_raw = false;
};

} // namespace DriveDesk
