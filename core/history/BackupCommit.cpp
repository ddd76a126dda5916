#include "BackupCommit.h"

#include "plant/PlantFile.h"
#include "plant/PlantRun.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>
#include <QSet>

namespace DriveDesk {

namespace {

// Where git's configuration names no author, the login name and host stand in: a commit is
// never refused for want of user.name.
void authorWhereGitHasNone(Git &git)
{
    // One run for both: "user.name Jane Doe\nuser.email jane@example.org\n".
    const Git::Result values = git.run({QStringLiteral("config"), QStringLiteral("--get-regexp"),
                                        QStringLiteral("^user\\.(name|email)$")});
    const auto configured = [&values](const QByteArray &key) {
        for (const QByteArray &line : values.out.split('\n')) {
            if (line.startsWith(key + ' ') && !line.mid(key.size() + 1).trimmed().isEmpty())
                return true;
        }
        return false;
    };
    const bool name = configured("user.name");
    const bool email = configured("user.email");
    if (name && email)
        return;
    QString login;
    for (const char *variable : {"USER", "LOGNAME", "USERNAME"}) {
        login = qEnvironmentVariable(variable);
        if (!login.isEmpty())
            break;
    }
    if (login.isEmpty())
        login = QDir::home().dirName();
    QString host = QSysInfo::machineHostName();
    if (host.isEmpty())
        host = QStringLiteral("localhost");
    if (!name) {
        git.setVariable(QStringLiteral("GIT_AUTHOR_NAME"), login);
        git.setVariable(QStringLiteral("GIT_COMMITTER_NAME"), login);
    }
    if (!email) {
        const QString address = QStringLiteral("%1@%2").arg(login, host);
        git.setVariable(QStringLiteral("GIT_AUTHOR_EMAIL"), address);
        git.setVariable(QStringLiteral("GIT_COMMITTER_EMAIL"), address);
    }
}

} // namespace

QString BackupCommit::commitMessage(const QList<DriveChange> &changes) const
{
    QStringList lines;
    QStringList drives;
    for (const DriveChange &change : changes) {
        lines << change.lines();
        drives << change.drive;
    }
    // The drives, not a count: `git log --oneline` then says where to look.
    const QString subject = message.trimmed().isEmpty()
                                ? tr("%1: backup, %2 changed")
                                      .arg(plantName, drives.join(QStringLiteral(", ")))
                                : message.trimmed();
    return subject + QStringLiteral("\n\n") + lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

std::optional<BackupCommit::Outcome> BackupCommit::commit(BackupRepository &repository,
                                                         QString *error) const
{
    Git &git = repository.git();
    QMap<QString, QByteArray> last;
    if (repository.hasCommits()) {
        const auto files = repository.filesAt(QStringLiteral("HEAD"), error);
        if (!files)
            return std::nullopt;
        const auto blobs = repository.contents(files->values(), error);
        if (!blobs)
            return std::nullopt;
        for (auto it = files->cbegin(); it != files->cend(); ++it)
            last.insert(it.key(), blobs->value(it.value()));
    }
    QStringList dropped = gone;
    if (plant)
        dropped << filesOfNoDrive(*plant, last.keys());
    QMap<QString, QByteArray> now = last;
    for (const QString &name : std::as_const(dropped))
        now.remove(name);
    for (const QString &name : saved) {
        QFile file(QDir(repository.directory()).filePath(name));
        if (!file.open(QIODevice::ReadOnly)) {
            *error = tr("cannot read %1: %2").arg(QDir::toNativeSeparators(file.fileName()),
                                                  file.errorString());
            return std::nullopt;
        }
        now.insert(name, file.readAll());
    }
    Outcome outcome;
    outcome.changes = compareRevisions(readDriveFiles(last), readDriveFiles(now));
    if (outcome.changes.isEmpty())
        return outcome;

    QStringList removed;
    for (const QString &name : std::as_const(dropped)) {
        if (last.contains(name))
            removed << name;
    }
    if (!saved.isEmpty()) {
        const Git::Result added = git.run(QStringList{QStringLiteral("add"), QStringLiteral("--")}
                                          + saved);
        if (!added.ok) {
            *error = added.error;
            return std::nullopt;
        }
    }
    // The file stays in the folder: the drive's last backup is the user's to delete.
    if (!removed.isEmpty()) {
        const Git::Result untracked = git.run(
            QStringList{QStringLiteral("rm"), QStringLiteral("-q"), QStringLiteral("--cached"),
                        QStringLiteral("--")}
            + removed);
        if (!untracked.ok) {
            *error = untracked.error;
            return std::nullopt;
        }
    }
    authorWhereGitHasNone(git);
    const Git::Result committed = git.run({QStringLiteral("commit"), QStringLiteral("-q"),
                                           QStringLiteral("--no-verify"),
                                           QStringLiteral("--cleanup=verbatim"),
                                           QStringLiteral("-F"), QStringLiteral("-")},
                                          commitMessage(outcome.changes).toUtf8());
    if (!committed.ok) {
        *error = committed.error;
        return std::nullopt;
    }
    const Git::Result head = git.run({QStringLiteral("rev-parse"), QStringLiteral("HEAD")});
    if (!head.ok) {
        *error = head.error;
        return std::nullopt;
    }
    outcome.committed = true;
    outcome.id = QString::fromLatin1(head.out).trimmed();
    return outcome;
}

QStringList filesOfNoDrive(const Plant &plant, const QStringList &files)
{
    QSet<QString> known;
    QStringList unsearched; // "cabinet-": a link whose drives are not known
    for (const PlantLink &link : plant.links) {
        if (link.protocol == Protocol::Hsp5) {
            known.insert(QFileInfo(PlantRun::fileFor({}, link, -1)).fileName());
        } else if (link.addresses.isEmpty()) {
            unsearched << link.name + QLatin1Char('-');
        } else {
            for (int address : link.addresses)
                known.insert(QFileInfo(PlantRun::fileFor({}, link, address)).fileName());
        }
    }
    QStringList result;
    for (const QString &file : files) {
        const bool ofUnsearched = std::any_of(unsearched.cbegin(), unsearched.cend(),
                                              [&file](const QString &prefix) {
                                                  return file.startsWith(prefix);
                                              });
        if (!known.contains(file) && !ofUnsearched)
            result << file;
    }
    return result;
}

std::optional<PlantBackupCommitted> commitPlantBackup(const QString &directory,
                                                      const Plant &plant,
                                                      const QList<PlantDrive> &drives,
                                                      const QString &message, QString *error)
{
    BackupCommit backup;
    backup.plantName = plant.name;
    backup.message = message;
    for (const PlantDrive &drive : drives) {
        if (drive.outcome == PlantDrive::Outcome::Saved)
            backup.saved << QFileInfo(drive.file).fileName();
    }
    PlantBackupCommitted committed;
    if (backup.saved.isEmpty())
        return committed;
    committed.savedAny = true;
    auto repository = BackupRepository::open(directory, true, error);
    if (!repository)
        return std::nullopt;
    backup.plant = &plant;
    const auto outcome = backup.commit(*repository, error);
    if (!outcome)
        return std::nullopt;
    committed.outcome = *outcome;
    if (outcome->committed)
        committed.subject = backup.commitMessage(outcome->changes).section(QLatin1Char('\n'), 0, 0);
    return committed;
}

} // namespace DriveDesk
