#pragma once

#include "session/Polling.h"

#include <QObject>

namespace DriveDesk {

class DriveClient;
class DriveState;

// Keeps the live values of one group (the run display "ru" unless told otherwise) fresh in the
// model: core's Polling reads the group's readable values every interval, the model announces
// only those that changed. Says once, not every round, why values could not be read. Lives in
// the GUI thread; the client and the model outlive it.
class PollingController : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMinimumIntervalMs = Polling::kMinimumIntervalMs;
    static constexpr int kMaximumIntervalMs = Polling::kMaximumIntervalMs;

    PollingController(DriveClient *client, DriveState *state, QObject *parent = nullptr);

    void setGroup(const QString &groupId); // default "ru"
    QString group() const { return m_group; }
    void setIntervalMs(int ms) { m_polling.setIntervalMs(ms); }
    int intervalMs() const { return m_polling.intervalMs(); }
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_polling.isEnabled(); }

    int roundsCompleted() const { return m_polling.roundsCompleted(); }
    int roundsSkipped() const { return m_polling.roundsSkipped(); }

signals:
    void enabledChanged(bool enabled);
    void roundFinished();
    void message(const QString &text); // why polling stopped, which values could not be read
    // A problem said with message() is over: the values are read again, or polling is off.
    void problemOver(const QString &text);

private:
    QList<ValueRead> groupReads();
    void roundDone(const Polling::Round &round);
    void say(const QString &problem);

    DriveState *m_state = nullptr;
    Polling m_polling;
    QString m_group = QStringLiteral("ru");
    // The group's reads, worked out again after the model was reset or the level changed.
    QList<ValueRead> m_reads;
    bool m_readsValid = false;
    QString m_lastProblem; // said once, not every round
};

} // namespace DriveDesk
