#pragma once

#include "DriveFavourites.h"
#include "frame/WindowFeature.h"

#include "client/DriveClient.h"

#include <QMainWindow>
#include <QPointer>

#include <functional>
#include <optional>

class QActionGroup;
class QFileDialog;
class QLabel;
class QMessageBox;

namespace DriveDesk {

class ConnectionDialog;
class DriveSession;
class NoticeBar;
class ParameterBrowser;
class DriveState;
class ParameterModel;

// DriveDesk's window, a frame: the parameter browser of the connected drive or of a parameter
// file shown instead of one (one thing at a time), the connection's state where the user looks
// (a notice bar and the status bar), connecting, refreshing and drive information. The file
// commands, editing, polling, the password level and the telegram monitor are features
// (WindowFeatures.cpp) that put their actions in its menus and toolbar and follow its session.
// Window layout, filters, favourites (per drive) and the last connection live in QSettings.
class MainWindow : public QMainWindow, public WindowFrame
{
    Q_OBJECT
public:
    // `language`: the UI's, and the one the drive's texts are read in.
    explicit MainWindow(Language language = Language::English, QWidget *parent = nullptr);
    ~MainWindow() override;

    // Closes the current connection (if any), waits until its link is closed, then connects to
    // `settings` and scans the drive. What the window shows stays until the new connection
    // stands: a connection that fails loses nothing.
    void connectTo(ConnectionSettings settings) override;
    // The connection dialog, filled with the last connection; connects when accepted. It opens
    // without waiting (open()) and closes itself.
    ConnectionDialog *openConnectionDialog();

    // The feature of that class (WindowFeatures.cpp), for the program's start and the tests:
    // window.feature<ParameterFileFeature>()->openParameterFile(path).
    template<typename Feature>
    Feature *feature() const
    {
        for (WindowFeature *each : m_features) {
            if (auto *found = qobject_cast<Feature *>(each))
                return found;
        }
        return nullptr;
    }

    // WindowFrame
    QWidget *frameWidget() override { return this; }
    // MainWindowFiles.cpp: the parameter file shown instead of a drive, absolute; empty while
    // none is. Edits go into it (the editing feature's DocumentEditor) until it is saved.
    QString parameterFilePath() const override { return m_filePath; }
    void showParameterFile(const DriveDescription &drive, const QString &path) override;
    void renameParameterFile(const QString &path) override;
    QMenu *menu(Menu menu) override;
    QToolBar *toolBar() override { return m_toolBar; }
    void addStatusWidget(QWidget *widget) override;
    void addDock(QDockWidget *dock) override;
    NoticeBar *noticeBar() const override { return m_notice; }
    ParameterModel *model() const override { return m_model; }
    DriveState *state() const override { return m_state; }
    ParameterBrowser *browser() const override { return m_browser; }
    QUndoStack *undoStack() const override { return m_undoStack; }
    Language language() const override { return m_language; }
    DriveSession *session() const override { return m_session; }
    bool isReady() const override;
    ParameterEditing *editing() const override;
    void showMessage(const QString &text) override;
    void withdrawMessage(const QString &text) override;
    void chooseParameterFile(const QString &title,
                             std::function<void(const QString &path)> chosen) override;
    void chooseFileToRead(const QString &title, const QString &filter,
                          std::function<void(const QString &path)> chosen) override;
    void chooseFileToWrite(const QString &title, const QString &name, const QString &filter,
                           std::function<bool(const QString &path)> chosen) override;
    void updateActions() override;

signals:
    // The scan finished and the model holds the drive (or the scan stopped: see the notice).
    void driveRead();

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    // MainWindowActions.cpp
    void createActions();
    void createMenus();
    void createToolBar();
    void createStatusBar();
    void finishMenus();
    // MainWindowCommands.cpp
    void findDrives();
    void showDriveInformation();
    void chooseLanguage(Language language);
    void about();
    // MainWindowFiles.cpp
    // `name`: a file name to suggest; empty for a dialog that opens a file.
    QFileDialog *fileDialog(const QString &title, const QString &name = {},
                           const QString &filter = {});
    // The file shown goes (its changes with it), and the table empties.
    void closeParameterFile();
    // Runs `proceed` once every feature from `from` on has settled its unsaved work
    // (WindowFeature::settle); never when the user chose to stay.
    void settleFeatures(WindowFeature::Leaving leaving, std::function<void()> proceed,
                        qsizetype from = 0);
    bool holdsUnsavedWork() const;
    // Runs `proceed` when nothing is at `path`, or once the user agreed to replace it.
    void confirmReplace(const QString &path, const std::function<void()> &proceed);
    void updateFileTitle();
    // MainWindow.cpp
    void openNextSession();
    // The session goes at once: its link closes, its undo history goes.
    void closeSession();
    // MainWindowSession.cpp
    void onStateChanged(DriveClient::State state);
    void onScanProgress(int value, int maximum, const QString &text);
    void onScanFinished(const QString &problem);
    void onDescribed(const DriveDescription &drive);
    void onLinkLost(const QString &reason);
    void onConnectionFailed(const QString &reason);
    void onDriveSilentChanged(bool silent);
    // MainWindow.cpp
    void reconnect();
    void disconnectFromDrive();
    void refresh();
    // A feature reads the whole drive (WindowFeature::isReadingDrive()).
    bool isReadingDrive() const;
    void restoreSettings();
    void saveSettings();

    Language m_language = Language::English;
    DriveState *m_state = nullptr; // the drive or the file shown
    ParameterModel *m_model = nullptr;
    QUndoStack *m_undoStack = nullptr;
    ParameterBrowser *m_browser = nullptr;
    NoticeBar *m_notice = nullptr;
    DriveSession *m_session = nullptr; // owned; replaced on every connectTo()
    QString m_filePath; // of the parameter file shown; empty while none is
    bool m_closeAnyway = false; // the features' unsaved work was settled on closing
    // connectTo() while connected: where to connect once the old link is closed.
    std::optional<ConnectionSettings> m_nextSettings;
    QList<WindowFeature *> m_features; // children
    DriveFavourites m_favourites;
    QString m_silenceNotice; // the notice shown while the drive does not answer

    QMenu *m_fileMenu = nullptr;
    QMenu *m_driveMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QToolBar *m_toolBar = nullptr;
    QLabel *m_stateLabel = nullptr;
    QLabel *m_metadataLabel = nullptr;

    QAction *m_connectAction = nullptr;
    QAction *m_disconnectAction = nullptr;
    QAction *m_findDrivesAction = nullptr;
    QAction *m_refreshAction = nullptr;
    QAction *m_readMetadataAction = nullptr;
    QAction *m_driveInfoAction = nullptr;
    QActionGroup *m_languageGroup = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_aboutAction = nullptr;
};

} // namespace DriveDesk
