// The scope dock's overlay: a second recording, read from a file, drawn over the one shown to
// compare them (ScopeOverlay, ScopeOverlayTraces).
#include "ScopeDock.h"

#include "ScopeChart.h"

#include "client/WhenFinished.h"
#include "frame/WindowFeature.h"
#include "scope/ScopeOverlay.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QtConcurrent/QtConcurrentRun>

namespace DriveDesk {

void ScopeDock::buildOverlayMenu(QMenu *menu)
{
    menu->addAction(tr("Overlay Recording..."), this, &ScopeDock::chooseOverlay)
        ->setObjectName(QStringLiteral("scopeOverlayAction"));
    auto *alignment = new QActionGroup(menu);
    m_overlayTriggerAction = menu->addAction(tr("Align Overlay at Trigger"));
    m_overlayTriggerAction->setObjectName(QStringLiteral("scopeOverlayTriggerAction"));
    m_overlayStartAction = menu->addAction(tr("Align Overlay at Start"));
    m_overlayStartAction->setObjectName(QStringLiteral("scopeOverlayStartAction"));
    for (QAction *action : { m_overlayTriggerAction, m_overlayStartAction }) {
        action->setCheckable(true);
        action->setEnabled(false);
        alignment->addAction(action);
    }
    // The chart's default: two single shots compare best edge on edge.
    m_overlayTriggerAction->setChecked(true);
    connect(alignment, &QActionGroup::triggered, this, &ScopeDock::alignOverlay);
    m_removeOverlayAction = menu->addAction(tr("Remove Overlay"), this, &ScopeDock::removeOverlay);
    m_removeOverlayAction->setObjectName(QStringLiteral("scopeRemoveOverlayAction"));
    m_removeOverlayAction->setEnabled(false);
}

void ScopeDock::chooseOverlay()
{
    m_frame.chooseFileToRead(tr("Overlay Scope Recording"), recordingFilter(),
                             [this](const QString &path) { openOverlay(path); });
}

void ScopeDock::openOverlay(const QString &path)
{
    // A file of millions of samples takes a while to read: not in the window's thread.
    const quint64 request = ++m_overlayRequest;
    showStatus(tr("Reading %1 to draw it over the recording...").arg(path));
    whenFinished(QtConcurrent::run([path] { return ScopeOverlay::load(path); }), this,
                 [this, request](const ScopeOverlay &overlay) {
                     if (request == m_overlayRequest)
                         overlayLoaded(overlay);
                 });
}

void ScopeDock::overlayLoaded(const ScopeOverlay &overlay)
{
    if (!overlay.isLoaded())
        return showStatus(overlay.error(), true);
    m_chart->setOverlay(std::make_shared<const ScopeOverlay>(overlay));
    m_overlayTriggerAction->setEnabled(true);
    m_overlayStartAction->setEnabled(true);
    m_removeOverlayAction->setEnabled(true);
    showOverlayStatus(overlay.warnings());
}

void ScopeDock::alignOverlay()
{
    m_chart->setOverlayAlignment(m_overlayStartAction->isChecked()
                                     ? ScopeOverlayAlignment::Start
                                     : ScopeOverlayAlignment::Trigger);
    showOverlayStatus();
}

void ScopeDock::removeOverlay()
{
    ++m_overlayRequest; // a file still being read is not drawn either
    m_chart->setOverlay(nullptr);
    m_overlayTriggerAction->setEnabled(false);
    m_overlayStartAction->setEnabled(false);
    m_removeOverlayAction->setEnabled(false);
    showStatus(tr("The overlay is removed."));
}

void ScopeDock::showOverlayStatus(const QStringList &warnings)
{
    const std::shared_ptr<const ScopeOverlay> overlay = m_chart->overlay();
    const std::optional<ScopeOverlayShift> shift = m_chart->overlayShift();
    if (!overlay || !shift)
        return;
    const int samples = int(overlay->recording().buffer.count());
    QString text = shift->alignment == ScopeOverlayAlignment::Trigger
        ? tr("%1 (%Ln sample(s)) drawn over the recording, aligned at its trigger.", nullptr,
             samples)
              .arg(overlay->fileName())
        : tr("%1 (%Ln sample(s)) drawn over the recording, aligned at its start.", nullptr,
             samples)
              .arg(overlay->fileName());
    if (!shift->fallback.isEmpty())
        text = tr("%1 Not at the trigger: %2.").arg(text, shift->fallback);
    if (!warnings.isEmpty())
        text = tr("%1 %2").arg(text, warnings.join(QLatin1Char(' ')));
    showStatus(text, !warnings.isEmpty());
}

} // namespace DriveDesk
