#pragma once

#include "journal/JournalEntry.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>

namespace DriveDesk {

// The journal's entries as `drivedesk-cli journal` prints them (docs/journal.md): a table for
// people (aligned columns, local time, the installed language), JSON and CSV for programs
// (every field, fixed English names and outcome words, UTC in JSON and local time with its
// offset in CSV).
class JournalFormat
{
    Q_DECLARE_TR_FUNCTIONS(JournalFormat)
public:
    static QString table(const QList<JournalEntry> &entries);
    static QByteArray json(const QList<JournalEntry> &entries);
    // UTF-8, comma-separated, CRLF line ends, quoted where needed (RFC 4180).
    static QByteArray csv(const QList<JournalEntry> &entries);

    // A value as the table shows it: its text, else its raw number, "(password)" for a
    // password's values, "-" for none.
    static QString valueText(const JournalValue &value, bool password);
};

} // namespace DriveDesk
