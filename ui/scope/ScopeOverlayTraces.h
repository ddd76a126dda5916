#pragma once

#include "ScopeCursorReadout.h"
#include "ScopeTraces.h"

#include "scope/ScopeOverlay.h"

#include <QCoreApplication>

#include <array>
#include <memory>
#include <optional>

class QCPAxis;
class QCPGraph;
class QCPLayer;
class QCustomPlot;

namespace DriveDesk {

// An overlay's channels (ScopeOverlay) as QCustomPlot graphs under the recording's own. Each
// compares with the shown recording's channel of the same source and id: it is drawn against
// that channel's value axis, in a lighter shade of its colour, and hidden with it. One that
// matches none is drawn on the shared axis in a light shade of its channel's default colour.
// The legend names each with the overlay's file ("ru.03 Actual frequency (overlay:
// run2.ddscope) [Hz]"). fill() reads the overlay's min/max levels over the visible time moved
// onto its time axis, as the channels do: a redraw costs the same for any length.
// The graphs belong to the plot; this keeps track of them.
class ScopeOverlayTraces
{
    Q_DECLARE_TR_FUNCTIONS(ScopeOverlayTraces)
public:
    static constexpr int kChannels = ScopeSample::kChannelCount;

    explicit ScopeOverlayTraces(QCustomPlot *plot);

    // The overlay drawn (nullptr: none); it stays until replaced or removed.
    void setOverlay(std::shared_ptr<const ScopeOverlay> overlay);
    const std::shared_ptr<const ScopeOverlay> &overlay() const { return m_overlay; }
    void setAlignment(ScopeOverlayAlignment alignment) { m_alignment = alignment; }
    ScopeOverlayAlignment alignment() const { return m_alignment; }
    // Where the overlay lies on `shown`'s time axis (ScopeOverlay::shiftTo()); none without one.
    std::optional<ScopeOverlayShift> shiftTo(const ScopeRecording &shown) const;

    // Takes each channel's match in the shown recording, its colour, axis and visibility from
    // the channels' traces: before every redraw, as the user may have changed them.
    void follow(const ScopeRecording &shown, const ScopeTraces &traces);
    // The window is in `shown`'s ms; its sample count is the shown recording's, not the
    // overlay's, which is drawn whole.
    void fill(const ScopeRecording &shown, const ScopeTraceWindow &window);
    void clear();
    // The span of the values the last fill drew against `axis`; none if nothing.
    std::optional<ScopeValueSpan> extentOn(const QCPAxis *axis) const;
    // The overlay's drawn channels at the cursors (the shown recording's ms), as
    // readScopeCursors() reads a recording: the sample at or before each. Titles as the
    // legend's (ScopeOverlay::label()); times and originMs in the shown recording's ms.
    ScopeCursorReadout read(const ScopeRecording &shown,
                            const std::array<std::optional<double>, 2> &timeMs) const;

    QCPGraph *graph(int channel) const { return m_traces[channel].graph; }
    bool isDrawn(int channel) const;
    QList<int> drawnChannels() const;

private:
    struct Trace
    {
        QCPGraph *graph = nullptr;
        int match = -1; // the shown recording's channel it compares with; -1: none
        bool drawn = false;
        std::optional<ScopeValueSpan> extent;
    };

    QCustomPlot *m_plot = nullptr;
    QCPLayer *m_layer = nullptr;
    std::shared_ptr<const ScopeOverlay> m_overlay;
    ScopeOverlayAlignment m_alignment = ScopeOverlayAlignment::Trigger;
    std::array<Trace, kChannels> m_traces;
    ScopeColumnMemo m_memo; // the last fill's columns of the overlay
};

} // namespace DriveDesk
