#include "MonitorFeature.h"

#include "TelegramMonitor.h"

#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"

#include <QAction>
#include <QMenu>
#include <QToolBar>

namespace DriveDesk {

MonitorFeature::MonitorFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_monitor = new TelegramMonitor(frame.frameWidget());
    if (m_monitor->objectName().isEmpty())
        m_monitor->setObjectName(QStringLiteral("telegramMonitor"));
    frame.addDock(m_monitor);

    QAction *action = m_monitor->toggleViewAction();
    action->setObjectName(QStringLiteral("monitorAction"));
    action->setText(tr("&Telegram Monitor"));
    action->setIcon(themedIcon("utilities-terminal", QStyle::SP_FileDialogDetailedView));
    action->setShortcut(QKeySequence(Qt::Key_F12));
    QMenu *view = frame.menu(WindowFrame::Menu::View);
    view->addSeparator();
    view->addAction(action);
    action->setPriority(QAction::LowPriority); // icon only: the toolbar must fit
    frame.toolBar()->addAction(action);
}

void MonitorFeature::attach(DriveSession *session)
{
    m_monitor->attach(session ? session->client() : nullptr);
    m_monitor->setDrive(nullptr);
    disconnect(m_describedConnection);
    if (!session)
        return;
    // Each scan names the parameters of the telegrams from then on, and those listed already.
    m_describedConnection = connect(session, &DriveSession::described, m_monitor,
                                    [this](const DriveDescription &drive) {
                                        m_monitor->setDrive(
                                            std::make_shared<const DriveDescription>(drive));
                                    });
}

void MonitorFeature::followClient(DriveClient *client)
{
    m_monitor->follow(client);
}

} // namespace DriveDesk
