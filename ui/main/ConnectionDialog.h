#pragma once

#include "link/ConnectionSettings.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace DriveDesk {

class DriveClient;

// Where to connect: a serial port, a TCP device server or the simulated drive, with protocol
// and drive address, and the recent connections to pick from. Accepting checks the entries and
// says what is wrong in words instead of closing.
class ConnectionDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ConnectionDialog(QWidget *parent = nullptr);

    // Fills the fields (and chooses the tab) from `settings`.
    void setSettings(const ConnectionSettings &settings);
    // What the fields say now; only meaningful after validate() returned true.
    ConnectionSettings settings() const;
    // Checks the fields; the problem in words (also shown in the dialog) when they do not fit.
    bool validate(QString *problem = nullptr);

    void accept() override;
    // Probes the bus for drives (DIN66019II / DIN66019) and connects to the one picked.
    void findDrives();

signals:
    // findDrives() searches through a connection of its own: `client`, until that dialog closes.
    void searchStarted(DriveDesk::DriveClient *client);

private:
    // The baud rate choice that has the client find the rate (ConnectionSettings::
    // automaticBaudRate), first in the list and the default.
    static QString automaticBaudRateText();
    bool isAutomaticBaudRate() const;
    QWidget *createSerialPage();
    QWidget *createTcpPage();
    QWidget *createSimulatedPage();
    void refreshSerialPorts();
    void fillRecent();
    void updateEnabled();
    void showProblem(const QString &problem, QWidget *field);

    QTabWidget *m_tabs = nullptr;
    QComboBox *m_serialPort = nullptr;
    QPushButton *m_refreshPorts = nullptr;
    QComboBox *m_baudRate = nullptr;
    QLineEdit *m_host = nullptr;
    QSpinBox *m_tcpPort = nullptr;
    QComboBox *m_protocol = nullptr;
    QCheckBox *m_extensions = nullptr;
    QSpinBox *m_address = nullptr;
    QPushButton *m_findDrives = nullptr;
    QListWidget *m_recent = nullptr;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    QList<ConnectionSettings> m_recentSettings;
};

} // namespace DriveDesk
