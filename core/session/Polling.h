#pragma once

#include "session/ValueReads.h"

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include <functional>

namespace DriveDesk {

class DriveClient;

// Reads a list of values again and again: while enabled, one round (a ReadValuesJob in the
// client's thread) every interval. A round still on its way when the next is due makes that one
// skip, so a slow line never piles up requests. The connection going away switches polling off.
// Lives in the client facade's thread; the client outlives it.
class Polling : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMinimumIntervalMs = 50;
    static constexpr int kMaximumIntervalMs = 60000;

    // What one round read; the values themselves came through reading().
    struct Round : ReadingsSummary
    {
        int reads = 0;
    };

    explicit Polling(DriveClient *client, QObject *parent = nullptr);
    ~Polling() override;

    // What a round reads, asked again before every round (the level in force may have changed).
    void setReads(std::function<QList<ValueRead>()> reads);
    // Bounded to kMinimumIntervalMs..kMaximumIntervalMs.
    void setIntervalMs(int ms);
    int intervalMs() const { return m_timer.interval(); }
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }

    int roundsCompleted() const { return m_rounds; }
    int roundsSkipped() const { return m_skipped; }

signals:
    void enabledChanged(bool enabled);
    void reading(const DriveDesk::ValueReading &reading); // each value as it comes
    void roundFinished(const DriveDesk::Polling::Round &round);
    void nothingToRead();           // the list was empty when a round was due
    void stopped(bool connectionLost); // the connection went away: polling is off

private:
    void poll();
    void take(int begin, int end);
    void roundDone();
    void clientStateChanged();

    DriveClient *m_client = nullptr;
    std::function<QList<ValueRead>()> m_reads;
    QTimer m_timer;
    QFutureWatcher<ValueReading> m_round;
    Round m_current;
    bool m_running = false;
    bool m_enabled = false;
    int m_rounds = 0;
    int m_skipped = 0;
};

} // namespace DriveDesk
