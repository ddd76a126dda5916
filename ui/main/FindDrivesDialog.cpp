#include "FindDrivesDialog.h"

#include "bus/LinkFactory.h"
#include "protocol/Codec.h"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

constexpr int kFirstAddress = 0;
constexpr int kLastAddress = 239;

// The bus without a drive address: "DIN66019II on /dev/ttyUSB0 at 38400 baud".
QString busName(const ConnectionSettings &settings)
{
    const QString protocol = protocolName(settings.protocol).toUpper();
    switch (settings.kind) {
    case ConnectionSettings::Kind::Serial:
        return FindDrivesDialog::tr("the %1 bus on %2 at %3 baud")
            .arg(protocol, settings.device)
            .arg(settings.baudRate);
    case ConnectionSettings::Kind::Tcp:
        return FindDrivesDialog::tr("the %1 bus behind %2").arg(protocol, settings.target().mid(4));
    case ConnectionSettings::Kind::Simulated:
        break;
    }
    return FindDrivesDialog::tr("the simulated %1 bus").arg(protocol);
}

} // namespace

FindDrivesDialog::FindDrivesDialog(QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Find drives"));
    m_bus = new QLabel;
    m_bus->setWordWrap(true);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("searchProgress"));
    m_progress->setRange(0, kLastAddress - kFirstAddress + 1);
    m_progress->setValue(0);
    m_stop = new QPushButton(tr("&Stop"));
    m_stop->setObjectName(QStringLiteral("stopSearch"));
    auto *progressRow = new QHBoxLayout;
    progressRow->addWidget(m_progress, 1);
    progressRow->addWidget(m_stop);
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("searchStatus"));
    m_status->setWordWrap(true);
    m_drives = new QListWidget;
    m_drives->setObjectName(QStringLiteral("foundDrives"));

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("&Connect"));
    m_again = m_buttons->addButton(tr("Search &again"), QDialogButtonBox::ActionRole);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_bus);
    layout->addLayout(progressRow);
    layout->addWidget(m_status);
    layout->addWidget(new QLabel(tr("Drives that answered:")));
    layout->addWidget(m_drives);
    layout->addWidget(m_buttons);
    resize(540, 420); // two lines a drive: its address and its identification

    connect(m_buttons, &QDialogButtonBox::accepted, this, &FindDrivesDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &FindDrivesDialog::reject);
    connect(m_stop, &QPushButton::clicked, this, &FindDrivesDialog::stopSearch);
    connect(m_again, &QPushButton::clicked, this, &FindDrivesDialog::start);
    connect(m_drives, &QListWidget::currentRowChanged, this, &FindDrivesDialog::updateButtons);
    connect(m_drives, &QListWidget::itemActivated, this, &FindDrivesDialog::accept);
    connect(&m_watcher, &QFutureWatcherBase::progressRangeChanged, m_progress,
            &QProgressBar::setRange);
    connect(&m_watcher, &QFutureWatcherBase::progressValueChanged, m_progress,
            &QProgressBar::setValue);
    connect(&m_watcher, &QFutureWatcherBase::resultReadyAt, this, &FindDrivesDialog::onDriveFound);
    connect(&m_watcher, &QFutureWatcherBase::progressTextChanged, this, [this](const QString &text) {
        if (!m_stopRequested)
            m_status->setText(text);
    });
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &FindDrivesDialog::onFinished);
}

FindDrivesDialog::FindDrivesDialog(DriveClient *client, QWidget *parent)
    : FindDrivesDialog(parent)
{
    m_client = client;
    if (client->state() == DriveClient::State::Connected)
        m_connectedAddress = client->settings().driveAddress;
    m_bus->setText(tr("Asking every address %2..%3 on %1 whether a drive answers.")
                       .arg(busName(client->settings()))
                       .arg(kFirstAddress)
                       .arg(kLastAddress));
    start();
}

FindDrivesDialog::FindDrivesDialog(const ConnectionSettings &settings, QWidget *parent)
    : FindDrivesDialog(parent)
{
    m_ownClient = std::make_unique<DriveClient>(settings, everyLink());
    m_client = m_ownClient.get();
    m_bus->setText(tr("Asking every address %2..%3 on %1 whether a drive answers.")
                       .arg(busName(settings))
                       .arg(kFirstAddress)
                       .arg(kLastAddress));
    connect(m_client, &DriveClient::connected, this, &FindDrivesDialog::search);
    connect(m_client, &DriveClient::connectionFailed, this, &FindDrivesDialog::fail);
    connect(m_client, &DriveClient::stateChanged, this, &FindDrivesDialog::updateButtons);
    start();
}

FindDrivesDialog::~FindDrivesDialog()
{
    m_watcher.disconnect(this);
    if (m_watcher.isRunning())
        m_watcher.cancel();
}

