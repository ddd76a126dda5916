// The plant view's Back Up All as a revision of the backup folder's repository: core's
// commitPlantBackup(), the same as `plant backup --commit`, run in the thread pool because git
// is a program of its own and may take a while on a large history.
#include "PlantDock.h"

#include "PlantHistoryWindow.h"

#include "history/BackupCommit.h"
#include "history/PlantHistory.h"
#include "plant/PlantRun.h"

#include <QAction>
#include <QFutureWatcher>
#include <QSettings>
#include <QToolBar>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace DriveDesk {

namespace {

const QString kCommitKey = QStringLiteral("plant/commitBackups");

struct CommitResult
{
    std::optional<PlantBackupCommitted> committed;
    QString error;
};

} // namespace

void PlantDock::createCommitAction()
{
    m_commitAction = new QAction(tr("Commit to History"), this);
    m_commitAction->setObjectName(QStringLiteral("plantCommitAction"));
    m_commitAction->setCheckable(true);
    m_commitAction->setChecked(QSettings().value(kCommitKey, false).toBool());
    m_commitAction->setToolTip(tr("Make each Back Up All a revision of the backup folder's git "
                                  "repository, with what changed since the last one"));
    connect(m_commitAction, &QAction::toggled, this,
            [](bool on) { QSettings().setValue(kCommitKey, on); });
    m_toolBar->addAction(m_commitAction);
}

void PlantDock::commitBackup(const Plant &plant, const QList<PlantDrive> &drives,
                             const QString &summary)
{
    // A backup stopped half way is no picture of the machine: the drives not read would count
    // as unchanged. `plant backup --commit` interrupted commits nothing either.
    const bool stopped = std::any_of(drives.begin(), drives.end(), [](const PlantDrive &drive) {
        return drive.outcome == PlantDrive::Outcome::Stopped;
    });
    if (stopped)
        return showMessage(tr("%1 Stopped: nothing committed.").arg(summary));
    m_committing = true;
    updateActions();
    showMessage(tr("%1 Committing to the history...").arg(summary));
    const QString directory = backupFolder();
    auto *watcher = new QFutureWatcher<CommitResult>(this);
    connect(watcher, &QFutureWatcher<CommitResult>::finished, this, [this, watcher, summary] {
        watcher->deleteLater();
        m_committing = false;
        updateActions();
        const CommitResult result = watcher->result();
        if (!result.committed) {
            showMessage(tr("%1 Not committed: %2").arg(summary, result.error));
        } else if (!result.committed->savedAny) {
            showMessage(tr("%1 No drive saved: nothing committed.").arg(summary));
        } else if (!result.committed->outcome.committed) {
            showMessage(tr("%1 No setting changed since the last revision: nothing committed.")
                            .arg(summary));
        } else {
            showMessage(tr("%1 Committed %2: %3")
                            .arg(summary, PlantRevision::shortId(result.committed->outcome.id),
                                 result.committed->subject));
            if (m_history && m_history->isVisible())
                m_history->refresh();
        }
    });
    watcher->setFuture(QtConcurrent::run([directory, plant, drives] {
        CommitResult result;
        result.committed = commitPlantBackup(directory, plant, drives, {}, &result.error);
        return result;
    }));
}

} // namespace DriveDesk
