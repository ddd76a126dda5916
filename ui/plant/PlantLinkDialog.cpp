#include "PlantLinkDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace DriveDesk {

PlantLinkDialog::PlantLinkDialog(const Plant &plant, bool newPlant, QWidget *parent)
    : QDialog(parent)
    , m_plant(plant)
{
    setObjectName(QStringLiteral("plantLinkDialog"));
    setWindowTitle(newPlant ? tr("New Plant") : tr("Add Link"));
    auto *form = new QFormLayout;
    if (newPlant) {
        m_machine = new QLineEdit(plant.name);
        m_machine->setObjectName(QStringLiteral("plantMachineEdit"));
        form->addRow(tr("&Machine:"), m_machine);
    }
    m_name = new QLineEdit;
    m_name->setObjectName(QStringLiteral("plantLinkNameEdit"));
    m_name->setPlaceholderText(tr("cabinet"));
    m_name->setToolTip(tr("Names the link in reports and in the names of the drives' files"));
    form->addRow(tr("Link &name:"), m_name);
    m_connect = new QLineEdit;
    m_connect->setObjectName(QStringLiteral("plantConnectEdit"));
    m_connect->setPlaceholderText(tr("tcp:HOST:PORT, serial:DEVICE or sim"));
    form->addRow(tr("Connec&t:"), m_connect);
    m_protocol = new QComboBox;
    m_protocol->setObjectName(QStringLiteral("plantProtocolBox"));
    for (Protocol protocol : { Protocol::Hsp5, Protocol::Din66019II, Protocol::Din66019 })
        m_protocol->addItem(protocolName(protocol), QVariant::fromValue(int(protocol)));
    form->addRow(tr("&Protocol:"), m_protocol);
    m_baud = new QLineEdit;
    m_baud->setObjectName(QStringLiteral("plantBaudEdit"));
    m_baud->setPlaceholderText(tr("the protocol's default"));
    form->addRow(tr("&Baud rate:"), m_baud);
    m_addresses = new QLineEdit;
    m_addresses->setObjectName(QStringLiteral("plantAddressesEdit"));
    m_addresses->setPlaceholderText(tr("2, 5, 9; empty: search the bus"));
    m_addresses->setToolTip(tr("DIN66019(II): the drive addresses on the bus. HSP5 has one "
                               "drive a line and no addresses."));
    form->addRow(tr("&Addresses:"), m_addresses);
    m_problem = new QLabel;
    m_problem->setObjectName(QStringLiteral("plantLinkProblem"));
    m_problem->setWordWrap(true);
    m_problem->hide();
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &PlantLinkDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
}

std::optional<Plant> PlantLinkDialog::read(QString *error) const
{
    Plant plant = m_plant;
    if (m_machine)
        plant.name = m_machine->text().trimmed();
    PlantLink link;
    link.name = m_name->text().trimmed();
    link.connect = m_connect->text().trimmed();
    link.protocol = Protocol(m_protocol->currentData().toInt());
    if (!m_baud->text().trimmed().isEmpty()) {
        bool ok = false;
        link.baudRate = m_baud->text().trimmed().toInt(&ok);
        if (!ok) {
            *error = tr("The baud rate '%1' is not a whole number.").arg(m_baud->text().trimmed());
            return std::nullopt;
        }
    }
    const QStringList addresses = m_addresses->text().split(
        QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
    for (const QString &text : addresses) {
        bool ok = false;
        link.addresses.append(text.toInt(&ok));
        if (!ok) {
            *error = tr("The address '%1' is not a whole number.").arg(text);
            return std::nullopt;
        }
    }
    plant.links.append(link);
    return plant;
}

Plant PlantLinkDialog::plant() const
{
    QString error;
    return read(&error).value_or(m_plant);
}

QString PlantLinkDialog::problem() const
{
    return m_problem->isHidden() ? QString() : m_problem->text();
}

void PlantLinkDialog::accept()
{
    QString error;
    const std::optional<Plant> plant = read(&error);
    // The plant file's reader says what may be in a plant file: what it refuses is not taken.
    if (plant)
        PlantFile::fromJson(PlantFile::toJson(*plant), &error);
    if (!error.isEmpty()) {
        m_problem->setText(error);
        m_problem->show();
        return;
    }
    QDialog::accept();
}

} // namespace DriveDesk
