#pragma once

#include "WindowFrame.h"

#include <QObject>

#include <functional>

namespace DriveDesk {

// One feature of the window (editing, polling, the password level, the telegram monitor): it
// owns its actions and widgets, puts them in the frame when it is made, and follows the drive
// session. A feature is added to the window in WindowFeatures.cpp, and nowhere else.
class WindowFeature : public QObject
{
    Q_OBJECT
public:
    explicit WindowFeature(WindowFrame &frame, QObject *parent = nullptr)
        : QObject(parent)
        , m_frame(frame)
    { }

    // A new session replaces the old one (already gone), or nullptr: none any more.
    virtual void attach(DriveSession *session) { Q_UNUSED(session) }
    // The window shows the parameter file at `path` (absolute; the model holds it) instead of a
    // drive, or none any more (empty). No session is attached while a file is shown.
    virtual void attachFile(const QString &path) { Q_UNUSED(path) }
    // A client besides the session's talks on a bus for a while (finding drives before
    // connecting); it goes away on its own.
    virtual void followClient(DriveClient *client) { Q_UNUSED(client) }
    // The connection, the scan, the selection or a job changed.
    virtual void updateActions() { }
    // Where the window's edits go while this feature takes them (the drive's edits once it is
    // read, the parameter file shown); nullptr otherwise. WindowFrame::editing() asks each.
    virtual ParameterEditing *editing() const { return nullptr; }
    // The feature reads the whole drive on its own (Save Drive to File): the frame's Refresh and
    // Read Metadata Again wait for it.
    virtual bool isReadingDrive() const { return false; }
    // The window closes: what the feature remembers goes to QSettings.
    virtual void saveSettings() { }
    // What the window is about to leave when it asks its features to settle.
    enum class Leaving {
        Shown,  // what it shows: another parameter file or a drive comes instead
        Window, // the window closes, and everything in it
    };
    // The feature holds work that closing the window would lose (a parameter file's changes,
    // a scope recording in memory only).
    virtual bool holdsUnsavedWork() const { return false; }
    // `proceed` runs once what leaving would lose of this feature's work is saved or given up
    // (asked about if need be), never when the user chose to stay. The frame asks every
    // feature in turn.
    virtual void settle(Leaving leaving, std::function<void()> proceed)
    {
        Q_UNUSED(leaving)
        proceed();
    }

protected:
    WindowFrame &frame() const { return m_frame; }

private:
    WindowFrame &m_frame;
};

} // namespace DriveDesk
