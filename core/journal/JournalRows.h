#pragma once

#include "journal/JournalEntry.h"

#include <QString>
#include <QVariantList>

class QSqlQuery;

namespace DriveDesk {

class JournalFilter;

// How entries are read back from the journal's tables: the query a filter makes (the
// indexes of JournalSchema serve each of its parts) and the entry one of its rows holds.
struct JournalSelect
{
    QString statement;
    QVariantList values; // bound in order
};

JournalSelect journalSelect(const JournalFilter &filter);
// The entry in the query's current row, a query made from journalSelect().
JournalEntry journalEntryOf(const QSqlQuery &row);

} // namespace DriveDesk
