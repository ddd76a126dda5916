#pragma once

#include "client/DriveClient.h"
#include "client/FindDrivesJob.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QPointer>

#include <memory>
#include <optional>

class QDialogButtonBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;

namespace DriveDesk {

// Asks every address 0..239 of a DIN66019II (or DIN66019) bus whether a drive answers, with
// progress and Stop. Lists each drive as it answers, with its identification and a mark on the
// one the window is connected to, keeps them when stopped, and lets the user pick one to
// connect to.
class FindDrivesDialog : public QDialog
{
    Q_OBJECT
public:
    // Searches through a client already connected to the bus (not owned).
    explicit FindDrivesDialog(DriveClient *client, QWidget *parent = nullptr);
    // Opens a connection of its own with `settings` for the search.
    explicit FindDrivesDialog(const ConnectionSettings &settings, QWidget *parent = nullptr);
    ~FindDrivesDialog() override;

    // The address of the drive picked, once the dialog was accepted.
    std::optional<int> chosenAddress() const { return m_chosen; }
    QList<int> foundAddresses() const;
    bool isSearching() const { return m_watcher.isRunning(); }
    // The client the search talks through: the window's, or the dialog's own.
    DriveClient *client() const { return m_client; }

    // The data of a found drive's row besides its text.
    enum Role {
        AddressRole = Qt::UserRole,     // int
        IdentificationRole,             // QString, empty where the drive gave none
        ConnectedRole,                  // bool: the drive the window is connected to now
    };

    void accept() override;
    void reject() override;

signals:
    void searchFinished();

private:
    explicit FindDrivesDialog(QWidget *parent);
    void start();
    void search();
    void stopSearch();
    void onDriveFound(int index);
    void onFinished();
    void fail(const QString &reason);
    void updateButtons();

    QPointer<DriveClient> m_client;
    std::unique_ptr<DriveClient> m_ownClient; // only when searching with settings of its own
    std::shared_ptr<FindDrivesJob> m_job; // the search running or last run
    QFutureWatcher<FoundDrive> m_watcher;
    std::optional<int> m_connectedAddress; // the drive the client is connected to, if any
    std::optional<int> m_chosen;
    bool m_stopRequested = false;
    QLabel *m_bus = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QListWidget *m_drives = nullptr;
    QPushButton *m_stop = nullptr;
    QPushButton *m_again = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace DriveDesk
