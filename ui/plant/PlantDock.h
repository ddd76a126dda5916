#pragma once

#include "PlantReportDialog.h"

#include "plant/PlantState.h"

#include <QDockWidget>
#include <QPointer>
#include <QTemporaryDir>

#include <functional>
#include <memory>

class QAction;
class QLabel;
class QToolBar;
class QTreeView;

namespace DriveDesk {

class PlantHistoryWindow;
class PlantModel;
class WindowFrame;

// The plant view: the links and drives of a plant file (core's PlantState, shown through
// PlantModel) with the jobs of `drivedesk-cli plant` run on them by core's PlantRun: Find,
// Back Up All, Verify All and Download All (a dry run as the last look per drive, then the
// writing and one combined report), each with progress per drive and Stop. A drive opens in the window's editor with a
// double click; two selected drives are read afresh and offered to the compare window. History
// shows the backup folder's revisions (PlantHistoryWindow); a revision restored goes through
// Download All's last look. The plant runs on connections of its own: the drive open in the
// editor goes on meanwhile.
class PlantDock : public QDockWidget
{
    Q_OBJECT
public:
    enum class Job { None, Find, Backup, Verify, DownloadLook, Download, CompareRead };

    PlantDock(WindowFrame &frame, QWidget *parent = nullptr);
    ~PlantDock() override;

    // Shows the plant file at `path`; false with the reason (file, place, line and column).
    bool openPlant(const QString &path, QString *error);
    // Shows `plant`, saved to `path` first; false with the reason when it cannot be saved.
    bool showNewPlant(const Plant &plant, const QString &path, QString *error);
    QString plantPath() const { return m_path; }
    // Where the backups of the plant shown are (remembered per plant; "backups" beside it).
    QString backupFolder() const;
    void setBackupFolder(const QString &directory);

    // What is known of the plant's drives; the jobs keep it, the view shows it.
    PlantState *state() const { return m_state; }
    PlantModel *model() const { return m_model; }
    QTreeView *view() const { return m_view; }
    Job job() const { return m_job; }
    PlantReportDialog *reportDialog() const { return m_report; }
    // How the jobs' clients wait for an answer (a search asks 240 addresses with this wait).
    void setClientOptions(const ClientOptions &options) { m_clientOptions = options; }
    // Asked at each Download All: journal what it writes (Drive > Journal Every Write), into
    // the window's journal. Unset: not journaled.
    void setJournaled(std::function<bool()> journaled) { m_journaled = std::move(journaled); }

    QAction *findAction() const { return m_findAction; }
    QAction *backupAction() const { return m_backupAction; }
    QAction *verifyAction() const { return m_verifyAction; }
    QAction *downloadAction() const { return m_downloadAction; }
    QAction *stopAction() const { return m_stopAction; }
    QAction *compareAction() const { return m_compareAction; }
    QAction *historyAction() const { return m_historyAction; }
    // Checked: each Back Up All becomes a revision of the backup folder's repository, as
    // `plant backup --commit` makes it. Remembered.
    QAction *commitAction() const { return m_commitAction; }
    // A finished backup is being committed (git runs in the thread pool).
    bool isCommitting() const { return m_committing; }
    PlantHistoryWindow *historyWindow() const;

    // The drive at `index` in the window's editor: its session connects to the drive.
    void openDrive(const QModelIndex &index);
    // The two drives selected, read afresh, to the compare window (compareRequested).
    void compareSelected();
    // The file `file` (named `name`: a drive's file at a revision) as A, the drive `drive`
    // ("cabinet-5") read afresh as B, to the compare window.
    void compareWithDrive(const QString &file, const QString &name, const QString &drive);
    // The backup folder's revisions in the history window, made at the first call.
    void showHistory();
    // A revision's files (`files`, kept until the download is done) to the drives, as
    // Download All does it: its last look first, then the writing and one report.
    void restoreRevision(std::shared_ptr<QTemporaryDir> files, const QString &revision);
    void updateActions();

signals:
    // Two drives read whole, each into a parameter file: A and B of the compare window, named
    // as readings of the drives (not to be written into).
    void compareRequested(const QString &fileA, const QString &nameA, const QString &fileB,
                          const QString &nameB);
    // A plant file was shown (to be remembered among the recent ones).
    void plantOpened(const QString &path);

private:
    void createActions();
    void addLink();
    void chooseBackupFolder();
    void showPlantTitle();
    // Every drive's row (column 0), link by link; its text is its name ("cabinet-5").
    QList<QModelIndex> driveRows() const;
    void fitColumns();
    QList<QModelIndex> selectedDrives() const;
    // PlantDockJobs.cpp
    void startJob(Job job, const Plant &plant, const QString &directory);
    void onJobFinished();
    void findFinished(const PlantRun &run);
    void downloadPlanned(const QList<PlantDrive> &drives);
    // The drives read afresh into files of their own, then to the compare window.
    void readToCompare(const QList<QModelIndex> &drives);
    void compareRead(const QList<PlantDrive> &drives);
    // PlantDockCommit.cpp: after Back Up All, with Commit to History checked.
    void createCommitAction();
    // `plant` as the run left it (a DIN link searched holds the addresses found).
    void commitBackup(const Plant &plant, const QList<PlantDrive> &drives, const QString &summary);
    // A drive that failed on the line the editor holds: its reason says to disconnect first.
    PlantDrive explained(PlantDrive drive) const;
    void showMessage(const QString &text);

    WindowFrame &m_frame;
    PlantState *m_state = nullptr;
    PlantModel *m_model = nullptr;
    QTreeView *m_view = nullptr;
    QToolBar *m_toolBar = nullptr;
    QLabel *m_title = nullptr;
    QLabel *m_status = nullptr;
    QString m_path;
    QPointer<PlantRun> m_run;
    Plant m_jobPlant; // the plant the job at work was given
    Job m_job = Job::None;
    ClientOptions m_clientOptions;
    std::function<bool()> m_journaled;
    std::unique_ptr<QTemporaryDir> m_compareFiles; // the drives read for a comparison
    QStringList m_compareWith; // compareWithDrive(): the file and its name; empty otherwise
    QString m_jobDirectory; // the files the job at work reads or writes
    // A revision being restored: its files and its short id; empty for Download All.
    std::shared_ptr<QTemporaryDir> m_revisionFiles;
    QString m_revision;
    QPointer<PlantHistoryWindow> m_history;
    QPointer<PlantReportDialog> m_report;
    bool m_committing = false;

    QAction *m_findAction = nullptr;
    QAction *m_backupAction = nullptr;
    QAction *m_verifyAction = nullptr;
    QAction *m_downloadAction = nullptr;
    QAction *m_stopAction = nullptr;
    QAction *m_compareAction = nullptr;
    QAction *m_historyAction = nullptr;
    QAction *m_commitAction = nullptr;
    QAction *m_addLinkAction = nullptr;
    QAction *m_folderAction = nullptr;
};

} // namespace DriveDesk
