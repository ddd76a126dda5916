#pragma once

#include "client/Reply.h"
#include "parameters/DriveDescription.h"
#include "parameters/PasswordLevel.h"

#include <QList>
#include <QObject>
#include <QString>

namespace DriveDesk {

class DriveClient;
class ParameterModel;

// One value to read: service 0 for one set of a set-programmable parameter, service 1 set 0 for
// the one value of any other parameter, as the drive scan reads them.
struct ValueRead
{
    quint16 address = 0;
    int set = 0;
    bool perSet = false;
};

// Every value of the parameter: one read per set, or the one value.
QList<ValueRead> valueReadsOf(const ParameterDescription &parameter);
// Whether the level in force lets the parameter be read at all.
bool isReadable(const ParameterDescription &parameter, PasswordLevel level);

// Reads a list of values and puts what the drive answers into the model (setValue: only a value
// that changed is announced). At most a few requests are on the client's queue at a time, so
// that a write the user asks for meanwhile is not stuck behind hundreds of reads. A read the
// drive refuses is recorded and the batch goes on; when the connection fails it stops.
// Lives in the GUI thread.
class ValueReadBatch : public QObject
{
    Q_OBJECT
public:
    struct Failure
    {
        quint16 address = 0;
        int set = 0;
        QString reason;
    };

    ValueReadBatch(DriveClient *client, ParameterModel *model, QList<ValueRead> reads,
                   QObject *parent = nullptr);

    void start();
    // Sends nothing more; finished() follows when the reads on the way are back.
    void cancel();

    int total() const { return int(m_reads.size()); }
    int done() const { return m_done; }
    bool isRunning() const { return m_running; }
    bool wasCancelled() const { return m_cancelled; }
    const QList<Failure> &failures() const { return m_failures; }
    // Why the batch stopped before reading everything (the connection failed), or empty.
    const QString &stopReason() const { return m_stopReason; }

signals:
    void progress(int done, int total);
    void finished();

private:
    void sendMore();
    void handle(const ValueRead &read, const Reply &reply);

    static constexpr int kWindow = 4; // HSP5's requests on the wire; DIN queues them

    DriveClient *m_client = nullptr;
    ParameterModel *m_model = nullptr;
    QList<ValueRead> m_reads;
    qsizetype m_next = 0;
    int m_onTheWay = 0;
    int m_done = 0;
    bool m_running = false;
    bool m_cancelled = false;
    QList<Failure> m_failures;
    QString m_stopReason;
};

} // namespace DriveDesk
