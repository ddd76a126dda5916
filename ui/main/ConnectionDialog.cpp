#include "ConnectionDialog.h"

#include "FindDrivesDialog.h"
#include "RecentConnections.h"

#include "protocol/Codec.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSpinBox>
#include <QStyle>
#include <QTabBar>
#include <QTabWidget>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

enum Tab { SerialTab, TcpTab, SimulatedTab };

constexpr int kDefaultTcpPort = 5020;
const int kBaudRates[] = { 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200 };

bool isDin(Protocol protocol)
{
    return protocol != Protocol::Hsp5;
}

} // namespace

ConnectionDialog::ConnectionDialog(QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Connect to a drive"));
    setMinimumWidth(fontMetrics().averageCharWidth() * 60);

    m_recent = new QListWidget;
    m_recent->setObjectName(QStringLiteral("recentConnections"));
    m_recent->setMaximumHeight(fontMetrics().height() * 7);
    auto *recentBox = new QGroupBox(tr("&Recent connections"));
    auto *recentLayout = new QVBoxLayout(recentBox);
    recentLayout->addWidget(m_recent);

    m_tabs = new QTabWidget;
    m_tabs->insertTab(SerialTab, createSerialPage(), tr("&Serial port"));
    m_tabs->insertTab(TcpTab, createTcpPage(), tr("&TCP"));
    m_tabs->insertTab(SimulatedTab, createSimulatedPage(), tr("Si&mulated drive"));
    // Every tab's title whole, in every language: no eliding, and no scroll arrows that push
    // the first tab half out of sight when the last one is chosen.
    m_tabs->setElideMode(Qt::ElideNone);
    m_tabs->setUsesScrollButtons(false);
    m_tabs->setMinimumWidth(m_tabs->tabBar()->sizeHint().width()
                            + 2 * style()->pixelMetric(QStyle::PM_DefaultFrameWidth));

    m_protocol = new QComboBox;
    m_protocol->setObjectName(QStringLiteral("protocol"));
    m_protocol->addItem(tr("HSP5"), int(Protocol::Hsp5));
    m_protocol->addItem(tr("DIN66019II"), int(Protocol::Din66019II));
    m_protocol->addItem(tr("DIN66019"), int(Protocol::Din66019));
    m_address = new QSpinBox;
    m_address->setObjectName(QStringLiteral("driveAddress"));
    m_address->setRange(0, 239);
    m_address->setValue(1);
    m_address->setToolTip(tr("The drive's address on a DIN66019(II) bus, 0..239"));
    m_findDrives = new QPushButton(tr("&Find drives..."));
    m_findDrives->setObjectName(QStringLiteral("findDrives"));
    m_findDrives->setToolTip(tr("Ask every address 0..239 on the bus which drives answer"));
    auto *addressRow = new QHBoxLayout;
    addressRow->addWidget(m_address, 1);
    addressRow->addWidget(m_findDrives);
    auto *addressLabel = new QLabel(tr("Drive &address:"));
    addressLabel->setBuddy(m_address);
    m_extensions = new QCheckBox(tr("The drive has DriveDesk's HSP5 e&xtensions"));
    m_extensions->setObjectName(QStringLiteral("hsp5Extensions"));
    m_extensions->setToolTip(
        tr("Services 13, 14, 19-21 and 51-53, which the HSP5 specification does not define. "
           "Only for a drive known to have them: a drive without them cannot tell where such a "
           "request ends and loses the requests that follow it."));
    auto *common = new QFormLayout;
    common->addRow(tr("&Protocol:"), m_protocol);
    common->addRow(QString(), m_extensions);
    common->addRow(addressLabel, addressRow);

    m_problem = new QLabel;
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problem->hide();

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("&Connect"));

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(recentBox);
    layout->addWidget(m_tabs);
    layout->addLayout(common);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectionDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ConnectionDialog::reject);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &ConnectionDialog::updateEnabled);
    connect(m_tabs, &QTabWidget::currentChanged, this, &ConnectionDialog::updateEnabled);
    connect(m_findDrives, &QPushButton::clicked, this, &ConnectionDialog::findDrives);
    connect(m_recent, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0 && row < m_recentSettings.size())
            setSettings(m_recentSettings[row]);
    });
    connect(m_recent, &QListWidget::itemActivated, this, &ConnectionDialog::accept);

    refreshSerialPorts();
    fillRecent();
    setSettings(RecentConnections::last());
}

