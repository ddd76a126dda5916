#pragma once

#include "client/DriveClient.h"
#include "parameters/PasswordLevel.h"
#include "protocol/Language.h"

#include <QMainWindow>

class QActionGroup;
class QComboBox;
class QLabel;
class QProgressBar;
class QUndoStack;

namespace DriveDesk {

class ConnectionDialog;
class DriveSession;
class NoticeBar;
class ParameterBrowser;
class ParameterModel;
class TelegramMonitor;

// DriveDesk's window: the parameter browser of the connected drive, the connection's state
// where the user looks (a notice bar and the status bar), menus and toolbar for connecting,
// refreshing, polling, undo, sets, password, drive information and the telegram monitor.
// Window layout, filters, favourites (per drive) and the last connection live in QSettings.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // `language`: the UI's, and the one the drive's texts are read in.
    explicit MainWindow(Language language = Language::English, QWidget *parent = nullptr);
    ~MainWindow() override;

    // Drops the current connection (if any) and connects to `settings`, then scans the drive.
    void connectTo(ConnectionSettings settings);
    // The connection dialog, filled with the last connection; connects when accepted. It opens
    // without waiting (open()) and closes itself.
    ConnectionDialog *openConnectionDialog();

    ParameterModel *model() const { return m_model; }
    ParameterBrowser *browser() const { return m_browser; }
    NoticeBar *noticeBar() const { return m_notice; }
    QUndoStack *undoStack() const { return m_undoStack; }
    TelegramMonitor *telegramMonitor() const { return m_monitor; }
    DriveSession *session() const { return m_session; }
    // Connected and read: values may be edited.
    bool isReady() const;

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
    void updateActions();
    // MainWindowCommands.cpp
    void findDrives();
    void resetToDefault();
    void writeToSets();
    void copySet();
    void enterPassword();
    int activeSet() const; // Fr.02 as last read, -1 when unknown
    void showDriveInformation();
    void chooseLanguage(Language language);
    void setPollingInterval(int ms);
    void about();
    // MainWindow.cpp
    void onStateChanged(DriveClient::State state);
    void onScanProgress(int value, int maximum, const QString &text);
    void onScanFinished(const QString &problem);
    void onDescribed(const DriveDescription &drive);
    void onLinkLost(const QString &reason);
    void onConnectionFailed(const QString &reason);
    void onLevelChanged(PasswordLevel level);
    void showMessage(const QString &text);
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
    TelegramMonitor *m_monitor = nullptr;
    DriveSession *m_session = nullptr; // owned; replaced on every connectTo()
    QString m_favouritesKey; // the drive's key in QSettings "favourites/"

    QLabel *m_stateLabel = nullptr;
    QLabel *m_levelLabel = nullptr;
    QLabel *m_setsLabel = nullptr;
    QLabel *m_metadataLabel = nullptr;
    QProgressBar *m_busy = nullptr;
    QComboBox *m_intervalBox = nullptr;
    int m_pollingIntervalMs = 500;

    QAction *m_connectAction = nullptr;
    QAction *m_disconnectAction = nullptr;
    QAction *m_findDrivesAction = nullptr;
    QAction *m_refreshAction = nullptr;
    QAction *m_readMetadataAction = nullptr;
    QAction *m_pollingAction = nullptr;
    QActionGroup *m_intervalGroup = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_resetAction = nullptr;
    QAction *m_writeSetsAction = nullptr;
    QAction *m_copySetAction = nullptr;
    QAction *m_passwordAction = nullptr;
    QAction *m_driveInfoAction = nullptr;
    QAction *m_monitorAction = nullptr;
    QActionGroup *m_languageGroup = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_aboutAction = nullptr;
};

} // namespace DriveDesk
