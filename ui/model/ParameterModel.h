#pragma once

#include "CellDecoration.h"
#include "GroupTreeModel.h"
#include "ParameterRow.h"

#include "parameters/DriveDescription.h"
#include "parameters/PasswordLevel.h"
#include "session/EditText.h"

#include <QHash>
#include <QSet>

#include <vector>

namespace DriveDesk {

struct WriteOutcome;

// The parameters of one drive as a tree: groups in the drive's order, their parameters below.
// Values are held raw and shown as the drive shows them (scaled with unit, or the plaintext).
// The model never talks to the drive: edits leave as valueEdited(), values arrive through
// setValue(). Lives in the GUI thread.
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

    explicit ParameterModel(QObject *parent = nullptr);

    // Replaces everything (a model reset). Favourites stay; edit states are dropped.
    void setDescription(const DriveDescription &drive);
    // The description with the values held now (pending writes not included).
    DriveDescription description() const;
    void clear();

    // What the drive reported for one set. Emits dataChanged for that one cell, and only when
    // the value changed. A parameter that is not set-programmable takes any set as its one
    // value. False for an address the description does not hold or a set outside 0..7.
    bool setValue(quint16 address, int set, qint32 raw);
    // The same value for every set in the mask (a read over several sets).
    bool setValues(quint16 address, quint8 setMask, qint32 raw);
    std::optional<qint32> value(quint16 address, int set) const;
    // An open parameter file's value after an edit or its undo: stored as it is, a value not
    // read (nothing) included, and the cell's edit state dropped. Not a reading from a drive.
    bool putValue(quint16 address, int set, std::optional<qint32> raw);

    // The drive stopped answering at `msecsSinceEpoch`: the values not read since are stale,
    // shown greyed and italic with when they were last read. 0: the drive answers, nothing is
    // stale. A value read later is fresh again.
    void setStaleSince(qint64 msecsSinceEpoch);
    qint64 staleSince() const { return m_staleSinceMs; }
    bool isStale(quint16 address) const;
    const ParameterDescription *parameter(quint16 address) const;

    // Asks for a write: checks that the user may edit the parameter and that the value lies
    // within its limits, and emits valueEdited() with the sets SetList::setsWritten() gives.
    // The reason when refused. The cells show pending once the edit is under way (markPending).
    bool requestWrite(quint16 address, quint8 setMask, qint32 raw, QString *error = nullptr);
    // How messages name the parameter and its values (its id as the table shows it).
    EditText editText(quint16 address) const;
    // An edit's outcome in the cells: failed with the drive's reason, or the value read back
    // (written when it is what was asked for). A superseded edit (a later one of the same
    // parameter will write and read these cells again) only stores the values read, so the
    // later one's cells never show a failure that is not theirs.
    void showOutcome(const WriteOutcome &outcome, bool superseded = false);
    void markUnknown(quint16 address, quint8 setMask, const QString &reason);
    // Edit states of the cells of the sets in the mask, as the edit path reports them.
    void markPending(quint16 address, quint8 setMask, qint32 raw);
    void markWritten(quint16 address, quint8 setMask);
    void markFailed(quint16 address, quint8 setMask, const QString &reason);
    // An open parameter file's cells whose values differ from what the file holds on disk.
    void markChanged(quint16 address, quint8 setMask);
    // A value read back after a write: stored, and the cell written when it equals what was
    // asked for, failed (saying what the drive holds) when it does not. A parameter whose
    // read-back may differ by its nature (readBackMayDiffer) is written whatever it reads.
    void confirmReadBack(quint16 address, int set, qint32 raw);
    void clearEditStates();
    // Drops the edit states of the sets in the mask: nothing was written there after all.
    void clearEditState(quint16 address, quint8 setMask);
    EditState editState(quint16 address, int set) const;

    // Until told otherwise nothing is locked by level: the drive refuses what it must.
    void setPasswordLevel(PasswordLevel level);
    PasswordLevel passwordLevel() const { return m_level; }
    // The parameter needs a higher level to be read, or (unless read-only) to be written.
    bool isAboveLevel(quint16 address) const;
    // Not read-only and within the level in force.
    bool isEditable(quint16 address) const;

    // The set the drive runs with (Fr.02), marked in its column's header; -1: not known.
    void setActiveSet(int set);
    int activeSet() const { return m_activeSet; }

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
    void passwordLevelChanged(DriveDesk::PasswordLevel level);

protected:
    int groupCount() const override { return int(m_groups.size()); }
    int rowCountOf(int group) const override
    {
        return int(m_groups[std::size_t(group)].rows.size());
    }

private:
    struct Group
    {
        GroupDescription description; // without its parameters: they live in `rows`
        std::vector<ParameterRow> rows;
    };
    struct Location
    {
        int group = -1;
        int row = -1;
    };

    const ParameterRow *rowAt(const QModelIndex &index) const;
    ParameterRow *rowAt(quint16 address);
    const ParameterRow *rowAt(quint16 address) const;
    QVariant groupData(const Group &group, int column, int role) const;
    QVariant parameterData(const ParameterRow &row, int column, int role) const;
    QVariant displayText(const ParameterRow &row, int column) const;
    QVariant toolTip(const ParameterRow &row, int column) const;
    QString accessText(const ParameterRow &row) const;
    QString valueText(const ParameterRow &row, qint32 raw) const; // as the value cells show it
    bool isAboveLevel(const ParameterRow &row) const;
    bool isStale(const ParameterRow &row) const;
    bool isEditable(const ParameterRow &row) const;
    // Why the user may not change the parameter (read-only, above the level in force); empty
    // when he may.
    QString editRefusal(const ParameterRow &row) const;
    // Applies `change` to the cells of the sets in the mask, then emits one dataChanged.
    template<typename Change> void changeCells(quint16 address, quint8 setMask, Change change);
    void emitRowChanged(quint16 address);
    void emitAllChanged(const QList<int> &roles = {});

    std::vector<Group> m_groups;
    QHash<quint16, Location> m_locations;
    DriveDescription m_drive; // groups left empty: header fields only
    QSet<quint16> m_favourites;
    PasswordLevel m_level = PasswordLevel::Supervisor;
    int m_activeSet = -1;
    bool m_raw = false;
    qint64 m_staleSinceMs = 0;
    CellDecoration m_decoration;
};

} // namespace DriveDesk
