#include "SetsDialog.h"

#include "parameters/DriveDescription.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace DriveDesk {

static_assert(kParameterSets == 8, "one check box per set");

SetsDialog::SetsDialog(Mode mode, QWidget *parent)
    : QDialog(parent)
    , m_mode(mode)
    , m_prompt(new QLabel(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    m_prompt->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_prompt);

    if (mode == Mode::ChooseSets) {
        setWindowTitle(tr("Write to Sets"));
        m_prompt->setText(tr("Write the value to these sets:"));
        auto *grid = new QGridLayout;
        for (int set = 0; set < kParameterSets; ++set) {
            m_sets[std::size_t(set)] = new QCheckBox(this);
            grid->addWidget(m_sets[std::size_t(set)], set % 4, set / 4);
            connect(m_sets[std::size_t(set)], &QCheckBox::toggled, this, &SetsDialog::updateOk);
        }
        layout->addLayout(grid);
        auto *all = new QPushButton(tr("&All"), this);
        auto *none = new QPushButton(tr("&None"), this);
        connect(all, &QPushButton::clicked, this, [this] { setSetMask(0xFF); });
        connect(none, &QPushButton::clicked, this, [this] { setSetMask(0x00); });
        auto *row = new QHBoxLayout;
        row->addWidget(all);
        row->addWidget(none);
        row->addStretch();
        layout->addLayout(row);
    } else {
        setWindowTitle(tr("Copy Set"));
        m_prompt->setText(tr("Copy every set-programmable value of one set into another:"));
        m_from = new QComboBox(this);
        m_to = new QComboBox(this);
        for (int set = 0; set < kParameterSets; ++set) {
            m_from->addItem(QString(), set);
            m_to->addItem(QString(), set);
        }
        auto *form = new QFormLayout;
        form->addRow(tr("&From:"), m_from);
        form->addRow(tr("&To:"), m_to);
        layout->addLayout(form);
        connect(m_from, &QComboBox::currentIndexChanged, this, &SetsDialog::updateOk);
        connect(m_to, &QComboBox::currentIndexChanged, this, &SetsDialog::updateOk);
        setCopy(0, 1);
    }
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &SetsDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &SetsDialog::reject);
    updateLabels();
    updateOk();
}

void SetsDialog::setPrompt(const QString &text)
{
    m_prompt->setText(text);
}

void SetsDialog::setActiveSet(int set)
{
    m_activeSet = set;
    updateLabels();
}

QString SetsDialog::setLabel(int set) const
{
    return set == m_activeSet ? tr("Set %1 (active)").arg(set) : tr("Set %1").arg(set);
}

void SetsDialog::updateLabels()
{
    for (int set = 0; set < kParameterSets; ++set) {
        if (m_mode == Mode::ChooseSets) {
            m_sets[std::size_t(set)]->setText(setLabel(set));
        } else {
            m_from->setItemText(set, setLabel(set));
            m_to->setItemText(set, setLabel(set));
        }
    }
}

quint8 SetsDialog::setMask() const
{
    quint8 mask = 0;
    for (int set = 0; set < kParameterSets; ++set) {
        if (m_sets[std::size_t(set)] && m_sets[std::size_t(set)]->isChecked())
            mask |= quint8(1u << set);
    }
    return mask;
}

void SetsDialog::setSetMask(quint8 mask)
{
    for (int set = 0; set < kParameterSets; ++set) {
        if (m_sets[std::size_t(set)])
            m_sets[std::size_t(set)]->setChecked(mask & (1u << set));
    }
}

int SetsDialog::fromSet() const
{
    return m_from ? m_from->currentIndex() : -1;
}

int SetsDialog::toSet() const
{
    return m_to ? m_to->currentIndex() : -1;
}

void SetsDialog::setCopy(int fromSet, int toSet)
{
    if (!m_from)
        return;
    m_from->setCurrentIndex(fromSet);
    m_to->setCurrentIndex(toSet);
}

void SetsDialog::updateOk()
{
    const bool ok = m_mode == Mode::ChooseSets
        ? setMask() != 0
        : fromSet() >= 0 && toSet() >= 0 && fromSet() != toSet();
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(ok);
}

} // namespace DriveDesk
