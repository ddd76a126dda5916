#pragma once

#include <QCoreApplication>
#include <QString>

class QSqlError;

namespace DriveDesk {

// What is wrong with a journal, in words that name its path and say what to do: the file
// system's view before SQLite is asked, and SQLite's errors after. Empty where nothing is.
class JournalProblem
{
    Q_DECLARE_TR_FUNCTIONS(JournalProblem)
public:
    // Before a journal is written: its folder is made where missing; a folder or a file that
    // cannot be written, or a full disk, is named.
    static QString beforeWriting(const QString &path);
    // Before a journal is read: a missing file, or one that cannot be read.
    static QString beforeReading(const QString &path);
    // An SQLite error in words: locked by another program past `busyTimeoutMs`, read-only,
    // the disk full or failing, damaged or not a database, or SQLite's own text.
    static QString of(const QString &path, const QSqlError &error, int busyTimeoutMs);
    // Another program holds the lock SQLite needs (SQLITE_BUSY, SQLITE_LOCKED).
    static bool isBusy(const QSqlError &error);
    static QString notJournal(const QString &path);
    static QString newer(const QString &path, int version);

    // Whether this process may write the file or folder: its effective user's rights, as
    // SQLite's open() meets them (QFileInfo asks for the real user's).
    static bool isWritable(const QString &path);
};

} // namespace DriveDesk
