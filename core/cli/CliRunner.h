#pragma once

#include "cli/CommandLine.h"
#include "client/DriveClient.h"
#include "scope/ScopeChannel.h"
#include "session/ScopeAssignment.h"

#include <QObject>
#include <QTextStream>

#include <memory>

namespace DriveDesk {

class DriveState;
class EditJournal;
class Journal;

class CliPlant;
class DownloadRun;
struct DownloadOptions;
class ScopeRecorder;
struct ScopePollEnd;
struct ScopeRecording;

// Runs one drivedesk-cli command against a drive: connects, does the work asynchronously
// through the client, prints the result, and ends with finished(exit code).
// Exit codes: 0 done, 1 the drive refused or the work could not be completed,
// 2 bad input (refused before anything was sent), 3 no connection, or the drive stopped
// answering on the way.
class CliRunner : public QObject
{
    Q_OBJECT
public:
    explicit CliRunner(CliRequest request, QObject *parent = nullptr);
    ~CliRunner() override;

    void start();
    // Ctrl+C: a download stops after the value on its way and reports what it wrote; a scope
    // recording stops and writes what it has. False
    // when nothing is under way that must end that way: the caller may just quit.
    bool interrupt();

signals:
    void finished(int exitCode);

private:
    void enterPassword();
    void runCommand();
    void runInfo();
    void runScan();
    void runRead();
    void runWrite();
    void runLegacy();
    // Two sides (files, the drive, the defaults): exit 0 equal, 1 different, 2 a file that
    // cannot be read (CliDiff.cpp).
    void runDiff();
    void printDiff(const DriveDescription &a, const DriveDescription &b);
    // The parameter files named on the command line, read before anything is sent; false
    // (and finished with exit 2) for one that cannot be read.
    bool loadFiles();
    // Drive to file and file to drive (CliTransfer.cpp).
    void runUpload();
    void runDownload();
    void download(const DriveDescription &file, const DownloadOptions &options);
    // journal revert: the entries' values before, through the download (CliRevert.cpp).
    void runRevert();
    // Records the drive's scope data and writes it as CSV (CliScope.cpp).
    void runScope();
    // Writes the channels' sources chosen (none: leaves them), journaled where `journaled`, and
    // reads them back, then records.
    void assignChannels(const ScopeAssignment &choices, bool journaled);
    void record(const QList<ScopeChannel> &channels);
    void recorded(const ScopePollEnd &end);
    void readOfflineRecords(const QList<ScopeChannel> &channels);
    bool writeScopeCsv(); // the recording to --csv; false (and finished) when it failed
    void progressLine(int percent, const QString &text);
    // What a scan brought besides the description: its warnings, metadata from the cache.
    void noteScan(const DriveDescription &drive, const QString &cacheDirectory);
    // Finds the parameter named on the command line and reads its metadata, then calls next.
    void lookUpParameter(std::function<void(const GroupDescription &, const ParameterDescription &)> next);
    // Writes through core's ValueEdits and reads back; `described`: the parameter's metadata
    // is known (not DIN66019), so values are shown scaled.
    // The journal (--journal, or the default) opened to write; false and why when it cannot
    // take an entry.
    bool openJournal(QString *error);
    // Reads the drive's identification (In.00, In.06, In.10) into m_state for the journal,
    // and the parameter's values before the write.
    void readIdentity(quint16 address, std::function<void()> next);
    void writeValue(const QString &id, const ParameterDescription &parameter, bool described,
                    qint32 raw);
    // Scans with progress on stderr and hands the result to done.
    // Metadata of a cached kind of drive comes from the cache unless --no-cache.
    void scan(ScanOptions options, std::function<void(const DriveDescription &)> done);

    // A failure (1) while the drive has stopped answering becomes exit 3, and says so.
    void fail(int exitCode, const QString &message);
    // A request or job dropped before it had an answer: the connection went.
    void connectionClosed();
    // "scan stopped after 120 of 206 parameters": how far a reading of the drive got.
    static QString stoppedAfter(const QString &what, const DriveDescription &drive);
    void done();
    QString valueText(const ParameterDescription &parameter, qint32 raw) const;

    CliRequest m_request;
    std::unique_ptr<DriveClient> m_client;
    // What the command knows of the drive: the parameter it reads or writes, and the edit's
    // outcome, as the window's state holds them.
    DriveState *m_state = nullptr;
    std::unique_ptr<Journal> m_journal; // a write's or a download's, unless --no-journal
    std::unique_ptr<EditJournal> m_editJournal;
    QTextStream m_out;
    QTextStream m_err;
    bool m_finished = false;
    bool m_cacheNoted = false;
    QString m_silence; // why the drive counts as stopped answering (DriveClient), else empty
    QString m_linkLost; // why the link went on the way (DriveClient::linkLost), else empty
    QList<DriveDescription> m_files; // loadFiles(): the files of diff, upload, download
    DownloadRun *m_download = nullptr;
    CliPlant *m_plant = nullptr; // `plant`: every drive of a plant file
    std::unique_ptr<ScopeRecording> m_recording;
    ScopeRecorder *m_recorder = nullptr;
};

} // namespace DriveDesk
