#pragma once

#include "scope/ScopeColumnMemo.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeSample.h"

#include <QColor>
#include <QCoreApplication>
#include <QList>

#include <array>
#include <optional>

class QCPAxis;
class QCPGraph;
class QCustomPlot;

namespace DriveDesk {

// The lowest and highest display value of what a trace was fed.
struct ScopeValueSpan
{
    double low = 0;
    double high = 0;
};

// The part of a recording a redraw looks at: the visible time span, the pixel columns it is
// cut into, and the samples that exist for the view (fewer than the recording's while frozen).
struct ScopeTraceWindow
{
    qint64 fromMs = 0; // recording ms, inclusive
    qint64 toMs = 0; // recording ms, inclusive
    int columns = 1; // about the plot's width in pixels
    qsizetype sampleCount = 0; // only samples [0, sampleCount) are drawn
    qint64 originMs = 0; // the recording's first sample: key 0 s
};

class ScopeColumnGrid;

// Feeds `graph` a channel's decimated points over the grid's columns (of the samples
// [0, count)): two a column (min and max, in the order that keeps the line short), the samples
// themselves in a column of one or two, and the samples just outside, so that the line reaches
// the edges. Keys in seconds from originMs. Returns the span of the values in view; none where
// the grid holds no sample. What ScopeTraces::fill() does for each channel, and an overlay for
// its own. Columns the last fill read are taken from `memo` (the caller keep()s the grid after
// all channels).
std::optional<ScopeValueSpan> fillScopeGraph(QCPGraph *graph, const ScopeRecording &recording,
                                             int channel, const ScopeColumnGrid &grid,
                                             qsizetype count, qint64 originMs,
                                             ScopeColumnMemo &memo);

// The four channels as QCustomPlot graphs: their colours, visibility, and the value axis each
// is drawn against (the shared one on the left or its own on the right), named after the
// recording's channels ("ru.03 Actual frequency [Hz]"). fill() feeds each drawn graph the
// decimated min/max points of the window, never the samples themselves.
// The graphs and axes belong to the plot; this keeps track of them.
class ScopeTraces
{
    Q_DECLARE_TR_FUNCTIONS(ScopeTraces)
public:
    static constexpr int kChannels = ScopeSample::kChannelCount;

    explicit ScopeTraces(QCustomPlot *plot);

    // Blue, vermilion, green, wine: apart on white and for most colour-blind eyes.
    static QColor defaultColor(int channel);

    QCPGraph *graph(int channel) const { return m_traces[channel].graph; }
    // The shared axis (the plot's yAxis) or the channel's own.
    QCPAxis *valueAxis(int channel) const;
    // The shared axis first, then the own axes of the channels that have one.
    QList<QCPAxis *> valueAxes() const;

    void setVisible(int channel, bool visible);
    bool isVisible(int channel) const { return m_traces[channel].visible; }
    void setColor(int channel, const QColor &color);
    QColor color(int channel) const { return m_traces[channel].color; }
    // Moves the channel onto an axis of its own on the right (true) or back onto the shared
    // one. A new axis starts at the range of the channel's drawn points.
    void setOwnAxis(int channel, bool own);
    bool hasOwnAxis(int channel) const { return m_traces[channel].ownAxis != nullptr; }

    // Names, units and which channels the drive delivers.
    void setChannels(const ScopeChannels &channels);
    // Visible and delivered by the drive (an off channel carries nothing worth drawing).
    bool isDrawn(int channel) const;
    QList<int> drawnChannels() const;

    // Decimates each drawn channel over the window in columns of equal time
    // (ScopeColumnGrid: decimateTime()'s columns, searched once for all channels) and hands its
    // graph two points a column (min and max, in the order that keeps the line short) plus the
    // samples just outside the window, so the line reaches the edges. Columns of one or two
    // samples give the samples themselves. Hidden channels get no points.
    void fill(const ScopeRecording &recording, const ScopeTraceWindow &window);
    void clear();
    // The next fill reads every column afresh: the recording was replaced, or cleared and
    // begun again.
    void forgetColumns() { m_memo.clear(); }
    // Display values' min and max of what fill() fed a channel; none if nothing.
    std::optional<ScopeValueSpan> extent(int channel) const;
    // The points fed on the last fill, all channels.
    int pointCount() const;

private:
    struct Trace
    {
        QCPGraph *graph = nullptr;
        QCPAxis *ownAxis = nullptr;
        bool visible = true;
        QColor color;
        std::optional<ScopeValueSpan> extent;
    };

    void updateStyle(int channel);
    void updateLabels();
    QString label(int channel) const;

    QCustomPlot *m_plot = nullptr;
    std::array<Trace, kChannels> m_traces;
    ScopeChannels m_channels;
    ScopeColumnMemo m_memo; // the last fill's columns
};

} // namespace DriveDesk
