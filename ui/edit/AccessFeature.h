#pragma once

#include "frame/WindowFeature.h"
#include "parameters/PasswordLevel.h"

class QLabel;

namespace DriveDesk {

class AccessController;

// The password level in the window: shown in the status bar, raised or lowered by a password,
// read by an AccessController made for each session once the drive is read.
class AccessFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit AccessFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void updateActions() override;

signals:
    // The level read rose above the one known before: what it opens can be read now.
    void levelRaised(DriveDesk::PasswordLevel from, DriveDesk::PasswordLevel to);

private:
    void enterPassword();

    QAction *m_passwordAction = nullptr;
    QLabel *m_levelLabel = nullptr;
    AccessController *m_access = nullptr; // child, of the session of the moment
};

} // namespace DriveDesk
