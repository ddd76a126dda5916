#pragma once

#include "session/ScopePolling.h"
#include "scope/ScopeClock.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include <deque>
#include <memory>

namespace DriveDesk {

class DriveClient;
class ScopeFileWriter;
struct ScopeRecording;

struct ScopeRecorderOptions
{
    ScopePollOptions polling;
    qint64 durationMs = 0; // 0: until stop(); otherwise the recording's span in drive time
    // Where to record to while recording (.ddscope), as well; empty: memory only.
    QString filePath;
};

// How a recording goes, for a status line.
struct ScopeRecorderStatus
{
    qint64 samples = 0;
    // Distinct samples: a repeated answer (ScopeBuffer::repeatsLast()) counts once.
    double rateHz = 0;    // samples a second over about the last second
    double averageHz = 0; // over the whole recording, by the drive's clock
    ScopePollCounts counts;
    qint64 discarded = 0; // answers whose timestamp went back: not stored
    qint64 repeated = 0;  // answers that repeated the sample before: stored once
    // Why recording to the file stopped (the recording in memory goes on); empty while it
    // works or when there is no file.
    QString fileError;
};

// Records the drive's scope data into a ScopeRecording: runs a ScopePollJob in the client's
// thread and, on a timer in its own thread, moves what the job collected into the recording,
// unwrapping the drive's timestamps. The window's scope and the command line both use it.
// Lives in the recording's thread; the client and the recording outlive it while it records.
class ScopeRecorder : public QObject
{
    Q_OBJECT
public:
    static constexpr int kTakeIntervalMs = 20;

    explicit ScopeRecorder(DriveClient *client, QObject *parent = nullptr);
    ~ScopeRecorder() override;

    // Starts polling into `recording`, which keeps what it holds (cleared by the caller for a
    // new one). Does nothing while a recording runs.
    void start(ScopeRecording *recording, ScopeRecorderOptions options = {});
    // Sends no more polls; the recording ends once those on the way are back (finished()).
    void stop();
    bool isRecording() const { return m_recording != nullptr; }
    ScopeRecorderStatus status() const { return m_status; }

signals:
    // Samples [first, first + count) of the recording are new.
    void samplesAppended(qsizetype first, qsizetype count);
    void statusChanged(const DriveDesk::ScopeRecorderStatus &status);
    // The recording ended: on stop(), after its duration, or because the link went away (the
    // reason says so). Everything recorded stays in the recording.
    void finished(const DriveDesk::ScopePollEnd &end);

private:
    void takeSamples();
    void pollingEnded();
    void updateRate(qint64 hostMs);
    void writeToFile(qsizetype first, qsizetype count);
    void closeFile();

    DriveClient *m_client = nullptr;
    ScopeRecording *m_recording = nullptr;
    ScopeRecorderOptions m_options;
    std::shared_ptr<ScopeInbox> m_inbox;
    std::shared_ptr<ScopePollJob> m_job;
    QFutureWatcher<ScopePollEnd> m_watcher;
    QTimer m_take;
    ScopeClock m_clock;
    ScopeRecorderStatus m_status;
    std::deque<std::pair<qint64, qint64>> m_rateWindow; // (host ms, samples so far)
    std::unique_ptr<ScopeFileWriter> m_file; // opened with the first sample
    QElapsedTimer m_sinceFlush;
};

} // namespace DriveDesk
