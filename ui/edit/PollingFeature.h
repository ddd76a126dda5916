#pragma once

#include "frame/WindowFeature.h"

class QActionGroup;
class QComboBox;

namespace DriveDesk {

class PollingController;

// Polling of the live values in the window: on and off, how often, remembered between runs.
// A PollingController made for each session polls while it is on and the drive is connected,
// read and not being scanned.
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
    void applyPolling();

    QAction *m_pollingAction = nullptr;
    QActionGroup *m_intervalGroup = nullptr;
    QComboBox *m_intervalBox = nullptr;
    int m_intervalMs = 500;
    PollingController *m_polling = nullptr; // child, of the session of the moment
};

} // namespace DriveDesk
