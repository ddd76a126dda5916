// ScopeChart: the overlay, a second recording drawn over the one shown (ScopeOverlayTraces).
#include "ScopeChart.h"

#include "ScopeCursors.h"
#include "ScopeOverlayTraces.h"

namespace DriveDesk {

void ScopeChart::setOverlay(std::shared_ptr<const ScopeOverlay> overlay)
{
    m_overlay->setOverlay(std::move(overlay));
    m_dataStale = true;
    // The legend names it, and the read-out gets its rows, before the next redraw.
    if (m_recording)
        m_overlay->follow(*m_recording, *m_traces);
    updateReadout();
    replotSoon();
}

std::shared_ptr<const ScopeOverlay> ScopeChart::overlay() const
{
    return m_overlay->overlay();
}

void ScopeChart::setOverlayAlignment(ScopeOverlayAlignment alignment)
{
    m_overlay->setAlignment(alignment);
    m_dataStale = true;
    updateReadout();
    replotSoon();
}

std::optional<ScopeOverlayShift> ScopeChart::overlayShift() const
{
    return m_recording ? m_overlay->shiftTo(*m_recording) : std::nullopt;
}

bool ScopeChart::readOverlay()
{
    const ScopeCursorReadout readout = m_recording && m_overlay->overlay()
        ? m_overlay->read(*m_recording, m_cursors->times())
        : ScopeCursorReadout();
    if (readout == m_overlayReadout)
        return false;
    m_overlayReadout = readout;
    return true;
}

} // namespace DriveDesk
