#pragma once

#include "journal/JournalEntry.h"

#include <QAbstractTableModel>
#include <QList>

namespace DriveDesk {

// The journal's entries as a table, newest first: each field as the journal view shows it, the
// time in local time. Holds the pages read so far; the view's filters decide which.
class JournalTableModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        IdColumn,
        TimeColumn,
        UserColumn,
        HostColumn,
        ProgramColumn,
        JobColumn,
        DriveColumn,
        ParameterColumn,
        NameColumn,
        SetColumn,
        BeforeColumn,
        WrittenColumn,
        ReadBackColumn,
        OutcomeColumn,
        ColumnCount
    };
    enum Role {
        EntryIdRole = Qt::UserRole + 1, // qint64
        SearchTextRole, // QString, lower-case: every field, what the search matches
    };

    using QAbstractTableModel::QAbstractTableModel;

    // A new page replaces everything (`entries` oldest first, as the journal gives them).
    void setEntries(const QList<JournalEntry> &entries);
    // Entries newer than those held, on top.
    void addNewer(const QList<JournalEntry> &entries);
    // Entries older than those held, below.
    void addOlder(const QList<JournalEntry> &entries);

    qint64 newestId() const;
    qint64 oldestId() const;
    const JournalEntry *entry(int row) const;
    const JournalEntry *entryById(qint64 id) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    QString text(const JournalEntry &entry, int column) const;

    QList<JournalEntry> m_entries; // newest first
};

} // namespace DriveDesk
