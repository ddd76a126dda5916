#pragma once

#include "journal/JournalEntry.h"

#include <QHash>
#include <QList>

namespace DriveDesk {

// The last change the journal holds of each value of one drive: what a value's tooltip names
// ("7.50 s since 10:42 by anna, was 5.00 s"). Only writes the drive took count as changes.
class JournalChanges
{
public:
    // The newest written entry per parameter and set among `entries` (of one drive).
    static JournalChanges of(const QList<JournalEntry> &entries);
    // `entries` newer than those taken so far.
    void add(const QList<JournalEntry> &entries);

    // The last change of the set's value; set -1: of the entries that name no set (a parameter
    // without sets; the active set, which one the journal does not say). Nothing when the
    // journal holds none.
    const JournalEntry *last(quint16 address, int set) const;
    bool isEmpty() const { return m_last.isEmpty(); }

private:
    QHash<quint32, JournalEntry> m_last; // address << 8 | set
};

} // namespace DriveDesk