void FindDrivesDialog::start()
{
    if (!m_client)
        return;
    if (m_client->state() == DriveClient::State::Connected) {
        search();
        return;
    }
    if (!m_ownClient) {
        fail(tr("not connected to the bus"));
        return;
    }
    m_status->setText(tr("Opening the connection..."));
    m_ownClient->connectToDrive();
    updateButtons();
}

void FindDrivesDialog::search()
{
    if (m_watcher.isRunning())
        return;
    m_drives->clear();
    m_stopRequested = false;
    m_job = std::make_shared<FindDrivesJob>(m_client->settings(), kFirstAddress, kLastAddress);
    m_progress->setRange(0, m_job->total());
    m_progress->setValue(0);
    m_status->setText(tr("Searching..."));
    m_watcher.setFuture(m_client->run(m_job));
    updateButtons();
}

void FindDrivesDialog::stopSearch()
{
    if (m_watcher.isRunning()) {
        // The search ends after the address on the way; what it found stays listed.
        m_stopRequested = true;
        m_job->requestStop();
        m_status->setText(tr("Stopping..."));
    } else if (m_ownClient && m_ownClient->state() == DriveClient::State::Connecting) {
        m_ownClient->disconnectFromDrive();
        m_status->setText(tr("Stopped."));
    }
    updateButtons();
}

void FindDrivesDialog::onDriveFound(int index)
{
    const FoundDrive drive = m_watcher.resultAt(index);
    const bool connected = m_connectedAddress == drive.address;
    const QString identification = drive.identification();
    const QString title = connected ? tr("Drive %1, connected now").arg(drive.address)
                                    : tr("Drive %1").arg(drive.address);
    const QString details = identification.isEmpty() ? tr("gave no identification")
                                                     : identification;
    auto *item = new QListWidgetItem(title + QLatin1Char('\n') + details);
    item->setData(AddressRole, drive.address);
    item->setData(IdentificationRole, identification);
    item->setData(ConnectedRole, connected);
    item->setToolTip(details);
    if (connected) {
        QFont font = item->font();
        font.setBold(true);
        item->setFont(font);
    }
    m_drives->addItem(item);
    if (!m_drives->currentItem())
        m_drives->setCurrentItem(item);
    updateButtons();
}

QList<int> FindDrivesDialog::foundAddresses() const
{
    QList<int> addresses;
    for (int row = 0; row < m_drives->count(); ++row)
        addresses.append(m_drives->item(row)->data(AddressRole).toInt());
    return addresses;
}

void FindDrivesDialog::onFinished()
{
    const QFuture<FoundDrive> future = m_watcher.future();
    const int found = m_drives->count();
    const bool complete = m_watcher.progressValue() >= m_watcher.progressMaximum();
    // The future reports progress at most every few milliseconds: the bar takes the final
    // count here, so that it says what the text says.
    m_progress->setValue(m_watcher.progressValue());
    if (future.isCanceled() || (m_stopRequested && !complete)) {
        m_status->setText(tr("Stopped after %1 of %2 addresses: %n drive(s) answered.", nullptr,
                             found)
                              .arg(m_watcher.progressValue())
                              .arg(m_watcher.progressMaximum()));
    } else if (!complete) {
        // The search ended early: the text says why (the link went away, ...).
        m_status->setText(tr("The search stopped: %1").arg(m_watcher.progressText()));
    } else if (found == 0) {
        m_status->setText(tr("No drive answered. Check the wiring, the baud rate and the "
                             "protocol."));
    } else {
        m_status->setText(tr("%n drive(s) answered.", nullptr, found));
    }
    updateButtons();
    emit searchFinished();
}

void FindDrivesDialog::fail(const QString &reason)
{
    m_status->setText(tr("Could not search: %1").arg(reason));
    updateButtons();
    emit searchFinished();
}

void FindDrivesDialog::updateButtons()
{
    const bool searching = m_watcher.isRunning()
                           || (m_ownClient
                               && m_ownClient->state() == DriveClient::State::Connecting);
    m_again->setEnabled(!searching);
    m_stop->setEnabled(searching && !m_stopRequested);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(m_drives->currentItem() != nullptr);
}

void FindDrivesDialog::accept()
{
    const QListWidgetItem *item = m_drives->currentItem();
    if (!item)
        return;
    // A drive picked while the search goes on: the rest of the search is not needed.
    if (m_watcher.isRunning())
        m_watcher.cancel();
    m_chosen = item->data(AddressRole).toInt();
    QDialog::accept();
}

void FindDrivesDialog::reject()
{
    if (m_watcher.isRunning())
        m_watcher.cancel();
    QDialog::reject();
}

} // namespace DriveDesk
