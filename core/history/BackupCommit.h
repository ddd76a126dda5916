#pragma once

#include "BackupRepository.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace DriveDesk {

struct Plant;
struct PlantDrive;

// One plant backup made a commit of its folder's repository (`plant backup --commit`).
struct BackupCommit
{
    Q_DECLARE_TR_FUNCTIONS(BackupCommit)
public:
    // The files of the backup, names at the top of the folder: those saved now (read whole by
    // this backup) and those of drives the plant no longer has.
    QStringList saved;
    QStringList gone;
    // The plant as the backup's run left it, if given: the last commit's files of no drive of
    // it (filesOfNoDrive) are gone too.
    const Plant *plant = nullptr;
    // The plant's name and the user's words for the commit's first line, if any.
    QString plantName;
    QString message;

    struct Outcome
    {
        bool committed = false; // false: no setting changed since the last commit
        QString id;             // the new commit
        QList<DriveChange> changes;
    };

    // The changes since the last commit (the folder's files at HEAD against the files saved,
    // the drives gone dropped); when there is one, the saved files and the drives gone are
    // committed, with the changes in the message. A change of live values alone commits
    // nothing. The author is git's user.name and user.email, or where git has none the login
    // name and host. Nothing and *error, naming what git said, when git fails.
    std::optional<Outcome> commit(BackupRepository &repository, QString *error) const;

    // The commit message: the user's words or "Line 3: backup, cabinet-5 changed", then a
    // line a change.
    QString commitMessage(const QList<DriveChange> &changes) const;
};

// A plant backup's run committed to its folder's repository, as `plant backup --commit` and
// the plant view's Back Up All with "Commit to History" do it.
struct PlantBackupCommitted
{
    bool savedAny = false; // false: the run saved no drive, and nothing was committed
    BackupCommit::Outcome outcome;
    QString subject; // the commit message's first line, where one was made
};

// The files the run saved and those of drives `plant` (as the run left it) no longer has,
// committed with the changes since the last commit; `directory` becomes a repository if it is
// not one. A run that saved nothing is no revision of the machine, whatever it was asked.
// Nothing and *error, naming what git said, when git fails.
std::optional<PlantBackupCommitted> commitPlantBackup(const QString &directory,
                                                      const Plant &plant,
                                                      const QList<PlantDrive> &drives,
                                                      const QString &message, QString *error);

// The files of a plant's backup folder that belong to no drive of `plant`: its links as a run
// left them (a DIN link searched to the end holds the addresses found). A file of a link whose
// drives are not known (no addresses, not searched) belongs to it, whatever its address.
QStringList filesOfNoDrive(const Plant &plant, const QStringList &files);

} // namespace DriveDesk