QWidget *ConnectionDialog::createSerialPage()
{
    auto *page = new QWidget;
    m_serialPort = new QComboBox;
    m_serialPort->setObjectName(QStringLiteral("serialPort"));
    m_serialPort->setEditable(true);
    m_serialPort->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_serialPort->setToolTip(tr("The serial port, or type a device such as /dev/ttyUSB0 or COM3"));
    m_refreshPorts = new QPushButton(tr("R&efresh"));
    m_refreshPorts->setToolTip(tr("Look for serial ports again"));
    connect(m_refreshPorts, &QPushButton::clicked, this, &ConnectionDialog::refreshSerialPorts);
    auto *portRow = new QHBoxLayout;
    portRow->addWidget(m_serialPort, 1);
    portRow->addWidget(m_refreshPorts);
    auto *portLabel = new QLabel(tr("P&ort:"));
    portLabel->setBuddy(m_serialPort);

    m_baudRate = new QComboBox;
    m_baudRate->setObjectName(QStringLiteral("baudRate"));
    m_baudRate->setEditable(true);
    // The client tries the usual rates and takes the one the drive answers at.
    m_baudRate->addItem(automaticBaudRateText());
    for (int rate : kBaudRates)
        m_baudRate->addItem(QString::number(rate));
    m_baudRate->setCurrentIndex(0);
    m_baudRate->setToolTip(tr("Automatic tries 38400, 19200, 9600, 57600 and 115200 Bd and "
                              "takes the rate the drive answers at"));

    auto *form = new QFormLayout(page);
    form->addRow(portLabel, portRow);
    form->addRow(tr("&Baud rate:"), m_baudRate);
    return page;
}

QWidget *ConnectionDialog::createTcpPage()
{
    auto *page = new QWidget;
    m_host = new QLineEdit;
    m_host->setObjectName(QStringLiteral("host"));
    m_host->setPlaceholderText(tr("host name or IP address of the serial device server"));
    m_tcpPort = new QSpinBox;
    m_tcpPort->setObjectName(QStringLiteral("tcpPort"));
    m_tcpPort->setRange(1, 65535);
    m_tcpPort->setValue(kDefaultTcpPort);
    auto *form = new QFormLayout(page);
    form->addRow(tr("&Host:"), m_host);
    form->addRow(tr("Po&rt:"), m_tcpPort);
    return page;
}

QWidget *ConnectionDialog::createSimulatedPage()
{
    auto *page = new QWidget;
    auto *text = new QLabel(tr("A simulated KEB COMBIVERT F5 running inside DriveDesk: "
                               "every parameter, password levels, eight sets and a motor "
                               "to watch. Nothing needs to be plugged in."));
    text->setWordWrap(true);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(text);
    layout->addStretch();
    return page;
}

void ConnectionDialog::refreshSerialPorts()
{
    const QString current = m_serialPort->currentData().toString().isEmpty()
        ? m_serialPort->currentText()
        : m_serialPort->currentData().toString();
    m_serialPort->clear();
    const QList<QSerialPortInfo> ports = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &port : ports) {
        QString label = port.systemLocation();
        if (!port.description().isEmpty())
            label += QStringLiteral(" - ") + port.description();
        m_serialPort->addItem(label, port.systemLocation());
    }
    m_serialPort->setPlaceholderText(ports.isEmpty() ? tr("no serial port found") : QString());
    const int index = m_serialPort->findData(current);
    if (index >= 0)
        m_serialPort->setCurrentIndex(index);
    else
        m_serialPort->setEditText(current);
}

void ConnectionDialog::fillRecent()
{
    m_recentSettings = RecentConnections::load();
    m_recent->clear();
    for (const ConnectionSettings &settings : std::as_const(m_recentSettings))
        m_recent->addItem(RecentConnections::describe(settings));
    if (m_recentSettings.isEmpty()) {
        auto *none = new QListWidgetItem(tr("(none yet)"));
        none->setFlags(Qt::NoItemFlags);
        m_recent->addItem(none);
    }
}

void ConnectionDialog::setSettings(const ConnectionSettings &settings)
{
    switch (settings.kind) {
    case ConnectionSettings::Kind::Serial: {
        m_tabs->setCurrentIndex(SerialTab);
        const int index = m_serialPort->findData(settings.device);
        if (index >= 0)
            m_serialPort->setCurrentIndex(index);
        else
            m_serialPort->setEditText(settings.device);
        break;
    }
    case ConnectionSettings::Kind::Tcp:
        m_tabs->setCurrentIndex(TcpTab);
        m_host->setText(settings.host);
        m_tcpPort->setValue(settings.port);
        break;
    case ConnectionSettings::Kind::Simulated:
        m_tabs->setCurrentIndex(SimulatedTab);
        break;
    }
    m_baudRate->setCurrentText(settings.automaticBaudRate ? automaticBaudRateText()
                                                          : QString::number(settings.baudRate));
    m_protocol->setCurrentIndex(m_protocol->findData(int(settings.protocol)));
    m_address->setValue(settings.driveAddress);
    m_extensions->setChecked(settings.hsp5Extensions);
    m_problem->hide();
    updateEnabled();
}

