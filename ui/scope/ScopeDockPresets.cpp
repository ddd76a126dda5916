// The scope dock's presets: the set-up saved under a name, for this kind of drive, beside the
// plant while one is open, and loaded again (docs/scope.md, "Presets"). Where they live and
// what a file holds is core's (ScopePresetLibrary, ScopePresetFile).
#include "ScopeDock.h"

#include "ScopeChannelPanel.h"

#include "scope/ScopePresetLibrary.h"
#include "session/ScopeChannelsJob.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QToolBar>
#include <QToolButton>

#include <cmath>

namespace DriveDesk {

void ScopeDock::buildPresetButton(QToolBar *bar)
{
    m_presetMenu = new QMenu(tr("Presets"), bar);
    m_presetMenu->setObjectName(QStringLiteral("scopePresetMenu"));
    // Filled as it opens: the files may have changed, and so may the drive and the plant.
    connect(m_presetMenu, &QMenu::aboutToShow, this, &ScopeDock::fillPresetMenu);
    auto *button = new QToolButton(bar);
    button->setObjectName(QStringLiteral("scopePresetButton"));
    button->setText(tr("Presets"));
    button->setToolTip(tr("Save the channels, trigger, roll and rate limit under a name, or "
                          "load a set-up saved for this kind of drive"));
    button->setMenu(m_presetMenu);
    button->setPopupMode(QToolButton::InstantPopup);
    bar->addWidget(button);
}

void ScopeDock::setPlantFile(const QString &path)
{
    m_plantFile = path;
}

void ScopeDock::fillPresetMenu()
{
    m_presetMenu->clear();
    const bool busy = isRecording() || m_assigning || m_readingOffline;
    QAction *save = m_presetMenu->addAction(tr("Save Preset As..."), this,
                                            &ScopeDock::choosePresetName);
    save->setObjectName(QStringLiteral("scopeSavePresetAction"));
    save->setEnabled(m_hasDrive);
    m_presetMenu->addSeparator();
    if (!m_hasDrive) {
        m_presetMenu->addAction(tr("Connect to a drive to load its presets"))->setEnabled(false);
        return;
    }
    QStringList problems;
    const QList<ScopePresetEntry> entries
        = ScopePresetLibrary(m_plantFile).list(scopeDriveKind(m_drive), &problems);
    for (const ScopePresetEntry &entry : entries) {
        QString text = entry.preset.name;
        text.replace(QLatin1Char('&'), QStringLiteral("&&"));
        if (entry.besidePlant)
            text = tr("%1 (plant)").arg(text);
        QAction *load = m_presetMenu->addAction(text, this, [this, path = entry.path] {
            loadPreset(path);
        });
        load->setObjectName(QStringLiteral("scopePresetAction"));
        load->setData(entry.path);
        load->setToolTip(QDir::toNativeSeparators(entry.path));
        // While recording the sources cannot change.
        load->setEnabled(!busy);
    }
    if (entries.isEmpty())
        m_presetMenu->addAction(tr("No presets for this kind of drive"))->setEnabled(false);
    if (!problems.isEmpty())
        showStatus(tr("Some presets cannot be read: %1").arg(problems.join(QStringLiteral("; "))),
                   true);
}

void ScopeDock::choosePresetName()
{
    auto *dialog = new QInputDialog(this);
    dialog->setObjectName(QStringLiteral("scopePresetNameDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Save Preset"));
    dialog->setLabelText(m_plantFile.isEmpty()
                             ? tr("Name of the preset for this kind of drive:")
                             : tr("Name of the preset, kept beside the plant %1:")
                                   .arg(QDir::toNativeSeparators(m_plantFile)));
    dialog->setTextValue(m_presetName);
    connect(dialog, &QInputDialog::textValueSelected, this, [this](const QString &name) {
        const QString existing = ScopePresetLibrary(m_plantFile).savePath(name);
        if (!name.trimmed().isEmpty() && QFileInfo::exists(existing))
            return askToReplacePreset(name, existing);
        saveAndSayPreset(name);
    });
    dialog->open();
}

void ScopeDock::askToReplacePreset(const QString &name, const QString &path)
{
    auto *question = new QMessageBox(
        QMessageBox::Question, tr("Save Preset"),
        tr("A preset named '%1' is already saved in %2. Replace it?")
            .arg(name.trimmed(), QDir::toNativeSeparators(QFileInfo(path).absolutePath())),
        QMessageBox::Cancel, this);
    question->setObjectName(QStringLiteral("scopePresetReplaceQuestion"));
    question->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton *replace = question->addButton(tr("&Replace"), QMessageBox::AcceptRole);
    question->setDefaultButton(QMessageBox::Cancel);
    connect(replace, &QPushButton::clicked, this, [this, name] { saveAndSayPreset(name); });
    question->open();
}

void ScopeDock::saveAndSayPreset(const QString &name)
{
    QString path;
    QString error;
    if (savePreset(name, &path, &error))
        showStatus(tr("Preset '%1' saved in %2.").arg(name.trimmed(), QDir::toNativeSeparators(path)));
    else
        showStatus(error, true);
}

ScopePreset ScopeDock::currentPreset(const QString &name) const
{
    ScopePreset preset;
    preset.name = name.trimmed();
    preset.driveKind = m_hasDrive ? scopeDriveKind(m_drive) : QString();
    const ScopeAssignment wanted = m_panel->wantedChoices();
    for (int channel = 0; channel < int(preset.channels.size()); ++channel) {
        ScopePresetChannel &saved = preset.channels[std::size_t(channel)];
        if (const std::optional<ChannelAssignment> &choice = wanted[std::size_t(channel)])
            saved.source = scopeSourceText(*choice, m_drive);
        saved.color = m_panel->channelColor(channel).name();
        saved.visible = m_panel->isChannelVisible(channel);
        saved.ownAxis = m_panel->hasOwnAxis(channel);
    }
    preset.trigger = triggerSettings();
    preset.rollSeconds = m_rollSeconds->value();
    preset.rateLimitHz = m_rateLimit->value();
    return preset;
}

bool ScopeDock::savePreset(const QString &name, QString *path, QString *error)
{
    if (name.trimmed().isEmpty()) {
        if (error)
            *error = tr("A preset needs a name.");
        return false;
    }
    if (!ScopePresetLibrary(m_plantFile).save(currentPreset(name), path, error))
        return false;
    m_presetName = name.trimmed();
    return true;
}

void ScopeDock::loadPreset(const QString &path)
{
    QString error;
    const std::optional<ScopePreset> preset = ScopePresetFile::load(path, &error);
    if (!preset)
        return showStatus(error, true);
    const QStringList problems = applyPreset(*preset);
    m_presetName = preset->name;
    if (problems.isEmpty())
        showStatus(tr("Preset '%1' loaded.").arg(preset->name));
    else
        showStatus(tr("Preset '%1' loaded, but: %2")
                       .arg(preset->name, problems.join(QLatin1Char(' '))),
                   true);
}

QStringList ScopeDock::applyPreset(const ScopePreset &preset)
{
    QStringList problems;
    // Sources first: the trigger level takes the decimals of its channel's source.
    ScopeAssignment choices;
    const bool assignable = m_hasDrive && scopeAssignmentParameters(m_drive);
    for (std::size_t channel = 0; channel < preset.channels.size(); ++channel) {
        const std::optional<ScopeSourceText> &source = preset.channels[channel].source;
        if (!source)
            continue;
        QString why;
        std::optional<ChannelAssignment> choice = scopeSourceOn(*source, m_drive, &why);
        if (choice) {
            ScopeAssignment one;
            one[channel] = choice;
            why = planScopeChannels(m_drive, one).error;
        }
        if (!why.isEmpty()) {
            problems << tr("Channel %1 (%2): %3").arg(channel + 1).arg(source->text(), why);
            // Not what the drive happens to have: that would be recorded as if it were asked for.
            choice = assignable ? std::optional(ChannelAssignment{}) : std::nullopt;
        }
        choices[channel] = choice;
    }
    m_panel->setChoices(choices);
    for (int channel = 0; channel < int(preset.channels.size()); ++channel) {
        const ScopePresetChannel &looks = preset.channels[std::size_t(channel)];
        if (!looks.color.isEmpty())
            m_panel->setChannelColor(channel, QColor(looks.color));
        m_panel->setChannelVisible(channel, looks.visible);
        m_panel->setOwnAxis(channel, looks.ownAxis);
    }
    const ScopeTriggerSettings &trigger = preset.trigger;
    m_triggerChannel->setCurrentIndex(trigger.channel);
    m_triggerEdge->setCurrentIndex(m_triggerEdge->findData(int(trigger.edge)));
    m_triggerLevel->setValue(trigger.level);
    m_triggerPre->setValue(int(std::lround(trigger.preTriggerShare * 100.0)));
    m_triggerWindow->setValue(double(trigger.windowMs) / 1000.0);
    m_rollSeconds->setValue(preset.rollSeconds);
    m_rateLimit->setValue(preset.rateLimitHz);
    return problems;
}

} // namespace DriveDesk
