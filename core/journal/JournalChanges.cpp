#include "JournalChanges.h"

namespace DriveDesk {

namespace {

quint32 keyOf(quint16 address, int set)
{
    return quint32(address) << 8 | quint32(set & 0xFF);
}

} // namespace

JournalChanges JournalChanges::of(const QList<JournalEntry> &entries)
{
    JournalChanges changes;
    changes.add(entries);
    return changes;
}

void JournalChanges::add(const QList<JournalEntry> &entries)
{
    for (const JournalEntry &entry : entries) {
        if (entry.outcome != JournalOutcome::Written || entry.password)
            continue;
        JournalEntry &last = m_last[keyOf(entry.parameterAddress, entry.set.value_or(-1))];
        if (entry.id >= last.id)
            last = entry;
    }
}

const JournalEntry *JournalChanges::last(quint16 address, int set) const
{
    const auto found = m_last.constFind(keyOf(address, set));
    return found == m_last.constEnd() ? nullptr : &found.value();
}

} // namespace DriveDesk