QString ConnectionDialog::automaticBaudRateText()
{
    return tr("Automatic");
}

bool ConnectionDialog::isAutomaticBaudRate() const
{
    return m_baudRate->currentText().trimmed().compare(automaticBaudRateText(), Qt::CaseInsensitive)
           == 0;
}

ConnectionSettings ConnectionDialog::settings() const
{
    ConnectionSettings settings;
    switch (m_tabs->currentIndex()) {
    case SerialTab:
        settings.kind = ConnectionSettings::Kind::Serial;
        // A listed port gives its device; a device typed by hand is taken as typed.
        settings.device
            = m_serialPort->currentText() == m_serialPort->itemText(m_serialPort->currentIndex())
            ? m_serialPort->currentData().toString()
            : m_serialPort->currentText().trimmed();
        break;
    case TcpTab:
        settings.kind = ConnectionSettings::Kind::Tcp;
        settings.host = m_host->text().trimmed();
        settings.port = quint16(m_tcpPort->value());
        break;
    default:
        settings.kind = ConnectionSettings::Kind::Simulated;
        break;
    }
    settings.protocol = Protocol(m_protocol->currentData().toInt());
    settings.driveAddress = m_address->value();
    settings.baudRate = m_baudRate->currentText().trimmed().toInt();
    if (settings.baudRate <= 0)
        settings.baudRate = 38400;
    settings.automaticBaudRate = settings.kind == ConnectionSettings::Kind::Serial
                                 && isAutomaticBaudRate();
    settings.simulation.driveAddresses = { settings.driveAddress };
    settings.simulation.baudRate = settings.baudRate;
    // The simulated drive is told the same, so that it frames what the client sends.
    settings.hsp5Extensions = settings.protocol == Protocol::Hsp5 && m_extensions->isChecked();
    settings.simulation.hsp5Extensions = settings.hsp5Extensions;
    return settings;
}

bool ConnectionDialog::validate(QString *problem)
{
    QString text;
    QWidget *field = nullptr;
    if (m_tabs->currentIndex() == SerialTab) {
        bool ok = false;
        const int baud = m_baudRate->currentText().trimmed().toInt(&ok);
        if (settings().device.isEmpty()) {
            text = m_serialPort->count() == 0
                ? tr("No serial port was found. Plug in the adapter and press Refresh, "
                     "or type the device (e.g. /dev/ttyUSB0 or COM3).")
                : tr("Choose the serial port the drive is connected to.");
            field = m_serialPort;
        } else if (!isAutomaticBaudRate() && (!ok || baud < 50 || baud > 4000000)) {
            text = tr("\"%1\" is not a baud rate: enter a number such as 38400, or choose "
                      "Automatic.")
                       .arg(m_baudRate->currentText());
            field = m_baudRate;
        }
    } else if (m_tabs->currentIndex() == TcpTab) {
        const QString host = m_host->text().trimmed();
        if (host.isEmpty()) {
            text = tr("Enter the host name or IP address of the serial device server.");
            field = m_host;
        } else if (host.contains(QLatin1Char(' ')) || host.contains(QLatin1Char('/'))) {
            text = tr("\"%1\" is not a host name or IP address.").arg(host);
            field = m_host;
        }
    }
    if (problem)
        *problem = text;
    if (text.isEmpty()) {
        m_problem->hide();
        return true;
    }
    showProblem(text, field);
    return false;
}

void ConnectionDialog::showProblem(const QString &problem, QWidget *field)
{
    m_problem->setText(problem);
    m_problem->show();
    if (field)
        field->setFocus();
}

void ConnectionDialog::accept()
{
    if (!validate())
        return;
    QDialog::accept();
}

void ConnectionDialog::findDrives()
{
    if (!isDin(Protocol(m_protocol->currentData().toInt()))) {
        showProblem(tr("Finding drives needs a DIN66019II or DIN66019 bus: HSP5 is point to "
                       "point. Choose the protocol first."),
                    m_protocol);
        return;
    }
    if (!validate())
        return;
    auto *dialog = new FindDrivesDialog(settings(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        if (!dialog->chosenAddress())
            return;
        m_address->setValue(*dialog->chosenAddress());
        accept();
    });
    emit searchStarted(dialog->client());
    dialog->open();
}

void ConnectionDialog::updateEnabled()
{
    const bool din = isDin(Protocol(m_protocol->currentData().toInt()));
    m_address->setEnabled(din);
    m_findDrives->setEnabled(din);
    m_extensions->setEnabled(!din);
}

} // namespace DriveDesk
