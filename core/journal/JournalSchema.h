#pragma once

#include <QString>

class QSqlDatabase;
class QSqlError;

namespace DriveDesk {

// The journal file's layout: the tables, their indexes and the version in SQLite's
// user_version, beside an application id that tells a journal from any other SQLite file
// (docs/journal.md, "The file").
class JournalSchema
{
public:
    static constexpr int kVersion = 1;
    static constexpr qint32 kApplicationId = 0x44444A4C; // "DDJL"

    enum class State : quint8 {
        Ready, // a journal this version reads and writes
        Empty, // no tables yet: a new file
        NotJournal, // another SQLite file
        Newer, // a journal of a later version: never written, read as far as it goes
        Failed, // SQLite could not say: *error tells why
    };

    // What the file holds. `version` receives its user_version.
    static State inspect(QSqlDatabase &db, int *version, QSqlError *error);
    // Creates the tables of an empty file in one immediate transaction, so that two programs
    // starting on a new file at once make them once. Returns what the file then is: Ready, or
    // what it turned out to be when another program was quicker, or Failed.
    static State create(QSqlDatabase &db, QSqlError *error);
};

} // namespace DriveDesk
