#include "ScopeChannelPanel.h"

#include "parameters/ParameterId.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QCompleter>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QToolButton>

namespace DriveDesk {

namespace {

// Source combo data: a bus address, or one of these.
constexpr int kAsAssigned = -2;
constexpr int kOff = ChannelAssignment::kOff;

// Told apart on white and by most colour-blind eyes (Okabe-Ito).
const std::array<QColor, 4> kDefaultColors{QColor(0x00, 0x72, 0xB2), QColor(0xD5, 0x5E, 0x00),
                                           QColor(0x00, 0x9E, 0x73), QColor(0xCC, 0x79, 0xA7)};

} // namespace

ScopeChannelPanel::ScopeChannelPanel(QWidget *parent)
    : QWidget(parent)
    , m_colors(kDefaultColors)
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Channel")), 0, 0, 1, 2);
    grid->addWidget(new QLabel(tr("Source")), 0, 2);
    grid->addWidget(new QLabel(tr("Set")), 0, 3);
    grid->addWidget(new QLabel(tr("Unit")), 0, 5);
    for (int channel = 0; channel < int(m_rows.size()); ++channel) {
        Row &row = m_rows[std::size_t(channel)];
        row.color = new QToolButton(this);
        row.color->setObjectName(QStringLiteral("scopeColor%1").arg(channel + 1));
        row.color->setToolTip(tr("Colour of channel %1").arg(channel + 1));
        row.visible = new QCheckBox(QString::number(channel + 1), this);
        row.visible->setObjectName(QStringLiteral("scopeVisible%1").arg(channel + 1));
        row.visible->setChecked(true);
        row.visible->setToolTip(tr("Show channel %1").arg(channel + 1));
        row.source = new QComboBox(this);
        row.source->setObjectName(QStringLiteral("scopeSource%1").arg(channel + 1));
        row.source->setEditable(true);
        row.source->setInsertPolicy(QComboBox::NoInsert);
        row.source->completer()->setFilterMode(Qt::MatchContains);
        row.source->completer()->setCompletionMode(QCompleter::PopupCompletion);
        row.source->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        row.source->setMinimumContentsLength(22);
        // An id typed and confirmed ("ru.3", "ru.03", "0203h") picks its source, as the table's
        // search finds it; the combo alone would only take a whole item's text.
        connect(row.source->lineEdit(), &QLineEdit::returnPressed, this,
                [this, channel] { chooseTyped(channel); });
        row.set = new QComboBox(this);
        row.set->setObjectName(QStringLiteral("scopeSet%1").arg(channel + 1));
        for (int set = 0; set < kParameterSets; ++set)
            row.set->addItem(QString::number(set), 1 << set);
        row.set->setToolTip(tr("The parameter set the drive reads channel %1 from").arg(channel + 1));
        row.ownAxis = new QCheckBox(tr("Own axis"), this);
        row.ownAxis->setObjectName(QStringLiteral("scopeOwnAxis%1").arg(channel + 1));
        row.ownAxis->setToolTip(tr("Give channel %1 a value axis of its own on the right")
                                    .arg(channel + 1));
        row.unit = new QLabel(this);
        row.unit->setMinimumWidth(48);
        grid->addWidget(row.color, channel + 1, 0);
        grid->addWidget(row.visible, channel + 1, 1);
        grid->addWidget(row.source, channel + 1, 2);
        grid->addWidget(row.set, channel + 1, 3);
        grid->addWidget(row.ownAxis, channel + 1, 4);
        grid->addWidget(row.unit, channel + 1, 5);
        paintSwatch(channel);
        fillSources(channel);

        connect(row.color, &QToolButton::clicked, this, [this, channel] { chooseColor(channel); });
        connect(row.visible, &QCheckBox::toggled, this,
                [this, channel](bool on) { emit visibilityChanged(channel, on); });
        connect(row.ownAxis, &QCheckBox::toggled, this,
                [this, channel](bool on) { emit ownAxisChanged(channel, on); });
        connect(row.set, &QComboBox::currentIndexChanged, this, [this, channel] {
            if (m_filling)
                return;
            m_wanted[std::size_t(channel)] = choices()[std::size_t(channel)];
            emit choicesChanged();
        });
        connect(row.source, &QComboBox::currentIndexChanged, this, [this, channel] {
            noteNarrowRange(channel);
            updateSet(channel);
            if (m_filling)
                return;
            m_wanted[std::size_t(channel)] = choices()[std::size_t(channel)];
            emit choicesChanged();
        });
    }
    grid->setColumnStretch(2, 1);
}

