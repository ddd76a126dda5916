#pragma once

#include "ScopeTraces.h"

#include "scope/ScopeSeries.h"
#include "scope/ScopeSeriesLevels.h"

#include <QCoreApplication>
#include <QList>

#include <memory>

class QCPAxis;
class QCPGraph;
class QCustomPlot;

namespace DriveDesk {

// The math channels as QCustomPlot graphs, each on a value axis of its own on the right (a
// derivative or an integral rarely shares a scale with its source), in colours apart from the
// four channels'. Like ScopeTraces, fill() hands each graph about two points a pixel column,
// the min and max of the column's values, never every value.
// The graphs and axes belong to the plot; this keeps track of them.
class ScopeMathTraces
{
    Q_DECLARE_TR_FUNCTIONS(ScopeMathTraces)
public:
    explicit ScopeMathTraces(QCustomPlot *plot);

    // Orange, sky blue, black, then again: the Okabe-Ito colours the channels leave.
    static QColor defaultColor(int index);

    // The traces to draw, replacing those before (a graph and an axis each), with their min/max
    // levels (ScopeMathChannels builds them in the thread pool). A trace without levels is
    // scanned value by value.
    void setSeries(const QList<std::shared_ptr<const ScopeSeries>> &series,
                   const QList<std::shared_ptr<const ScopeSeriesLevels>> &levels = {});
    const QList<std::shared_ptr<const ScopeSeries>> &series() const { return m_series; }
    int count() const { return int(m_traces.size()); }
    QCPGraph *graph(int index) const { return m_traces.at(index).graph; }
    QCPAxis *valueAxis(int index) const { return m_traces.at(index).axis; }

    // Decimates each trace over the window's time in its columns: a binary search a column
    // and its min and max from the levels, O(columns * log n); without levels O(its samples in
    // view).
    void fill(const ScopeTraceWindow &window);
    void clear();
    // Fits each trace's axis to what the last fill drew.
    void fitAxes(double margin);

private:
    struct Trace
    {
        QCPGraph *graph = nullptr;
        QCPAxis *axis = nullptr;
        std::optional<ScopeValueSpan> extent;
    };

    QCustomPlot *m_plot = nullptr;
    QList<std::shared_ptr<const ScopeSeries>> m_series;
    QList<std::shared_ptr<const ScopeSeriesLevels>> m_levels; // as m_series, or none
    QList<Trace> m_traces;
};

} // namespace DriveDesk
