#pragma once

#include "scope/ScopeSeries.h"
#include "scope/ScopeSeriesLevels.h"

#include <QObject>
#include <QStringList>

#include <memory>

namespace DriveDesk {

struct ScopeRecording;
struct ScopeSnapshot;

// The math channels of the recording shown, computed (core's computeScopeMath()) in the thread
// pool from a snapshot of its samples: a million samples take tens of ms a channel. The
// definitions are the recording's own (ScopeRecording::math, kept in its file); this holds
// their traces as last computed, each with its min/max levels (built in the pool too, so that
// the chart draws a math trace as fast as a channel), and computes them again when asked.
// While one computing runs, a newer request waits (only the newest); the traces come with
// seriesChanged().
class ScopeMathChannels : public QObject
{
    Q_OBJECT
public:
    explicit ScopeMathChannels(QObject *parent = nullptr);

    // Computes the recording's math channels over its first `sampleCount` samples; none when
    // it has no definitions (seriesChanged() with an empty list).
    void compute(const ScopeRecording &recording, qsizetype sampleCount);
    bool isComputing() const { return m_running; }
    // The traces, in the order of the definitions (one that could not be computed is left
    // out, and its reason is in errors()).
    const QList<std::shared_ptr<const ScopeSeries>> &series() const { return m_series; }
    // Each trace's min/max levels, built with it in the thread pool, for drawing.
    const QList<std::shared_ptr<const ScopeSeriesLevels>> &levels() const { return m_levels; }
    const QStringList &errors() const { return m_errors; }

signals:
    void seriesChanged();

private:
    struct Request;
    struct Result
    {
        QList<std::shared_ptr<const ScopeSeries>> series;
        QList<std::shared_ptr<const ScopeSeriesLevels>> levels;
        QStringList errors;
    };
    void start(std::shared_ptr<const Request> request);

    bool m_running = false;
    std::shared_ptr<const Request> m_waiting;
    quint64 m_generation = 0;
    QList<std::shared_ptr<const ScopeSeries>> m_series;
    QList<std::shared_ptr<const ScopeSeriesLevels>> m_levels;
    QStringList m_errors;
};

} // namespace DriveDesk
