#pragma once

#include "frame/WindowFeature.h"

#include <QPointer>

class QAction;

namespace DriveDesk {

class UploadRun;
struct UploadResult;

// File > Save Drive to File: the connected drive read afresh as an upload does (core's
// UploadRun, as `drivedesk-cli upload`) with progress and Cancel in the notice bar, and saved to
// a parameter file once the read is whole; an incomplete read is refused with a dialog naming
// what is missing, and nothing is saved. What the table shows is not what is saved. The window
// goes on with the drive.
class SaveDriveFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit SaveDriveFeature(WindowFrame &frame, QObject *parent = nullptr);

    void updateActions() override;
    bool isReadingDrive() const override { return isSavingDrive(); }

    // Reads the drive and saves it to `path`; false when it cannot start (no drive connected, a
    // scan or another save on its way).
    bool saveDriveToFile(const QString &path);
    // Save Drive to File is reading the drive.
    bool isSavingDrive() const { return !m_upload.isNull(); }

private:
    void chooseFile();
    void driveRead(const UploadResult &result, const QString &path);

    QAction *m_action = nullptr;
    QPointer<UploadRun> m_upload; // reading the drive; a child of its session
};

} // namespace DriveDesk
