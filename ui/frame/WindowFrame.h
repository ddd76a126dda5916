#pragma once

#include "link/ConnectionSettings.h"

#include <QString>

#include <functional>

class QAction;
class QDockWidget;
class QMenu;
class QToolBar;
class QUndoStack;
class QWidget;

namespace DriveDesk {

class DriveClient;
struct DriveDescription;
class DriveSession;
class DriveState;
class NoticeBar;
class ParameterBrowser;
class ParameterEditing;
class ParameterModel;

// What a feature sees of the window it works in: the places for its actions and widgets, what
// the window shows, and the drive session of the moment. MainWindow is the one frame.
class WindowFrame
{
public:
    enum class Menu { File, Drive, Edit, View };

    virtual ~WindowFrame() = default;

    virtual QWidget *frameWidget() = 0; // the parent of the feature's dialogs and docks
    virtual QMenu *menu(Menu menu) = 0;
    virtual QToolBar *toolBar() = 0;
    virtual void addStatusWidget(QWidget *widget) = 0;
    virtual void addDock(QDockWidget *dock) = 0; // at the bottom, hidden until asked for
    // The bar across the top that says what is going on: a feature's long job shows its
    // progress there, and Cancel (cancelClicked) stops it.
    virtual NoticeBar *noticeBar() const = 0;

    // The drive (or parameter file) the window shows, held once; what features read and
    // change. model() shows it in the table.
    virtual DriveState *state() const = 0;
    virtual ParameterModel *model() const = 0;
    virtual ParameterBrowser *browser() const = 0;
    virtual QUndoStack *undoStack() const = 0;
    // The UI's language, the one the drives' texts are read in.
    virtual Language language() const = 0;
    // Closes the connection of the moment (if any) and connects to `settings`, reading the
    // drive (its metadata from the cache where its kind was read before).
    virtual void connectTo(ConnectionSettings settings) = 0;
    // The connection and its controllers; nullptr before the first connect.
    virtual DriveSession *session() const = 0;
    // Connected to a drive and read.
    virtual bool isReady() const = 0;
    // The parameter file the window shows instead of a drive; empty while it shows none.
    virtual QString parameterFilePath() const = 0;
    // Shows `drive`, read from the parameter file at `path`, instead of a drive: a connected
    // drive is disconnected, every feature attaches the file (WindowFeature::attachFile), the
    // title names it and marks its unsaved changes (the undo stack's).
    virtual void showParameterFile(const DriveDescription &drive, const QString &path) = 0;
    // The file shown was saved under another name: it is that file now.
    virtual void renameParameterFile(const QString &path) = 0;
    // Where edits go now: the drive's edit controller (connected and read) or the editor of the
    // parameter file shown instead of a drive, whichever feature offers it; nullptr while
    // nothing may be edited.
    virtual ParameterEditing *editing() const = 0;

    virtual void showMessage(const QString &text) = 0;
    // Takes `text` off the status bar if it still shows it: what it said is no longer so.
    virtual void withdrawMessage(const QString &text) = 0;
    // Asks for a parameter file to read, in a dialog that does not block; `chosen` runs with
    // its path once the user picked one.
    virtual void chooseParameterFile(const QString &title,
                                     std::function<void(const QString &path)> chosen) = 0;
    // The same for any kind of file (`filter` like "Scope recordings (*.ddscope)").
    virtual void chooseFileToRead(const QString &title, const QString &filter,
                                  std::function<void(const QString &path)> chosen) = 0;
    // Asks where to write a file (`filter` like "CSV files (*.csv)"), and whether to replace one
    // that is there; `chosen` runs with the path once the user agreed and says whether the file
    // was written (or its writing began): only then is its folder the next dialog's.
    virtual void chooseFileToWrite(const QString &title, const QString &name,
                                   const QString &filter,
                                   std::function<bool(const QString &path)> chosen) = 0;
    // Something an action depends on changed: every feature's actions enable as they apply.
    virtual void updateActions() = 0;
};

} // namespace DriveDesk
