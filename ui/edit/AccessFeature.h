#pragma once

#include "main/WindowFeature.h"
#include "parameters/PasswordLevel.h"

class QLabel;

namespace DriveDesk {

// The password level in the window: shown in the status bar, raised or lowered by a password.
class AccessFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit AccessFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void updateActions() override;

private:
    void enterPassword();

    QAction *m_passwordAction = nullptr;
    QLabel *m_levelLabel = nullptr;
};

} // namespace DriveDesk
