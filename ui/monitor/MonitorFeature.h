#pragma once

#include "frame/WindowFeature.h"

namespace DriveDesk {

class TelegramMonitor;

// The telegram monitor in the window: a dock that follows the session's client.
class MonitorFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit MonitorFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void followClient(DriveClient *client) override;

private:
    TelegramMonitor *m_monitor = nullptr;
    QMetaObject::Connection m_describedConnection;
};

} // namespace DriveDesk
