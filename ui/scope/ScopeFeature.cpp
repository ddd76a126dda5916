#include "ScopeFeature.h"

#include "ScopeDock.h"

#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"

#include <QAction>
#include <QMenu>
#include <QToolBar>

namespace DriveDesk {

ScopeFeature::ScopeFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_dock = new ScopeDock(frame, frame.frameWidget());
    frame.addDock(m_dock);
    QAction *action = m_dock->toggleViewAction();
    action->setObjectName(QStringLiteral("scopeViewAction"));
    action->setText(tr("&Scope"));
    action->setIcon(themedIcon("utilities-system-monitor", QStyle::SP_ComputerIcon));
    action->setShortcut(QKeySequence(Qt::Key_F11));
    action->setPriority(QAction::LowPriority);
    frame.menu(WindowFrame::Menu::View)->addAction(action);
    frame.toolBar()->addAction(action);
}

bool ScopeFeature::holdsUnsavedWork() const
{
    return m_dock->hasUnsavedRecording();
}

void ScopeFeature::settle(Leaving leaving, std::function<void()> proceed)
{
    if (leaving == Leaving::Window)
        m_dock->settleBeforeClosing(proceed);
    else
        proceed();
}

void ScopeFeature::attach(DriveSession *session)
{
    disconnect(m_describedConnection);
    m_dock->setClient(session ? session->client() : nullptr);
    if (!session)
        return;
    m_describedConnection = connect(session, &DriveSession::described, m_dock,
                                    [this](const DriveDescription &drive) {
                                        m_dock->setDrive(drive);
                                    });
}

void ScopeFeature::updateActions()
{
    m_dock->updateActions();
}

void ScopeFeature::saveSettings()
{
    m_dock->saveSettings();
}

} // namespace DriveDesk
