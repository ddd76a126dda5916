#include "PasswordDialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QIntValidator>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace DriveDesk {

PasswordDialog::PasswordDialog(QWidget *parent)
    : QDialog(parent)
    , m_level(new QLabel(this))
    , m_password(new QLineEdit(this))
    , m_answer(new QLabel(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Enter Password"));
    setMinimumWidth(fontMetrics().averageCharWidth() * 45); // the drive's reason fits on a line
    m_level->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_password->setEchoMode(QLineEdit::Password);
    m_password->setValidator(new QIntValidator(0, kHighestPassword, m_password));
    m_password->setPlaceholderText(tr("0 to %1").arg(kHighestPassword));

    m_answer->setObjectName(QStringLiteral("passwordAnswer"));
    m_answer->setWordWrap(true);
    m_answer->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_answer->hide();

    auto *form = new QFormLayout;
    form->addRow(tr("Level in force:"), m_level);
    form->addRow(tr("&Password:"), m_password);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_answer);
    layout->addWidget(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &PasswordDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &PasswordDialog::reject);
    connect(m_password, &QLineEdit::textChanged, this, &PasswordDialog::updateOk);
    setLevel(std::nullopt);
    updateOk();
    m_password->setFocus();
}

void PasswordDialog::setLevel(std::optional<PasswordLevel> level)
{
    m_level->setText(level ? tr("%1 (%2)").arg(passwordLevelName(*level)).arg(int(*level))
                           : tr("not read yet"));
}

std::optional<int> PasswordDialog::password() const
{
    if (!m_password->hasAcceptableInput())
        return std::nullopt;
    return m_password->text().toInt();
}

void PasswordDialog::accept()
{
    const std::optional<int> number = password();
    if (!number || m_checking)
        return;
    setChecking(true);
    m_answer->setText(tr("Asking the drive ..."));
    m_answer->show();
    adjustSize();
    emit passwordEntered(*number);
}

void PasswordDialog::passwordAccepted()
{
    setChecking(false);
    QDialog::accept();
}

void PasswordDialog::passwordRefused(const QString &reason)
{
    setChecking(false);
    m_answer->setText(tr("Not accepted: %1").arg(reason));
    m_answer->show();
    adjustSize(); // room for the reason, however long
    m_password->selectAll();
    m_password->setFocus();
}

void PasswordDialog::setChecking(bool checking)
{
    m_checking = checking;
    m_password->setReadOnly(checking);
    updateOk();
}

void PasswordDialog::updateOk()
{
    m_buttons->button(QDialogButtonBox::Ok)
        ->setEnabled(!m_checking && m_password->hasAcceptableInput());
}

} // namespace DriveDesk
