#pragma once

#include "frame/WindowFeature.h"

#include <QPointer>

class QAction;
class QMessageBox;

namespace DriveDesk {

// File > Open, Save and Save As: a parameter file shown and edited with no drive (the frame
// shows it, the editing feature edits it), saved atomically, and the question Save / Discard /
// Cancel before its unsaved changes would go (another file, a connection, closing the window).
class ParameterFileFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit ParameterFileFeature(WindowFrame &frame, QObject *parent = nullptr);

    // Shows the parameter file at `path` instead of a drive, once the unsaved changes of the
    // file shown are saved or discarded (asked first; never after Cancel). False, with a message
    // naming the line and column, when the file cannot be read: then nothing changes.
    bool openParameterFile(const QString &path);
    // The file shown, to its own path or to another, which it is then; false with the reason
    // in a message (the file on disk is left as it was).
    bool saveParameterFile();
    bool saveParameterFileAs(const QString &path);
    // The file shown was changed since it was opened or saved (undoing back clears this).
    bool hasUnsavedChanges() const;

    // WindowFeature
    void updateActions() override;
    bool holdsUnsavedWork() const override { return hasUnsavedChanges(); }
    // The file's changes, whatever the window leaves: it shows one thing at a time.
    void settle(Leaving leaving, std::function<void()> proceed) override;

private:
    void chooseFileToOpen();
    void chooseFileToSaveAs();
    void showFile(const DriveDescription &drive, const QString &path);
    bool reportProblem(const QString &title, const QString &text);

    QAction *m_openAction = nullptr;
    QAction *m_saveAction = nullptr;
    QAction *m_saveAsAction = nullptr;
    QPointer<QMessageBox> m_unsavedQuestion; // asking Save / Discard / Cancel, at most one
};

} // namespace DriveDesk
