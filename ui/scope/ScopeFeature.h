#pragma once

#include "frame/WindowFeature.h"

namespace DriveDesk {

class ScopeDock;

// The scope in the window: a dock (View > Scope, F11) that records from the session's drive.
class ScopeFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit ScopeFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void updateActions() override;
    void saveSettings() override;
    // A recording in memory only is asked about when the window closes (Save / Discard /
    // Cancel); a drive or a file shown instead leaves it as it is.
    bool holdsUnsavedWork() const override;
    void settle(Leaving leaving, std::function<void()> proceed) override;

    ScopeDock *dock() const { return m_dock; }

private:
    ScopeDock *m_dock = nullptr;
    QMetaObject::Connection m_describedConnection;
};

} // namespace DriveDesk
