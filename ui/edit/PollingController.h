#pragma once

#include "ValueReadBatch.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

namespace DriveDesk {

class DriveClient;
class ParameterModel;

// Keeps the live values of one group (the run display "ru" unless told otherwise) fresh: while
// enabled, every interval it reads the group's values into the model, which announces only the
// values that changed. A round still on its way when the next one is due makes that one skip,
// so a slow line never piles up requests. The connection going away switches polling off.
// Lives in the GUI thread; the client and the model outlive it.
class PollingController : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMinimumIntervalMs = 50;
    static constexpr int kMaximumIntervalMs = 60000;

    PollingController(DriveClient *client, ParameterModel *model, QObject *parent = nullptr);

    void setGroup(const QString &groupId); // default "ru"
    QString group() const { return m_group; }
    // Bounded to kMinimumIntervalMs..kMaximumIntervalMs; the UI offers e.g. 200..5000.
    void setIntervalMs(int ms);
    int intervalMs() const { return m_timer.interval(); }
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }

    int roundsCompleted() const { return m_rounds; }
    int roundsSkipped() const { return m_skipped; }

signals:
    void enabledChanged(bool enabled);
    void roundFinished();
    void message(const QString &text); // why polling stopped, which values could not be read

private:
    void poll();
    void roundDone();
    QList<ValueRead> groupReads();
    void clientStateChanged();

    DriveClient *m_client = nullptr;
    ParameterModel *m_model = nullptr;
    QString m_group = QStringLiteral("ru");
    QTimer m_timer;
    bool m_enabled = false;
    QPointer<ValueReadBatch> m_round; // child while a round is on its way
    // The group's reads, worked out again after the model was reset or the level changed.
    QList<ValueRead> m_reads;
    bool m_readsValid = false;
    QString m_lastProblem; // said once, not every round
    int m_rounds = 0;
    int m_skipped = 0;
};

} // namespace DriveDesk
