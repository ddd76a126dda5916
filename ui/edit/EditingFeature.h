#pragma once

#include "main/WindowFeature.h"

class QProgressBar;

namespace DriveDesk {

// Editing in the window, of the drive or of the parameter file open instead: undo and redo,
// reset to default, write to several sets, copy a set, and the progress of the edit
// controller's long jobs.
class EditingFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit EditingFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void updateActions() override;

private:
    void resetToDefault();
    void writeToSets();
    void copySet();
    int activeSet() const; // the drive's (Fr.02); -1 when unknown or no drive

    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_resetAction = nullptr;
    QAction *m_writeSetsAction = nullptr;
    QAction *m_copySetAction = nullptr;
    QProgressBar *m_busy = nullptr;
};

} // namespace DriveDesk
