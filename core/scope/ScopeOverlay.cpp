#include "ScopeOverlay.h"

#include "ScopeFileReader.h"

#include <QFileInfo>

namespace DriveDesk {

ScopeOverlay ScopeOverlay::load(const QString &path)
{
    ScopeOverlay overlay;
    overlay.m_path = path;
    auto recording = std::make_shared<ScopeRecording>();
    if (readScopeFile(path, *recording, &overlay.m_error, &overlay.m_warnings))
        overlay.m_recording = std::move(recording);
    return overlay;
}

QString ScopeOverlay::fileName() const
{
    return QFileInfo(m_path).fileName();
}

QString ScopeOverlay::label(const QString &title) const
{
    return tr("%1 (overlay: %2)", "a channel's title, the overlay's file").arg(title, fileName());
}

ScopeOverlayShift ScopeOverlay::shiftTo(const ScopeRecording &shown,
                                        ScopeOverlayAlignment wanted) const
{
    const ScopeRecording &overlay = recording();
    ScopeOverlayShift shift;
    if (wanted == ScopeOverlayAlignment::Trigger) {
        if (shown.triggerMs && overlay.triggerMs) {
            shift.alignment = ScopeOverlayAlignment::Trigger;
            shift.shiftMs = *shown.triggerMs - *overlay.triggerMs;
            return shift;
        }
        shift.fallback = !overlay.triggerMs
            ? tr("the overlay %1 has no trigger (it is no single shot)").arg(fileName())
            : tr("the recording shown has no trigger (it is no single shot)");
    }
    shift.alignment = ScopeOverlayAlignment::Start;
    shift.shiftMs = shown.firstTime() - overlay.firstTime();
    return shift;
}

} // namespace DriveDesk
