#pragma once

#include "main/WindowFeature.h"

class QActionGroup;
class QComboBox;

namespace DriveDesk {

// Polling of the live values in the window: on and off, how often, remembered between runs.
class PollingFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit PollingFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void updateActions() override;
    void saveSettings() override;

private:
    void setInterval(int ms);

    QAction *m_pollingAction = nullptr;
    QActionGroup *m_intervalGroup = nullptr;
    QComboBox *m_intervalBox = nullptr;
    int m_intervalMs = 500;
};

} // namespace DriveDesk