void ScopeChannelPanel::setDrive(const DriveDescription *drive)
{
    m_drive = drive;
    for (int channel = 0; channel < int(m_rows.size()); ++channel)
        fillSources(channel);
    applyWanted();
}

void ScopeChannelPanel::fillSources(int channel)
{
    QComboBox *box = m_rows[std::size_t(channel)].source;
    const QSignalBlocker blocker(box);
    box->clear();
    box->addItem(tr("As the drive has it"), kAsAssigned);
    const bool assignable = m_drive && scopeAssignmentParameters(*m_drive);
    box->setEnabled(assignable);
    box->setToolTip(assignable ? tr("The parameter the drive delivers on channel %1").arg(channel + 1)
                               : tr("This drive's channels cannot be assigned from here: they "
                                    "are recorded as the drive has them."));
    if (!assignable)
        return;
    box->addItem(tr("Off"), kOff);
    for (const ParameterDescription *parameter : scopeSources(*m_drive)) {
        box->addItem(QStringLiteral("%1  %2").arg(ParameterId::format(parameter->address, *m_drive),
                                                  parameter->name),
                     int(parameter->address));
    }
}

void ScopeChannelPanel::chooseTyped(int channel)
{
    QComboBox *box = m_rows[std::size_t(channel)].source;
    const QString typed = box->lineEdit()->text().trimmed();
    // An editable combo's currentText() is what the field shows: the item's own is chosen.
    const QString chosen = box->itemText(box->currentIndex());
    if (!m_drive || typed.isEmpty() || typed == chosen)
        return;
    int found = box->findText(typed, Qt::MatchFixedString);
    if (found < 0) {
        const QString id = typed.section(QLatin1Char(' '), 0, 0);
        if (const std::optional<quint16> address = ParameterId::parse(id, *m_drive))
            found = box->findData(int(*address));
    }
    if (found >= 0)
        box->setCurrentIndex(found);
    else
        box->lineEdit()->setText(chosen); // not a source: what is chosen stays
}

ScopeAssignment ScopeChannelPanel::choices() const
{
    ScopeAssignment choices;
    for (std::size_t channel = 0; channel < m_rows.size(); ++channel) {
        const int data = m_rows[channel].source->currentData().toInt();
        const ParameterDescription *source = sourceOf(int(channel));
        const bool perSet = source && source->isSetProgrammable();
        const auto mask = quint8(perSet ? m_rows[channel].set->currentData().toInt() : 0x01);
        if (data != kAsAssigned && m_rows[channel].source->currentIndex() >= 0)
            choices[channel] = ChannelAssignment{data, mask};
    }
    return choices;
}

void ScopeChannelPanel::setChoices(const ScopeAssignment &choices)
{
    m_wanted = choices;
    applyWanted();
}

void ScopeChannelPanel::applyWanted()
{
    m_filling = true;
    for (std::size_t channel = 0; channel < m_rows.size(); ++channel) {
        QComboBox *box = m_rows[channel].source;
        const int wanted = m_wanted[channel] ? m_wanted[channel]->source : kAsAssigned;
        const int index = box->findData(wanted);
        box->setCurrentIndex(index >= 0 ? index : 0);
        noteNarrowRange(int(channel));
        updateSet(int(channel));
        const int setIndex = m_rows[channel].set->findData(
            m_wanted[channel] ? int(m_wanted[channel]->setMask) : 0x01);
        m_rows[channel].set->setCurrentIndex(std::max(0, setIndex));
    }
    m_filling = false;
    emit choicesChanged();
}

