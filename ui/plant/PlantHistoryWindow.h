#pragma once

#include "PlantHistoryReading.h"

#include <QFutureWatcher>
#include <QStringList>
#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSplitter;
class QTreeWidget;

namespace DriveDesk {

// The plant's history (the plant view's History): the revisions of the backup folder's git
// repository, newest first, filtered by drive and parameter as `plant history` filters them;
// the changes of the revision selected, in core's words (DriveChange, the lines the command
// line prints); one drive at two revisions, or at one and in the backup folder now, handed to
// the compare window; a revision's files handed to the plant's Download All to restore it.
// Non-modal. git runs in the thread pool (core's Git blocks), never in the window's thread.
class PlantHistoryWindow : public QWidget
{
    Q_OBJECT
    enum class Purpose { Compare, CompareDrive, Restore };

public:
    explicit PlantHistoryWindow(QWidget *parent = nullptr);
    ~PlantHistoryWindow() override;

    // Shows the history of the backup folder `directory` of `plantName`, whose drives are
    // `drives`, and reads it.
    void showFolder(const QString &plantName, const QString &directory, const QStringList &drives);
    // Reads the history again, as the filters say.
    void refresh();
    // Restore is offered only while the plant runs no job.
    void setRestoreAllowed(bool allowed);

    // Reading the history or a revision's files.
    bool isBusy() const { return m_readPending || m_extractPending; }
    QString message() const;
    QTreeWidget *revisionList() const { return m_revisions; }
    QListWidget *changeList() const { return m_changes; }
    QComboBox *driveFilter() const { return m_driveFilter; }
    QLineEdit *parameterFilter() const { return m_parameterFilter; }
    QComboBox *compareDrive() const { return m_compareDrive; }
    // The full ids of the revisions selected, newest first.
    QStringList selectedRevisions() const;

    // The drive chosen at the two revisions selected (A the older), or at the one selected
    // (A) and in the backup folder now (B), to the compare window.
    void compareSelected() { compare(Purpose::Compare); }
    // The drive chosen at the revision selected (A) against the drive read afresh (B).
    void compareWithDrive() { compare(Purpose::CompareDrive); }
    // The revision selected to the plant's Download All, with its last look.
    void restoreSelected();

signals:
    void compareRequested(const QString &fileA, const QString &nameA, const QString &fileB,
                          const QString &nameB);
    // The drive's file at a revision (`file`, named `name`) against `drive` read afresh.
    void compareWithDriveRequested(const QString &file, const QString &name, const QString &drive);
    // The files of `revision` (its short id) in `files`, to be downloaded to the drives.
    void restoreRequested(std::shared_ptr<QTemporaryDir> files, const QString &revision);

protected:
    void hideEvent(QHideEvent *event) override;

private:

    void onRead();
    void showRevisions(const HistoryReading &reading);
    void showChanges();
    void compare(Purpose purpose);
    void extract(const QStringList &revisions, Purpose purpose);
    void onExtracted();
    // "cabinet-5 at 3f2a1bc04e11 (2026-11-28 16:40:12)"
    QString revisionName(const QString &id) const;
    const PlantRevision *revision(const QString &id) const;
    void updateButtons();
    void showMessage(const QString &text);
    void saveSettings() const;

    QString m_directory;
    QList<PlantRevision> m_shown;
    QFutureWatcher<HistoryReading> m_reading;
    QFutureWatcher<RevisionFolders> m_extracting;
    // Until the watcher's finished() is handled: the future alone ends before that.
    bool m_readPending = false;
    bool m_extractPending = false;
    bool m_readAgain = false;
    bool m_fitColumns = true; // no column widths remembered yet
    bool m_restoreAllowed = true;
    Purpose m_purpose = Purpose::Compare;
    QStringList m_extractedIds; // what m_extracting extracts, in order
    QString m_extractedDrive;
    // The files the compare window shows: it reads them again at each Compare.
    QList<std::shared_ptr<QTemporaryDir>> m_compared;

    QLabel *m_title = nullptr;
    QComboBox *m_driveFilter = nullptr;
    QLineEdit *m_parameterFilter = nullptr;
    QSplitter *m_splitter = nullptr;
    QTreeWidget *m_revisions = nullptr;
    QListWidget *m_changes = nullptr;
    QComboBox *m_compareDrive = nullptr;
    QPushButton *m_compareButton = nullptr;
    QPushButton *m_driveButton = nullptr;
    QPushButton *m_restoreButton = nullptr;
    QLabel *m_message = nullptr;
};

} // namespace DriveDesk
