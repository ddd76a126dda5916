#pragma once

#include "parameters/DriveDescription.h"

#include <QDockWidget>
#include <QSettings>

#include <memory>

class QAction;
class QCheckBox;
class QLabel;
class QLineEdit;
class QTreeView;

namespace DriveDesk {

class DriveClient;
class TrafficFilterModel;
class TrafficModel;

// The telegram monitor: a dock listing the telegrams exchanged with the drive (time,
// direction, bytes, meaning, errors highlighted), with pause, clear, a filter and saving.
// Follows the newest telegram unless the user scrolled away from the bottom.
class TelegramMonitor : public QDockWidget
{
    Q_OBJECT
public:
    explicit TelegramMonitor(QWidget *parent = nullptr);
    ~TelegramMonitor() override;

    // Connects to DriveClient::traffic (nullptr detaches). What was shown stays.
    void attach(DriveClient *client);
    // The drive the telegrams name parameters of (null: none known, e.g. before a scan).
    void setDrive(std::shared_ptr<const DriveDescription> drive);
    // Also shows the traffic of a client besides the attached one (a search for drives on a
    // connection of its own), for as long as that client lives.
    void follow(DriveClient *client);

    TrafficModel *model() const { return m_model; }
    TrafficFilterModel *filterModel() const { return m_filter; }
    QTreeView *view() const { return m_view; }

    void setPaused(bool paused);
    bool isPaused() const;
    void clear();
    void setFilterText(const QString &text);
    void setErrorsOnly(bool on);

    // Saves the telegrams the filter lets through. False, with the reason in *error and in
    // the dock, when the file cannot be written.
    bool saveTo(const QString &path, QString *error = nullptr);
    // Copies the selected rows to the clipboard, tab-separated, one line each (Ctrl+C).
    void copySelection() const;

    // What the dock says under the list: counts, dropped and held telegrams.
    QString statusText() const;
    // The outcome of the last save, empty before one.
    QString noticeText() const;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    // Where the monitor remembers its columns and the folder it saved to.
    static QSettings settings();
    QWidget *createToolBar();
    void chooseFileAndSave();
    void updateStatus();
    void updateCharactersColumn();
    void showNotice(const QString &text, bool problem);
    bool isAtBottom() const;
    void keepTopRowsInView(int removedRows);

    TrafficModel *m_model = nullptr;
    TrafficFilterModel *m_filter = nullptr;
    QTreeView *m_view = nullptr;
    QAction *m_pauseAction = nullptr;
    QAction *m_copyAction = nullptr;
    QLineEdit *m_filterEdit = nullptr;
    QCheckBox *m_errorsOnlyBox = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_notice = nullptr;
    QMetaObject::Connection m_trafficConnection;
    bool m_followNewest = true;
    bool m_inBatch = false;
};

} // namespace DriveDesk
