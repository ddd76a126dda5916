#include "JournalProblem.h"

#include "JournalSchema.h"

#include <QDir>
#include <QFileInfo>
#include <QSqlError>
#include <QStorageInfo>

#ifdef Q_OS_UNIX
#include <fcntl.h>
#include <unistd.h>
#endif

namespace DriveDesk {

namespace {

// SQLite's primary result codes that have words of their own.
enum SqliteCode : int {
    Permission = 3,
    Busy = 5,
    Locked = 6,
    ReadOnly = 8,
    InputOutput = 10,
    Corrupt = 11,
    Full = 13,
    CannotOpen = 14,
    NotADatabase = 26,
};

bool readable(const QString &path)
{
#ifdef Q_OS_UNIX
    return ::faccessat(AT_FDCWD, QFile::encodeName(path).constData(), R_OK, AT_EACCESS) == 0;
#else
    return QFileInfo(path).isReadable();
#endif
}

// Less than this free, a journal counts as on a full disk: an entry and the write-ahead log's
// growth need a few pages.
constexpr qint64 kLeastFreeBytes = 256 * 1024;

} // namespace

bool JournalProblem::isWritable(const QString &path)
{
#ifdef Q_OS_UNIX
    return ::faccessat(AT_FDCWD, QFile::encodeName(path).constData(), W_OK, AT_EACCESS) == 0;
#else
    return QFileInfo(path).isWritable();
#endif
}

QString JournalProblem::beforeWriting(const QString &path)
{
    const QFileInfo file(path);
    const QString folder = file.absolutePath();
    if (!QDir().mkpath(folder))
        return tr("cannot write the journal %1: the folder %2 cannot be made").arg(path, folder);
    if (file.exists() && !file.isFile())
        return tr("cannot write the journal %1: it is no file").arg(path);
    if (file.exists() && !isWritable(path))
        return tr("cannot write the journal %1: the file is read-only").arg(path);
    // SQLite keeps the write-ahead log (-wal) and its index (-shm) beside the file.
    if (!isWritable(folder))
        return tr("cannot write the journal %1: the folder %2 is read-only (the journal keeps "
                  "%3-wal and %3-shm beside it)")
            .arg(path, folder, file.fileName());
    const QStorageInfo storage(folder);
    if (storage.isValid() && storage.bytesAvailable() >= 0
        && storage.bytesAvailable() < kLeastFreeBytes)
        return tr("cannot write the journal %1: the disk is full").arg(path);
    return {};
}

QString JournalProblem::beforeReading(const QString &path)
{
    const QFileInfo file(path);
    if (!file.exists())
        return tr("there is no journal %1").arg(path);
    if (!file.isFile())
        return tr("cannot read the journal %1: it is no file").arg(path);
    if (!readable(path))
        return tr("cannot read the journal %1: permission denied").arg(path);
    return {};
}

QString JournalProblem::of(const QString &path, const QSqlError &error, int busyTimeoutMs)
{
    bool isNumber = false;
    const int code = error.nativeErrorCode().toInt(&isNumber) & 0xFF;
    const QString sqlite = error.databaseText().isEmpty() ? error.text() : error.databaseText();
    switch (isNumber ? code : 0) {
    case Busy:
    case Locked:
        return tr("the journal %1 is locked by another program: waited %2 ms for it")
            .arg(path)
            .arg(busyTimeoutMs);
    case ReadOnly:
    case Permission:
        return tr("cannot write the journal %1: it is read-only (%2)").arg(path, sqlite);
    case Full:
        return tr("cannot write the journal %1: the disk is full").arg(path);
    case InputOutput:
        return tr("cannot write the journal %1: the disk failed or is full (%2)").arg(path, sqlite);
    case Corrupt:
    case NotADatabase:
        return notJournal(path);
    case CannotOpen:
        return tr("cannot open the journal %1 (%2)").arg(path, sqlite);
    default:
        break;
    }
    return tr("the journal %1: %2").arg(path, sqlite);
}

bool JournalProblem::isBusy(const QSqlError &error)
{
    bool isNumber = false;
    const int code = error.nativeErrorCode().toInt(&isNumber) & 0xFF;
    return isNumber && (code == Busy || code == Locked);
}

QString JournalProblem::notJournal(const QString &path)
{
    return tr("%1 is no DriveDesk journal: it is damaged or not a journal at all").arg(path);
}

QString JournalProblem::newer(const QString &path, int version)
{
    return tr("the journal %1 was made by a newer DriveDesk (journal version %2; this one knows "
              "up to %3): it is not written")
        .arg(path)
        .arg(version)
        .arg(JournalSchema::kVersion);
}

} // namespace DriveDesk
