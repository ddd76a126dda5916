#include "BackupRepository.h"

#include "parameters/ParameterDocument.h"
#include "parameters/SavedFile.h"

#include <QtConcurrent/QtConcurrentMap>

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

namespace DriveDesk {

std::optional<BackupRepository> BackupRepository::open(const QString &directory, bool create,
                                                       QString *error)
{
    if (!QFileInfo(directory).isDir() && !(create && QDir().mkpath(directory))) {
        *error = create ? tr("cannot make the directory %1").arg(QDir::toNativeSeparators(directory))
                        : tr("the directory %1 does not exist").arg(QDir::toNativeSeparators(directory));
        return std::nullopt;
    }
    BackupRepository repository(QFileInfo(directory).absoluteFilePath());
    const QString canonical = QFileInfo(directory).canonicalFilePath();
    const Git::Result top = repository.m_git.run(
        {QStringLiteral("rev-parse"), QStringLiteral("--show-toplevel")});
    if (!top.started) {
        *error = top.error;
        return std::nullopt;
    }
    const bool own = top.ok
                     && QFileInfo(QString::fromUtf8(top.out).trimmed()).canonicalFilePath()
                            == canonical;
    if (own)
        return repository;
    if (!create) {
        *error = tr("%1 is not a git repository of backups: make it one with plant backup "
                    "--commit")
                     .arg(QDir::toNativeSeparators(directory));
        return std::nullopt;
    }
    const Git::Result made = repository.m_git.run({QStringLiteral("init"), QStringLiteral("-q"),
                                                   QStringLiteral(".")});
    if (!made.ok) {
        *error = made.error;
        return std::nullopt;
    }
    return repository;
}

bool BackupRepository::hasCommits() const
{
    return m_git.run({QStringLiteral("rev-parse"), QStringLiteral("--verify"),
                      QStringLiteral("--quiet"), QStringLiteral("HEAD^{commit}")})
        .ok;
}

std::optional<QString> BackupRepository::resolve(const QString &revision, QString *error) const
{
    const QString trimmed = revision.trimmed();
    // An option to git is never a revision.
    if (!trimmed.isEmpty() && !trimmed.startsWith(QLatin1Char('-'))) {
        const Git::Result named = m_git.run({QStringLiteral("rev-parse"), QStringLiteral("--verify"),
                                             QStringLiteral("--quiet"),
                                             trimmed + QStringLiteral("^{commit}")});
        if (named.ok)
            return QString::fromLatin1(named.out).trimmed();
        static const QRegularExpression day(QStringLiteral("^\\d{4}-\\d{2}-\\d{2}$"));
        if (day.match(trimmed).hasMatch() && QDate::fromString(trimmed, Qt::ISODate).isValid()
            && hasCommits()) {
            const Git::Result dated = m_git.run(
                {QStringLiteral("rev-list"), QStringLiteral("-1"), QStringLiteral("--first-parent"),
                 QStringLiteral("--before=%1 23:59:59").arg(trimmed), QStringLiteral("HEAD")});
            const QString id = QString::fromLatin1(dated.out).trimmed();
            if (dated.ok && !id.isEmpty())
                return id;
            if (dated.ok) {
                *error = tr("there is no revision on or before %1 in %2")
                             .arg(trimmed, QDir::toNativeSeparators(directory()));
                return std::nullopt;
            }
        }
    }
    *error = tr("'%1' is no revision of %2: give a commit id, a tag or a date like 2026-11-24")
                 .arg(revision, QDir::toNativeSeparators(directory()));
    return std::nullopt;
}

std::optional<QMap<QString, QByteArray>> BackupRepository::filesAt(const QString &commit,
                                                                   QString *error) const
{
    const Git::Result listed = m_git.run({QStringLiteral("ls-tree"), QStringLiteral("-z"), commit});
    if (!listed.ok) {
        *error = listed.error;
        return std::nullopt;
    }
    QMap<QString, QByteArray> files;
    // "<mode> blob <id>\t<name>\0"
    for (const QByteArray &entry : listed.out.split('\0')) {
        const qsizetype tab = entry.indexOf('\t');
        const QList<QByteArray> fields = entry.left(tab).split(' ');
        if (tab < 0 || fields.size() != 3 || fields[1] != "blob")
            continue;
        const QString name = QString::fromUtf8(entry.mid(tab + 1));
        if (driveOfFile(name))
            files.insert(name, fields[2]);
    }
    return files;
}

std::optional<QHash<QByteArray, QByteArray>>
BackupRepository::contents(const QList<QByteArray> &blobs, QString *error) const
{
    QHash<QByteArray, QByteArray> result;
    if (blobs.isEmpty())
        return result;
    QByteArray input;
    for (const QByteArray &blob : blobs)
        input += blob + '\n';
    const Git::Result read = m_git.run({QStringLiteral("cat-file"), QStringLiteral("--batch")},
                                       input);
    if (!read.ok) {
        *error = read.error;
        return std::nullopt;
    }
    // Each: "<id> blob <size>\n<contents>\n", or "<name> missing\n".
    qsizetype at = 0;
    const QByteArray &out = read.out;
    while (at < out.size()) {
        const qsizetype end = out.indexOf('\n', at);
        if (end < 0)
            break;
        const QList<QByteArray> header = out.mid(at, end - at).split(' ');
        at = end + 1;
        if (header.size() != 3) {
            *error = tr("git cat-file: no object %1").arg(QString::fromLatin1(header.value(0)));
            return std::nullopt;
        }
        const qsizetype size = header[2].toLongLong();
        result.insert(header[0], out.mid(at, size));
        at += size + 1;
    }
    return result;
}

bool BackupRepository::extract(const QString &commit, const QString &target, QString *error) const
{
    const auto files = filesAt(commit, error);
    if (!files)
        return false;
    const auto blobs = contents(files->values(), error);
    if (!blobs)
        return false;
    for (auto it = files->cbegin(); it != files->cend(); ++it) {
        if (!SavedFile::write(QDir(target).filePath(it.key()), blobs->value(it.value()), error))
            return false;
    }
    return true;
}

std::unique_ptr<QTemporaryDir> extractRevision(const QString &directory, const QString &revision,
                                               QString *commit, QString *error)
{
    const auto repository = BackupRepository::open(directory, false, error);
    if (!repository)
        return nullptr;
    const std::optional<QString> id = repository->resolve(revision, error);
    if (!id)
        return nullptr;
    auto folder = std::make_unique<QTemporaryDir>();
    if (!folder->isValid()) {
        *error = BackupRepository::tr("cannot make a temporary folder: %1")
                     .arg(folder->errorString());
        return nullptr;
    }
    if (!repository->extract(*id, folder->path(), error))
        return nullptr;
    *commit = *id;
    return folder;
}

QList<ReadDescription> readDescriptions(const QList<QByteArray> &contents)
{
    return QtConcurrent::blockingMapped(contents, [](const QByteArray &bytes) {
        ReadDescription read;
        read.description = ParameterDocument::fromJson(bytes, &read.reason);
        return read;
    });
}

DriveFiles readDriveFiles(const QMap<QString, QByteArray> &files)
{
    QStringList drives;
    QList<QByteArray> contents;
    for (auto it = files.cbegin(); it != files.cend(); ++it) {
        if (const std::optional<QString> drive = driveOfFile(it.key())) {
            drives << *drive;
            contents << it.value();
        }
    }
    const QList<ReadDescription> read = readDescriptions(contents);
    DriveFiles result;
    for (qsizetype i = 0; i < drives.size(); ++i) {
        if (read[i].description)
            result.drives.insert(drives[i], *read[i].description);
        else
            result.unreadable.insert(drives[i], read[i].reason);
    }
    return result;
}

} // namespace DriveDesk
