#pragma once

#include "frame/WindowFeature.h"
#include "parameters/DriveDescription.h"
#include "session/DownloadPlan.h"

#include <QPointer>

#include <functional>

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
    // `what`: the values in words, as the last look names them (none: the compare window's
    // choice); `journalJob`: what its writes are journaled as, where not the download (a revert).
    void downloadSelection(const DriveDescription &selection, const QString &what = {},
                           const QString &journalJob = {});
    DownloadDialog *dialog() const;
    // Asked at each download: journal its writes (Drive > Journal Every Write), into the
    // window's journal. Unset: not journaled.
    void setJournaled(std::function<bool()> journaled) { m_journaled = std::move(journaled); }

private:
    bool isBusy() const; // a download dialog is open
    // `job`: how the journal names it ("download of f5.json").
    void download(const DriveDescription &file, const DownloadOptions &options,
                  const QString &source, const QString &job);

    QAction *m_action = nullptr;
    QPointer<DownloadDialog> m_dialog;
    std::function<bool()> m_journaled;
};

} // namespace DriveDesk
