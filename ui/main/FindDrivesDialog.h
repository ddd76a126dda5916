#pragma once

#include "client/DriveClient.h"

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
// progress and Cancel, lists the drives that did and lets the user pick one to connect to.
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
    QList<int> foundAddresses() const { return m_found; }
    bool isSearching() const { return m_watcher.isRunning(); }

    void accept() override;
    void reject() override;

signals:
    void searchFinished();

private:
    explicit FindDrivesDialog(QWidget *parent);
    void start();
    void search();
    void cancelSearch();
    void onFinished();
    void fail(const QString &reason);
    void updateButtons();

    QPointer<DriveClient> m_client;
    std::unique_ptr<DriveClient> m_ownClient; // only when searching with settings of its own
    QFutureWatcher<QList<int>> m_watcher;
    QList<int> m_found;
    std::optional<int> m_chosen;
    QLabel *m_bus = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QListWidget *m_drives = nullptr;
    QPushButton *m_stop = nullptr;
    QPushButton *m_again = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace DriveDesk
