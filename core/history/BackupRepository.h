#pragma once

#include "DriveChange.h"
#include "Git.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QDateTime>
#include <QHash>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>
#include <optional>

namespace DriveDesk {

// A plant's backup folder as a git repository: one commit a plant backup, the drives'
// parameter files at its top (core/plant's PlantRun::fileFor names them). Reads revisions from
// git's object store and never touches the working tree or the index, except to commit a
// backup. Blocks while git runs (see Git).
class BackupRepository
{
    Q_DECLARE_TR_FUNCTIONS(BackupRepository)
public:
    // The folder's repository: the folder must be its top, not a folder inside another
    // repository (that one is not ours to commit to). With `create` a folder that is no
    // repository of its own is made one. Nothing and *error when git is missing or fails, or,
    // without `create`, when the folder is no repository.
    static std::optional<BackupRepository> open(const QString &directory, bool create,
                                                QString *error);

    const QString &directory() const { return m_git.directory(); }
    Git &git() { return m_git; }
    const Git &git() const { return m_git; }

    // Whether a commit exists yet.
    bool hasCommits() const;
    // A commit id, a tag or a date "2026-11-24" (the last commit on or before that day,
    // local time) as a full commit id; nothing and *error naming the revision otherwise.
    std::optional<QString> resolve(const QString &revision, QString *error) const;
    // The drives' files at the top of the tree of `commit`: file name -> blob id.
    std::optional<QMap<QString, QByteArray>> filesAt(const QString &commit, QString *error) const;
    // The contents of blobs, read in one run of git cat-file.
    std::optional<QHash<QByteArray, QByteArray>> contents(const QList<QByteArray> &blobs,
                                                          QString *error) const;
    // The drives' files of `commit` written into `target` (a folder of the caller's), as they
    // were; the working tree and the index stay as they are.
    bool extract(const QString &commit, const QString &target, QString *error) const;

private:
    explicit BackupRepository(QString directory) : m_git(std::move(directory)) {}

    Git m_git;
};

// A parameter file's contents read: its description, or why it cannot be read.
struct ReadDescription
{
    std::optional<DriveDescription> description;
    QString reason;
};

// Each file's contents read, in order, on every core at once: reading is most of the work of
// a commit and of a history, and each file stands alone.
QList<ReadDescription> readDescriptions(const QList<QByteArray> &contents);

// The drives' files of `revision` (as resolve() takes it) of the repository at `directory` in a
// temporary folder of their own: what `plant verify|download --at` and the window's Restore
// work on. The repository's working tree stays as it is. *commit: the commit it named. Nothing
// and *error for a folder that is no repository of backups, a revision that does not exist, or
// git failing. Blocks while git runs.
std::unique_ptr<QTemporaryDir> extractRevision(const QString &directory, const QString &revision,
                                               QString *commit, QString *error);

// Reads each file's contents into a DriveFiles: a description per drive, or why it cannot be
// read. `files`: file name -> contents.
DriveFiles readDriveFiles(const QMap<QString, QByteArray> &files);

} // namespace DriveDesk
