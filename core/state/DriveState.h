#pragma once

#include "ParameterState.h"

#include "journal/JournalChanges.h"
#include "parameters/DriveDescription.h"
#include "parameters/PasswordLevel.h"
#include "state/EditText.h"

#include <QHash>
#include <QObject>

#include <optional>
#include <vector>

namespace DriveDesk {

struct WriteOutcome;

// What DriveDesk knows about one drive (read over a link) or one parameter file opened to edit,
// held once: its description, the values per set with when they were read, where each cell
// stands with an edit (pending, written, failed, unknown, changed in the file), its password
// level and active set. The scan, polling, the edits and the jobs update it; the window's
// ParameterModel shows it, and features and the command line read it. Lives in one thread (the
// window's); the signals say what changed so that views follow.
class DriveState : public QObject
{
    Q_OBJECT
public:
    struct Location
    {
        int group = -1;
        int row = -1;
    };

    explicit DriveState(QObject *parent = nullptr);

    // Replaces everything. Edit states go; the level and the active set stay.
    void setDescription(const DriveDescription &drive);
    void clear() { setDescription({}); }
    // The drive with the values held now (a pending write's value not included). Built again
    // only after something changed.
    const DriveDescription &description() const;
    bool isEmpty() const { return m_groups.empty(); }

    int groupCount() const { return int(m_groups.size()); }
    // A group's description without its parameters (they are parameterAt()).
    const GroupDescription &group(int group) const { return m_groups[std::size_t(group)].header; }
    int parameterCount(int group) const { return int(m_groups[std::size_t(group)].rows.size()); }
    const ParameterState &parameterAt(int group, int row) const
    {
        return m_groups[std::size_t(group)].rows[std::size_t(row)];
    }
    Location locationOf(quint16 address) const { return m_locations.value(address); }
    const ParameterState *find(quint16 address) const;
    const ParameterDescription *parameter(quint16 address) const;
    // How messages name the parameter and its values (its id as the table shows it).
    EditText editText(quint16 address) const;

    // What the drive reported for one set: stored, and the parameter marked read now. A
    // parameter that is not set-programmable takes any set as its one value. False for an
    // address the state does not hold or a set outside 0..7.
    bool setValue(quint16 address, int set, qint32 raw);
    // The same value for every set in the mask (a read over several sets).
    bool setValues(quint16 address, quint8 setMask, qint32 raw);
    std::optional<qint32> value(quint16 address, int set) const;
    // An open parameter file's value after an edit or its undo: stored as it is, a value not
    // read (nothing) included, and the cell's edit state dropped. Not a reading from a drive.
    bool putValue(quint16 address, int set, std::optional<qint32> raw);

    // The drive stopped answering at `msecsSinceEpoch`: the values not read since are stale.
    // 0: the drive answers. A value read later is fresh again.
    void setStaleSince(qint64 msecsSinceEpoch);
    qint64 staleSince() const { return m_staleSinceMs; }
    bool isStale(quint16 address) const;
    bool isStale(const ParameterState &parameter) const;

    // Edit states of the cells of the sets in the mask, as the edit path reports them.
    void markPending(quint16 address, quint8 setMask, qint32 raw);
    void markWritten(quint16 address, quint8 setMask);
    void markFailed(quint16 address, quint8 setMask, const QString &reason);
    void markUnknown(quint16 address, quint8 setMask, const QString &reason);
    // An open parameter file's cells whose values differ from what the file holds on disk.
    void markChanged(quint16 address, quint8 setMask);
    // A value read back after a write: stored, and the cell written when it equals what was
    // asked for, failed (saying what the drive holds) when it does not. A parameter whose
    // read-back may differ by its nature (readBackMayDiffer) is written whatever it reads.
    void confirmReadBack(quint16 address, int set, qint32 raw);
    // An edit's outcome in the cells: failed with the drive's reason, unknown where no answer
    // came, or the value read back. A superseded edit (a later one of the same parameter will
    // write and read these cells again) only stores the values read.
    void showOutcome(const WriteOutcome &outcome, bool superseded = false);
    void clearEditStates();
    // Drops the edit states of the sets in the mask: nothing was written there after all.
    void clearEditState(quint16 address, quint8 setMask);
    EditState editState(quint16 address, int set) const;

    // Until told otherwise nothing is locked by level: the drive refuses what it must.
    void setPasswordLevel(PasswordLevel level);
    PasswordLevel passwordLevel() const { return m_level; }
    bool isAboveLevel(quint16 address) const;
    // Not read-only and within the level in force.
    bool isEditable(quint16 address) const;
    bool isEditable(const ParameterState &parameter) const;
    // Why the user may not change the parameter; empty when he may (EditCheck).
    QString editRefusal(quint16 address) const;
    // Why `raw` may not go into the sets of the mask (EditCheck); empty when it may.
    QString writeRefusal(quint16 address, quint8 setMask, qint32 raw) const;

    // The set the drive runs with (Fr.02); -1: not known.
    void setActiveSet(int set);
    int activeSet() const { return m_activeSet; }

    // Each value's last change the journal holds for this drive, which its tooltip names. Set
    // by what reads the journal; read when a tooltip is asked for, so no signal.
    void setJournalChanges(JournalChanges changes) { m_journalChanges = std::move(changes); }
    const JournalChanges &journalChanges() const { return m_journalChanges; }

signals:
    void aboutToReset();
    void reset();
    // The cells from `firstCell` to `lastCell` of one parameter changed (value or edit state).
    void cellsChanged(quint16 address, int firstCell, int lastCell);
    // Everything shown of one parameter may have changed (it is no longer stale).
    void parameterChanged(quint16 address);
    void staleChanged();
    void passwordLevelChanged(DriveDesk::PasswordLevel level);
    void activeSetChanged(int set);

private:
    struct Group
    {
        GroupDescription header; // without its parameters: they live in `rows`
        std::vector<ParameterState> rows;
    };

    ParameterState *findMutable(quint16 address);
    // Applies `change` to the cells of the sets in the mask, then emits one cellsChanged.
    template<typename Change> void changeCells(quint16 address, quint8 setMask, Change change);
    void cellsChangedAt(quint16 address, int firstCell, int lastCell);

    std::vector<Group> m_groups;
    QHash<quint16, Location> m_locations;
    DriveDescription m_header; // groups left empty
    mutable std::optional<DriveDescription> m_described; // description(), until a change
    PasswordLevel m_level = PasswordLevel::Supervisor;
    int m_activeSet = -1;
    qint64 m_staleSinceMs = 0;
    JournalChanges m_journalChanges;
};

} // namespace DriveDesk
