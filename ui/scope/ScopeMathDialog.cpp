#include "ScopeMathDialog.h"

#include "scope/ScopeSample.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>

namespace DriveDesk {

using Kind = ScopeMathDefinition::Kind;
using WindowUnit = ScopeMathDefinition::WindowUnit;

ScopeMathDialog::ScopeMathDialog(const QStringList &channels, QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Add Math Channel"));
    setObjectName(QStringLiteral("scopeMathDialog"));
    auto *form = new QFormLayout(this);
    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("scopeMathKind"));
    m_kind->addItem(tr("Derivative (d/dt)"), int(Kind::Derivative));
    m_kind->addItem(tr("Integral over time"), int(Kind::Integral));
    m_kind->addItem(tr("Difference (first − second)"), int(Kind::Difference));
    m_kind->addItem(tr("Sum (first + second)"), int(Kind::Sum));
    m_kind->addItem(tr("Moving average"), int(Kind::MovingAverage));
    form->addRow(tr("&Kind:"), m_kind);
    m_first = new QComboBox(this);
    m_first->setObjectName(QStringLiteral("scopeMathFirst"));
    m_second = new QComboBox(this);
    m_second->setObjectName(QStringLiteral("scopeMathSecond"));
    for (int channel = 0; channel < channels.size(); ++channel) {
        m_first->addItem(channels.at(channel), channel);
        m_second->addItem(channels.at(channel), channel);
    }
    m_second->setCurrentIndex(std::min(1, int(channels.size()) - 1));
    form->addRow(tr("&Channel:"), m_first);
    form->addRow(tr("&Second channel:"), m_second);
    auto *windowRow = new QHBoxLayout;
    m_window = new QDoubleSpinBox(this);
    m_window->setObjectName(QStringLiteral("scopeMathWindow"));
    m_window->setRange(0, 1e6);
    m_window->setDecimals(1);
    m_window->setValue(10);
    m_windowUnit = new QComboBox(this);
    m_windowUnit->addItem(tr("samples"), int(WindowUnit::Samples));
    m_windowUnit->addItem(tr("ms"), int(WindowUnit::Milliseconds));
    windowRow->addWidget(m_window, 1);
    windowRow->addWidget(m_windowUnit);
    form->addRow(tr("&Window:"), windowRow);
    m_problem = new QLabel(this);
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020;"));
    form->addRow(m_problem);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    form->addRow(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    for (QComboBox *box : { m_kind, m_first, m_second, m_windowUnit })
        connect(box, &QComboBox::currentIndexChanged, this, &ScopeMathDialog::checkChoice);
    connect(m_window, &QDoubleSpinBox::valueChanged, this, &ScopeMathDialog::checkChoice);
    checkChoice();
}

ScopeMathDefinition ScopeMathDialog::definition() const
{
    ScopeMathDefinition definition;
    definition.kind = Kind(m_kind->currentData().toInt());
    definition.sources = { m_first->currentData().toInt() };
    if (ScopeMathDefinition::sourceCount(definition.kind) > 1)
        definition.sources << m_second->currentData().toInt();
    if (definition.kind == Kind::MovingAverage) {
        definition.window = m_window->value();
        definition.windowUnit = WindowUnit(m_windowUnit->currentData().toInt());
    }
    return definition;
}

void ScopeMathDialog::setDefinition(const ScopeMathDefinition &definition)
{
    m_kind->setCurrentIndex(m_kind->findData(int(definition.kind)));
    m_first->setCurrentIndex(m_first->findData(definition.sources.value(0)));
    if (definition.sources.size() > 1)
        m_second->setCurrentIndex(m_second->findData(definition.sources.at(1)));
    m_window->setValue(definition.window);
    m_windowUnit->setCurrentIndex(m_windowUnit->findData(int(definition.windowUnit)));
}

void ScopeMathDialog::checkChoice()
{
    const Kind kind = Kind(m_kind->currentData().toInt());
    m_second->setEnabled(ScopeMathDefinition::sourceCount(kind) > 1);
    m_window->setEnabled(kind == Kind::MovingAverage);
    m_windowUnit->setEnabled(kind == Kind::MovingAverage);
    const QString problem = definition().check(ScopeSample::kChannelCount);
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

} // namespace DriveDesk
