#pragma once

#include "WindowFeature.h"

#include "client/DriveClient.h"

#include <QMainWindow>

#include <optional>

class QActionGroup;
class QLabel;

namespace DriveDesk {

class ConnectionDialog;
class DriveSession;
class NoticeBar;
class ParameterBrowser;
class ParameterModel;

// DriveDesk's window, a frame: the parameter browser of the connected drive, the connection's
// state where the user looks (a notice bar and the status bar), connecting, refreshing and drive
// information. Editing, polling, the password level and the telegram monitor are features
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
    void connectTo(ConnectionSettings settings);
    // The connection dialog, filled with the last connection; connects when accepted. It opens
    // without waiting (open()) and closes itself.
    ConnectionDialog *openConnectionDialog();

    NoticeBar *noticeBar() const { return m_notice; }

    // WindowFrame
    QWidget *frameWidget() override { return this; }
    QMenu *menu(Menu menu) override;
    QToolBar *toolBar() override { return m_toolBar; }
    void addStatusWidget(QWidget *widget) override;
    void addDock(QDockWidget *dock) override;
    ParameterModel *model() const override { return m_model; }
    ParameterBrowser *browser() const override { return m_browser; }
    QUndoStack *undoStack() const override { return m_undoStack; }
    DriveSession *session() const override { return m_session; }
    bool isReady() const override;
    void showMessage(const QString &text) override;
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
    // MainWindow.cpp
    void openNextSession();
    void onStateChanged(DriveClient::State state);
    void onScanProgress(int value, int maximum, const QString &text);
    void onScanFinished(const QString &problem);
    void onDescribed(const DriveDescription &drive);
    void onLinkLost(const QString &reason);
    void onConnectionFailed(const QString &reason);
    void onDriveSilentChanged(bool silent);
    void updateSetsLabel();
    void reconnect();
    void disconnectFromDrive();
    void refresh();
    void saveFavourites();
    void restoreSettings();
    void saveSettings();

    Language m_language = Language::English;
    ParameterModel *m_model = nullptr;
    QUndoStack *m_undoStack = nullptr;
    ParameterBrowser *m_browser = nullptr;
    NoticeBar *m_notice = nullptr;
    DriveSession *m_session = nullptr; // owned; replaced on every connectTo()
    // connectTo() while connected: where to connect once the old link is closed.
    std::optional<ConnectionSettings> m_nextSettings;
    QList<WindowFeature *> m_features; // children
    QString m_favouritesKey; // the drive's key in QSettings "favourites/"
    QString m_silenceNotice; // the notice shown while the drive does not answer

    QMenu *m_driveMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QToolBar *m_toolBar = nullptr;
    QLabel *m_stateLabel = nullptr;
    QLabel *m_setsLabel = nullptr;
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
