#pragma once

#include "CellDecoration.h"
#include "GroupTreeModel.h"
#include "ParameterRow.h"

#include "state/DriveState.h"

#include <QHash>
#include <QSet>

#include <vector>

namespace DriveDesk {

// A DriveState as a tree for Qt's views: groups in the drive's order, their parameters below,
// values shown as the drive shows them (scaled with unit, or the plaintext), edit states as
// icons and colours. The model holds no values of its own and never talks to the drive: it
// follows the state's signals, and edits leave as valueEdited(). Lives in the GUI thread.
class ParameterModel : public GroupTreeModel
{
    Q_OBJECT
public:
    enum Column {
        IdColumn,
        NameColumn,
        FirstSetColumn, // set 0; the one value of a parameter that is not set-programmable
        LastSetColumn = FirstSetColumn + kParameterSets - 1,
        MinimumColumn,
        MaximumColumn,
        DefaultColumn,
        UnitColumn,
        AccessColumn,
        ColumnCount
    };

    enum Role {
        RawValueRole = Qt::UserRole + 1, // qint32 of a value, limit or default cell
        AddressRole, // quint16: the parameter's address, or the group's
        SetRole, // int: the set of a value column, -1 elsewhere
        EditStateRole, // EditState of a value cell
        EditableRole, // bool: the user may change this parameter
        FavouriteRole, // bool; settable on any cell of a parameter row
        IsGroupRole, // bool
        DiffersFromDefaultRole, // bool: a user setting (isUserSetting) whose value in some set
                                // differs from the default
        AboveLevelRole, // bool: needs a higher password level than the one in force
        SearchTextRole, // QString, lower-case: what the search matches
        DescriptionRole, // ParameterDescription with the values held now
        RawModeRole, // bool: values are shown raw
        GroupIdRole, // QString: a group row's id ("ru")
        EditRefusalRole, // QString: why the user may not change this parameter; empty if he may
        StaleRole, // bool: a value cell not read since the drive stopped answering
        LastReadRole, // QDateTime: when a value of the parameter last came from the drive
    };

    // Shows `state` (which outlives the model), or a state of its own when none is given.
    explicit ParameterModel(DriveState *state = nullptr, QObject *parent = nullptr);

    DriveState *state() const { return m_state; }

    // The user edited a cell: checks the write (DriveState::writeRefusal) and emits
    // valueEdited() with the sets SetList::setsWritten() gives. The reason when refused.
    bool requestWrite(quint16 address, quint8 setMask, qint32 raw, QString *error = nullptr);

    void setShowRawValues(bool raw);
    bool showsRawValues() const { return m_raw; }

    QSet<quint16> favourites() const { return m_favourites; }
    void setFavourites(const QSet<quint16> &addresses);
    void setFavourite(quint16 address, bool favourite);
    void toggleFavourite(quint16 address);
    bool isFavourite(quint16 address) const { return m_favourites.contains(address); }

    QModelIndex indexOf(quint16 address, int column = IdColumn) const;
    // The cell of the set's value (set 0 for parameters that are not set-programmable).
    QModelIndex valueIndex(quint16 address, int set) const;
    static int columnOfSet(int set) { return FirstSetColumn + set; }
    static int setOfColumn(int column); // -1 for columns that hold no value

    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    // The user changed a value: write it.
    void valueEdited(quint16 address, quint8 setMask, qint32 raw);
    void favouritesChanged();

protected:
    int groupCount() const override { return int(m_groups.size()); }
    int rowCountOf(int group) const override
    {
        return int(m_groups[std::size_t(group)].rows.size());
    }

private:
    struct Group
    {
        std::vector<ParameterRow> rows;
    };

    void rebuild();
    const ParameterRow *rowAt(const QModelIndex &index) const;
    ParameterRow *rowAt(quint16 address);
    const ParameterRow *rowAt(quint16 address) const;
    QVariant groupData(int group, int column, int role) const;
    QVariant parameterData(const ParameterRow &row, int column, int role) const;
    QVariant displayText(const ParameterRow &row, int column) const;
    QVariant toolTip(const ParameterRow &row, int column) const;
    QString accessText(const ParameterRow &row) const;
    QString valueText(const ParameterRow &row, qint32 raw) const; // as the value cells show it
    bool isAboveLevel(const ParameterRow &row) const;
    bool isStale(const ParameterRow &row) const;
    bool isEditable(const ParameterRow &row) const;
    void onCellsChanged(quint16 address, int firstCell, int lastCell);
    void emitRowChanged(quint16 address);
    void emitAllChanged(const QList<int> &roles = {});

    DriveState *m_state = nullptr;
    std::vector<Group> m_groups;
    QSet<quint16> m_favourites;
    bool m_raw = false;
    CellDecoration m_decoration;
};

} // namespace DriveDesk
