#pragma once

#include "client/DriveClient.h"
#include "session/DownloadPlan.h"
#include "session/DownloadReport.h"
#include "session/EditJournal.h"

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>

#include <memory>

namespace DriveDesk {

class WriteChangesJob;

// A parameter file downloaded to a drive, from start to report, as the window and the command
// line both run it: the drive's values are read afresh, the download is planned against them
// (planned(): a last look, nothing written yet), and write() writes the plan, each value read
// back, with progress, until finished() brings the report. stop() ends it at any point: before
// write() nothing is written; while writing, the values on their way are still reported.
// Thread: the caller's; the reading and writing run in the client's thread.
class DownloadRun : public QObject
{
    Q_OBJECT
public:
    enum class Stage : quint8 { Idle, Reading, Planned, Writing, Done };

    DownloadRun(DriveClient *client, Protocol protocol, DriveDescription file,
                QObject *parent = nullptr);
    ~DownloadRun() override;

    // Every value write() writes is journaled there (docs/journal.md): its entry begun before
    // anything is sent, completed with its outcome; a journal that cannot take the entries
    // stops the download unsent. None: not journaled. The journal outlives the run.
    void setJournal(EditJournal *journal) { m_journal = journal; }

    // Reads the drive as `reading` says (where its metadata comes from), with the values of
    // every set, then plans.
    void start(ScanOptions reading = {});
    // Plans again with other options (sets chosen, forced) against the values read.
    void setOptions(const DownloadOptions &options);
    // Writes the plan. Refused (and ignored) for a plan the checks refused unless forced.
    void write();
    void stop();

    Stage stage() const { return m_stage; }
    const DownloadOptions &options() const { return m_options; }
    const DownloadPlan &plan() const { return m_plan; }
    const DriveDescription &file() const { return m_file; }
    const DriveDescription &drive() const { return m_drive; } // as read by start()

signals:
    // Reading: done and total in any unit; writing: values written of the plan's items.
    void progress(int done, int total, const QString &what);
    void planned(const DriveDesk::DownloadPlan &plan);
    // Nothing was written: the drive could not be read (or stop() came first).
    void failed(const QString &reason);
    void finished(const DriveDesk::DownloadReport &report);

private:
    void onRead();
    void onWritten();
    // Begins the entries of the plan's items [begin, end), after those begun before; false and
    // why when the journal cannot.
    bool beginJournal(int begin, int end, QString *error);
    const ParameterDescription *parameterOf(const DownloadItem &item) const;
    void completeJournal(int begin, int end);

    const QPointer<DriveClient> m_client; // gone with its session: the run then ends
    const Protocol m_protocol;
    const DriveDescription m_file;
    DownloadOptions m_options;
    DriveDescription m_drive;
    DownloadPlan m_plan;
    Stage m_stage = Stage::Idle;
    bool m_stopped = false;
    QString m_journalError; // the journal stopped the download after its first items
    QFutureWatcher<DriveDescription> m_reading;
    QFutureWatcher<WriteOutcome> m_writing;
    std::shared_ptr<WriteChangesJob> m_job;
    int m_driveAddress = -1; // the drive on the client's bus, as start() was told (ScanOptions)
    EditJournal *m_journal = nullptr;
    QList<QList<EditJournal::Entry>> m_journaled; // per item of the plan, while writing
};

} // namespace DriveDesk