void ScopeChannelPanel::setChannels(const ScopeChannels &channels)
{
    for (std::size_t channel = 0; channel < m_rows.size() && qsizetype(channel) < channels.size();
         ++channel) {
        const ScopeChannel &shown = channels.at(qsizetype(channel));
        QLabel *unit = m_rows[channel].unit;
        unit->setText(shown.enabled ? shown.unit() : tr("off"));
        unit->setToolTip(shown.enabled ? shown.title(int(channel)) : QString());
    }
}

void ScopeChannelPanel::setSourcesEditable(bool editable)
{
    const bool assignable = m_drive && scopeAssignmentParameters(*m_drive);
    for (int channel = 0; channel < int(m_rows.size()); ++channel) {
        m_rows[std::size_t(channel)].source->setEnabled(editable && assignable);
        updateSet(channel);
    }
}

bool ScopeChannelPanel::isChannelVisible(int channel) const
{
    return m_rows[std::size_t(channel)].visible->isChecked();
}

void ScopeChannelPanel::setChannelVisible(int channel, bool visible)
{
    m_rows[std::size_t(channel)].visible->setChecked(visible);
}

void ScopeChannelPanel::setChannelColor(int channel, const QColor &color)
{
    if (!color.isValid() || color == m_colors[std::size_t(channel)])
        return;
    m_colors[std::size_t(channel)] = color;
    paintSwatch(channel);
    emit colorChanged(channel, color);
}

bool ScopeChannelPanel::hasOwnAxis(int channel) const
{
    return m_rows[std::size_t(channel)].ownAxis->isChecked();
}

void ScopeChannelPanel::setOwnAxis(int channel, bool own)
{
    m_rows[std::size_t(channel)].ownAxis->setChecked(own);
}

void ScopeChannelPanel::chooseColor(int channel)
{
    auto *dialog = new QColorDialog(m_colors[std::size_t(channel)], this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Colour of channel %1").arg(channel + 1));
    connect(dialog, &QColorDialog::colorSelected, this,
            [this, channel](const QColor &color) { setChannelColor(channel, color); });
    dialog->open();
}

void ScopeChannelPanel::paintSwatch(int channel)
{
    QPixmap swatch(16, 16);
    swatch.fill(m_colors[std::size_t(channel)]);
    m_rows[std::size_t(channel)].color->setIcon(QIcon(swatch));
}

const ParameterDescription *ScopeChannelPanel::sourceOf(int channel) const
{
    if (!m_drive)
        return nullptr;
    const int address = m_rows[std::size_t(channel)].source->currentData().toInt();
    return address < 0 ? nullptr : m_drive->find(quint16(address));
}

void ScopeChannelPanel::updateSet(int channel)
{
    // Only a set-programmable source has a set to choose; the others are read as set 0.
    const ParameterDescription *source = sourceOf(channel);
    QComboBox *set = m_rows[std::size_t(channel)].set;
    const bool perSet = source && source->isSetProgrammable();
    set->setEnabled(perSet && m_rows[std::size_t(channel)].source->isEnabled());
    if (!perSet) {
        const QSignalBlocker blocker(set);
        set->setCurrentIndex(0);
    }
}

void ScopeChannelPanel::noteNarrowRange(int channel)
{
    if (channel < 2 || !m_drive)
        return;
    QComboBox *box = m_rows[std::size_t(channel)].source;
    const ParameterDescription *source = sourceOf(channel);
    const bool fits = !source || fitsNarrowChannel(*source);
    box->setStyleSheet(fits ? QString() : QStringLiteral("QComboBox { color: #a05a00; }"));
    box->setToolTip(fits ? tr("The parameter the drive delivers on channel %1").arg(channel + 1)
                         : tr("Channel %1 carries 16 bits: this parameter's values beyond "
                              "-32768..32767 arrive cut to their low 16 bits.")
                               .arg(channel + 1));
}

} // namespace DriveDesk
