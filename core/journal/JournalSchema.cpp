#include "JournalSchema.h"

#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>

namespace DriveDesk {

namespace {

// Version 1. Times are UTC milliseconds since 1970. One row per value written; a job (an edit,
// a download, a revert) is a row of jobs its entries point at. The drive is kept in each entry
// as it was found then. Indexes serve the journal command's filters, each ending in the id so
// that "newest last" is the index's own order.
const char *const kTables[] = {
    "CREATE TABLE jobs ("
    " id INTEGER PRIMARY KEY,"
    " description TEXT NOT NULL,"
    " time_utc_ms INTEGER NOT NULL)",
    "CREATE TABLE entries ("
    " id INTEGER PRIMARY KEY,"
    " time_utc_ms INTEGER NOT NULL,"
    " completed_utc_ms INTEGER,"
    " user TEXT NOT NULL,"
    " host TEXT NOT NULL,"
    " program TEXT NOT NULL,"
    " job_id INTEGER REFERENCES jobs(id),"
    " link TEXT NOT NULL,"
    " protocol TEXT NOT NULL,"
    " address INTEGER,"
    " drive_kind TEXT NOT NULL,"
    " software_version TEXT NOT NULL,"
    " serial_number TEXT NOT NULL,"
    " parameter_id TEXT NOT NULL COLLATE NOCASE,"
    " parameter_address INTEGER NOT NULL,"
    " parameter_name TEXT NOT NULL,"
    " parameter_set INTEGER,"
    " password INTEGER NOT NULL,"
    " before_raw INTEGER, before_text TEXT,"
    " written_raw INTEGER, written_text TEXT,"
    " read_back_raw INTEGER, read_back_text TEXT,"
    " outcome TEXT NOT NULL CHECK (outcome IN ('unknown', 'written', 'refused')),"
    " reason TEXT NOT NULL DEFAULT '')",
    "CREATE INDEX entries_by_serial_number ON entries (serial_number, id)",
    "CREATE INDEX entries_by_link ON entries (link, address, id)",
    "CREATE INDEX entries_by_parameter ON entries (parameter_id, id)",
    "CREATE INDEX entries_by_time ON entries (time_utc_ms)",
};

bool exec(QSqlDatabase &db, const QString &statement, QSqlError *error)
{
    QSqlQuery query(db);
    if (query.exec(statement))
        return true;
    *error = query.lastError();
    return false;
}

} // namespace

JournalSchema::State JournalSchema::inspect(QSqlDatabase &db, int *version, QSqlError *error)
{
    // One statement, so one snapshot: another program making the tables meanwhile is seen
    // before or after, never half-way.
    QSqlQuery query(db);
    if (!query.exec(QStringLiteral("SELECT (SELECT application_id FROM pragma_application_id()), "
                                   "(SELECT user_version FROM pragma_user_version()), "
                                   "(SELECT count(*) FROM sqlite_schema)"))
        || !query.next()) {
        *error = query.lastError();
        return State::Failed;
    }
    const qint64 applicationId = query.value(0).toLongLong();
    *version = query.value(1).toInt();
    const qint64 objects = query.value(2).toLongLong();
    if (applicationId == 0 && *version == 0)
        return objects == 0 ? State::Empty : State::NotJournal;
    if (applicationId != kApplicationId)
        return State::NotJournal;
    return *version > kVersion ? State::Newer : State::Ready;
}

JournalSchema::State JournalSchema::create(QSqlDatabase &db, QSqlError *error)
{
    if (!exec(db, QStringLiteral("BEGIN IMMEDIATE"), error))
        return State::Failed;
    // Another program may have made the tables while this one waited for the lock.
    int version = 0;
    State state = inspect(db, &version, error);
    if (state == State::Empty) {
        bool ok = true;
        for (const char *statement : kTables)
            ok = ok && exec(db, QString::fromLatin1(statement), error);
        ok = ok && exec(db, QStringLiteral("PRAGMA application_id = %1").arg(kApplicationId), error)
            && exec(db, QStringLiteral("PRAGMA user_version = %1").arg(kVersion), error);
        state = ok ? State::Ready : State::Failed;
    }
    QSqlError ignored; // the error to report is the statement's, not the rollback's
    if (state != State::Ready) {
        exec(db, QStringLiteral("ROLLBACK"), &ignored);
        return state;
    }
    return exec(db, QStringLiteral("COMMIT"), error) ? State::Ready : State::Failed;
}

} // namespace DriveDesk
