#pragma once

#include "client/DriveClient.h"
#include "parameters/DriveDescription.h"

#include <QCoreApplication>
#include <QFutureWatcher>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

namespace DriveDesk {

// Something an upload could not read: one parameter, or the drive as a whole (no id).
struct UploadGap
{
    QString id; // "op.11"; empty when the read as a whole stopped
    QString name;
    QString reason; // in words
    bool operator==(const UploadGap &) const = default;
};

// What an upload brought: a parameter file's contents read afresh and whole, or a refusal
// with everything that could not be read. A backup with holes is no backup: a refused or
// cancelled upload has nothing to save.
struct UploadResult
{
    Q_DECLARE_TR_FUNCTIONS(UploadResult)
public:
    enum class Outcome : quint8 { Complete, Refused, Cancelled };

    Outcome outcome = Outcome::Refused;
    // Complete: what the parameter file holds (ParameterList::fromScan of a full read).
    // Otherwise what was read before it ended, to look at, never to save.
    DriveDescription document;
    // Refused: why. The read as a whole first (stopped, the drive went silent), then each
    // parameter whose description or value is missing.
    QList<UploadGap> missing;

    bool isComplete() const { return outcome == Outcome::Complete; }
    // Why nothing is saved, in one sentence; empty when complete.
    QString summary() const;
    // Each gap on a line of its own: "op.11 Maximum speed forward: value of set 3: ...".
    QStringList details() const;
};

// Judges a drive read as an upload reads it (ScanOptions::parameterList): complete when the
// read went to the end and every parameter the list reads has its description and a value in
// every set it has. Write-only parameters hold their default and are not read.
UploadResult checkUpload(const DriveDescription &read);

// Saves a complete upload as a parameter file, whole or not at all (SavedFile). An upload that
// is not complete is refused with its summary, and nothing is written.
bool saveUpload(const QString &path, const UploadResult &result, QString *error = nullptr);

// A drive's parameter list read afresh for a parameter file, as the window's File > Save Drive
// to File and `drivedesk-cli upload` both run it: one client in, one UploadResult out.
// Progress and cancel; a drive that stops answering ends the read at once (refused). Runs on
// as many clients side by side as there are drives to back up.
// Thread: the caller's; the reading runs in the client's thread.
class UploadRun : public QObject
{
    Q_OBJECT
public:
    explicit UploadRun(DriveClient *client, QObject *parent = nullptr);
    ~UploadRun() override;

    // Reads the drive. `reading` says how (where the metadata comes from, the cache); what is
    // read is the upload's: every group, every parameter's description, the value of every
    // set the list reads.
    void start(ScanOptions reading = {});
    // Ends the read; finished() then says Cancelled.
    void cancel();
    bool isRunning() const { return m_running; }

signals:
    // value of maximum (1000), and what is being read.
    void progress(int value, int maximum, const QString &what);
    void finished(const DriveDesk::UploadResult &result);

private:
    void onRead();
    void onSilent();
    void end(const UploadResult &result);

    const QPointer<DriveClient> m_client; // gone with its connection: the upload then ends
    QFutureWatcher<DriveDescription> m_reading;
    bool m_running = false;
    bool m_cancelled = false;
    bool m_silent = false;
};

} // namespace DriveDesk
