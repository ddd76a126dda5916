#pragma once

#include "session/ValueReads.h"

#include <QFutureWatcher>
#include <QList>
#include <QObject>
#include <QString>

namespace DriveDesk {

class DriveClient;
class DriveState;

// Runs a ReadValuesJob in the client's thread and puts what the drive answers into the model as
// it comes (setValue: only a value that changed is announced). A read the drive refuses is
// recorded; when the connection fails the job stops and says why. Lives in the GUI thread.
class ValueReadBatch : public QObject
{
    Q_OBJECT
public:
    ValueReadBatch(DriveClient *client, DriveState *state, QList<ValueRead> reads,
                   QObject *parent = nullptr);
    ~ValueReadBatch() override;

    void start();
    // Sends nothing more; finished() follows when the reads on the way are back.
    void cancel();

    int total() const { return int(m_reads.size()); }
    int done() const { return m_done; }
    bool isRunning() const { return m_running; }
    bool wasCancelled() const { return m_cancelled; }
    const QList<ValueReading> &failures() const { return m_summary.failures; }
    // Why the batch stopped before reading everything (the connection failed), or empty.
    const QString &stopReason() const { return m_summary.stopReason; }

signals:
    void progress(int done, int total);
    void finished();

private:
    void take(int begin, int end);
    void jobFinished();

    DriveClient *m_client = nullptr;
    DriveState *m_state = nullptr;
    QList<ValueRead> m_reads;
    QFutureWatcher<ValueReading> m_watcher;
    int m_done = 0;
    bool m_running = false;
    bool m_cancelled = false;
    ReadingsSummary m_summary;
};

} // namespace DriveDesk
