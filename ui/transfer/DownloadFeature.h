#pragma once

#include "frame/WindowFeature.h"
#include "parameters/DriveDescription.h"
#include "session/DownloadPlan.h"

#include <QPointer>

class QAction;

namespace DriveDesk {

class DownloadDialog;

// Downloads a parameter file to the connected drive: the checks, a last look at what will be
// written, the writing with progress and Stop, the report; then the table reads the drive
// again. One download at a time.
class DownloadFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit DownloadFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void updateActions() override;

    // The file at `path`, or the values a compare view chose (DownloadOptions::selection).
    void downloadFile(const QString &path);
    // `journalJob`: what its writes are journaled as, where not the download (a revert).
    void downloadSelection(const DriveDescription &selection, const QString &source = {},
                           const QString &journalJob = {});
    DownloadDialog *dialog() const;

private:
    bool isBusy() const; // a download dialog is open
    void download(const DriveDescription &file, const DownloadOptions &options,
                  const QString &source);

    QAction *m_action = nullptr;
    QPointer<DownloadDialog> m_dialog;
};

} // namespace DriveDesk
