// The scope dock's recording: channels assigned, the recorder, the trigger, offline records.
#include "ScopeDock.h"

#include "ScopeChannelPanel.h"
#include "ScopeChart.h"
#include "ScopeMathChannels.h"

#include "client/DriveClient.h"
#include "client/WhenFinished.h"
#include "frame/ParameterEditing.h"
#include "frame/WindowFeature.h"
#include "model/ParameterModel.h"
#include "scope/ScopeRecording.h"
#include "session/ScopeChannelsJob.h"
#include "session/ScopeOfflineJob.h"
#include "state/ScopeChannelEdits.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFutureWatcher>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QSpinBox>

namespace DriveDesk {

void ScopeDock::toggleRecording(bool on)
{
    if (on)
        startRecording();
    else
        stopRecording();
}

void ScopeDock::startRecording()
{
    if (!m_client || !m_recorder || isRecording() || m_assigning)
        return updateActions();
    // Nothing records while the question is open: the actions show it, and a single shot
    // asked for comes back with the answer.
    const bool shot = m_triggerAction->isChecked();
    m_triggerAction->setChecked(false);
    updateActions();
    // Titled after what was asked for: Record, or a single shot (armed by its own button).
    confirmReplacing(shot ? m_triggerAction->text().remove(QLatin1Char('&')) : tr("Record"),
                     tr("The recording shown is not saved. A new recording replaces it."),
                     [this, shot] {
                         m_triggerAction->setChecked(shot);
                         startRecordingNow();
                     });
}

void ScopeDock::startRecordingNow()
{
    // The channels are written the way the table's edits are, ordered with them.
    ParameterEditing *editing = m_frame.editing();
    ValueEdits *edits = editing ? editing->driveEdits() : nullptr;
    if (!m_client || !m_recorder || isRecording() || m_assigning || !edits)
        return updateActions();
    // The sources first, written and read back: the recording shows what the drive delivers.
    m_assigning = true;
    updateActions();
    showStatus(tr("Assigning the channels..."));
    assignScopeChannels(*edits, m_drive, m_panel->choices(),
                        [this](const ScopeChannelsOutcome &outcome) { channelsAssigned(outcome); });
}

void ScopeDock::showAssignmentInTable(const ScopeAssignment &assignment)
{
    // The table shows Sy.16..Sy.23 too: it shows what the drive holds now, not what was read
    // before the scope wrote them. Not when the window shows a parameter file instead.
    const auto parameters = scopeAssignmentParameters(m_drive);
    ParameterModel *model = m_frame.model();
    if (!parameters || !model || !m_frame.parameterFilePath().isEmpty())
        return;
    for (std::size_t channel = 0; channel < assignment.size(); ++channel) {
        if (!assignment[channel])
            continue;
        // The assignment parameters hold one value (not set-programmable on an F5): set 0.
        model->state()->setValue(parameters->source[channel], 0, assignment[channel]->source);
        model->state()->setValue(parameters->setMask[channel], 0, assignment[channel]->setMask);
    }
}

void ScopeDock::channelsAssigned(const ScopeChannelsOutcome &outcome)
{
    m_assigning = false;
    showAssignmentInTable(outcome.assignment);
    if (!outcome.error.isEmpty() || !m_recorder) {
        m_triggerAction->setChecked(false);
        updateActions();
        return showStatus(tr("The channels could not be assigned: %1").arg(outcome.error), true);
    }
    auto recording = std::make_unique<ScopeRecording>();
    recording->channels = scopeChannels(m_drive, outcome.assignment);
    recording->source = m_client ? m_client->settings().displayName() : QString();
    // The math channels go on with the next recording: they are the user's way to read one.
    recording->math = m_recording->math;
    replaceRecording(std::move(recording));
    if (m_triggerAction->isChecked()) {
        m_trigger.setSettings(triggerSettings());
        m_trigger.arm(0);
    } else {
        m_chart->setFollow(true);
    }
    ScopeRecorderOptions options;
    options.polling.maxRateHz = m_rateLimit->value();
    options.filePath = m_recordFile;
    m_recorder->start(m_recording.get(), options);
    showStatus(tr("Recording..."));
    updateActions();
}

void ScopeDock::stopRecording()
{
    if (m_recorder)
        m_recorder->stop();
    updateActions();
}

void ScopeDock::replaceRecording(std::unique_ptr<ScopeRecording> recording)
{
    // The chart lets go of the old recording before it goes.
    m_chart->setRecording(recording.get());
    m_recording = std::move(recording);
    m_panel->setChannels(m_recording->channels);
    triggerChannelChanged();
    computeMath();
}

void ScopeDock::samplesAppended()
{
    m_chart->samplesAppended();
    // Computed again as the recording grows, but never queued behind a computing that runs.
    if (!m_recording->math.isEmpty() && !m_math->isComputing())
        computeMath();
    if (!m_triggerAction->isChecked() || m_trigger.state() == ScopeTrigger::State::Idle)
        return;
    const ScopeTrigger::State before = m_trigger.state();
    const ScopeTrigger::State now = m_trigger.update(*m_recording);
    if (now == ScopeTrigger::State::Triggered && before != now)
        showStatus(tr("Triggered; recording the rest of the shot..."));
    if (now == ScopeTrigger::State::Complete) {
        // The shot is cut out of the recording once the polls on their way are in
        // (recordingFinished()).
        m_triggerAction->setChecked(false);
        stopRecording();
    }
}

void ScopeDock::recorderStatus(const ScopeRecorderStatus &status)
{
    const QLocale locale;
    QString text = tr("%1 samples, %2 Hz (average %3 Hz), %4 lost, %5 failed")
                       .arg(locale.toString(status.samples))
                       .arg(locale.toString(status.rateHz, 'f', 0))
                       .arg(locale.toString(status.averageHz, 'f', 1))
                       .arg(status.counts.lost)
                       .arg(status.counts.failed);
    if (m_triggerAction->isChecked() && m_trigger.state() == ScopeTrigger::State::Armed)
        text = tr("Waiting for the trigger; %1").arg(text);
    if (!status.fileError.isEmpty())
        return showStatus(tr("%1. Not recording to the file any more: %2").arg(text, status.fileError),
                          true);
    if (!m_recordFile.isEmpty())
        text = tr("%1; into %2").arg(text, m_recordFile);
    showStatus(text);
}

void ScopeDock::recordingFinished(const ScopePollEnd &end)
{
    const ScopeRecorderStatus status = m_recorder->status();
    recorderStatus(status);
    m_unsaved = m_recordFile.isEmpty() || !status.fileError.isEmpty();
    if (m_trigger.state() == ScopeTrigger::State::Complete) {
        keepShot();
        return updateActions();
    }
    if (m_triggerAction->isChecked()) {
        m_triggerAction->setChecked(false);
        m_trigger.disarm();
    }
    if (!end.reason.isEmpty()) {
        showStatus(tr("Recording stopped: %1. The %Ln sample(s) recorded are kept.", nullptr,
                      int(status.samples))
                       .arg(end.reason),
                   true);
    } else if (status.fileError.isEmpty()) {
        showStatus(tr("Recorded %Ln sample(s) at %1 Hz on average; %2 lost, %3 failed.", nullptr,
                      int(status.samples))
                       .arg(QLocale().toString(status.averageHz, 'f', 1))
                       .arg(end.counts.lost)
                       .arg(end.counts.failed));
    }
    computeMath(); // with every sample, whatever was computed on the way
    updateActions();
}

void ScopeDock::keepShot()
{
    // The shot and its pre-trigger time, not the wait before it nor what came after.
    const qint64 triggerMs = m_trigger.triggerTime();
    const qint64 preMs = m_trigger.settings().preTriggerMs();
    const qint64 postMs = m_trigger.settings().postTriggerMs();
    // The shot keeps where it fired, in its file too: an overlay is aligned at it.
    m_recording->triggerMs = triggerMs;
    replaceRecording(m_recording->excerpt(m_trigger.shotStart(), m_trigger.shotEnd()));
    m_trigger.disarm();
    m_chart->setTriggerTime(triggerMs);
    m_chart->showTimeRange(triggerMs - preMs, triggerMs + postMs);
    // Cursors left in the wait would read nothing: the first goes to the trigger, the second
    // to the shot's end.
    if (m_chart->cursorTime(0))
        m_chart->setCursorTime(0, double(triggerMs));
    if (m_chart->cursorTime(1))
        m_chart->setCursorTime(1, double(m_recording->lastTime()));
    QString text = tr("Shot of %Ln sample(s) around the trigger.", nullptr,
                      int(m_recording->buffer.count()));
    if (!m_recordFile.isEmpty()) {
        QString error;
        if (!saveRecording(m_recordFile, &error))
            return showStatus(tr("%1 %2").arg(text, error), true);
        text = tr("%1 Saved to %2.").arg(text, m_recordFile);
    }
    showStatus(text);
}

void ScopeDock::armTrigger(bool on)
{
    if (!on) {
        m_trigger.disarm();
        return stopRecording();
    }
    m_trigger.setSettings(triggerSettings());
    if (isRecording()) {
        // Armed from now on; the pre-trigger time is recorded first.
        m_trigger.arm(m_recording->buffer.count());
        showStatus(tr("Waiting for the trigger..."));
        return;
    }
    startRecording();
}

ScopeTriggerSettings ScopeDock::triggerSettings() const
{
    ScopeTriggerSettings settings;
    settings.channel = m_triggerChannel->currentIndex();
    settings.edge = ScopeTriggerSettings::Edge(m_triggerEdge->currentData().toInt());
    settings.level = m_triggerLevel->value();
    settings.preTriggerShare = m_triggerPre->value() / 100.0;
    settings.windowMs = qint64(m_triggerWindow->value() * 1000.0 + 0.5);
    return settings;
}

void ScopeDock::triggerChannelChanged()
{
    // The level is in the channel's display units, with its decimals.
    const ScopeChannel &channel = m_recording->channels.at(m_triggerChannel->currentIndex());
    m_triggerLevel->setDecimals(std::clamp(channel.scaling.decimals(), 0, 4));
    const QString unit = channel.unit();
    m_triggerLevel->setSuffix(unit.isEmpty() ? QString() : QLatin1Char(' ') + unit);
    for (int index = 0; index < m_triggerChannel->count(); ++index) {
        const ScopeChannel &shown = m_recording->channels.at(index);
        m_triggerChannel->setItemText(index, shown.title(index));
    }
}

void ScopeDock::readOfflineRecords()
{
    if (!m_client || isRecording() || m_readingOffline)
        return;
    confirmReplacing(tr("Read Offline Records"),
                     tr("The recording shown is not saved. The offline records replace it."),
                     [this] { readOfflineRecordsNow(); });
}

void ScopeDock::readOfflineRecordsNow()
{
    if (!m_client || isRecording() || m_readingOffline)
        return;
    m_readingOffline = true;
    updateActions();
    showStatus(tr("Reading the offline records..."));
    m_progress->setRange(0, 0);
    m_progress->show();
    // The channels as assigned now tell what the records hold.
    const auto channels = std::make_shared<ScopeChannelsJob>(m_client->settings().protocol,
                                                             m_drive);
    whenFinished(
        m_client->run(channels), this,
        [this](const ScopeChannelsOutcome &assigned) {
            readOfflineRecordsOf(scopeChannels(m_drive, assigned.assignment));
        },
        [this] {
            offlineRecordsRead({{}, 0, 0, tr("The connection went away.")}, ScopeChannels{});
        });
}

void ScopeDock::readOfflineRecordsOf(const ScopeChannels &channels)
{
    if (!m_client)
        return offlineRecordsRead({{}, 0, 0, tr("The connection went away.")}, channels);
    auto *watcher = new QFutureWatcher<ScopeOfflineRecords>(this);
    connect(watcher, &QFutureWatcherBase::progressRangeChanged, m_progress,
            &QProgressBar::setRange);
    connect(watcher, &QFutureWatcherBase::progressValueChanged, m_progress,
            &QProgressBar::setValue);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, channels] {
        watcher->deleteLater();
        offlineRecordsRead(watcher->future().resultCount() > 0 ? watcher->future().result()
                                                               : ScopeOfflineRecords{},
                           channels);
    });
    watcher->setFuture(m_client->run(std::make_shared<ScopeOfflineJob>()));
}

void ScopeDock::offlineRecordsRead(const ScopeOfflineRecords &records,
                                   const ScopeChannels &channels)
{
    if (!records.samples.isEmpty()) {
        replaceRecording(offlineRecording(
            records, channels, m_client ? m_client->settings().displayName() : QString()));
        m_unsaved = true;
        m_chart->showAll();
    }
    m_readingOffline = false;
    m_progress->hide();
    updateActions();
    QString text = tr("%n offline record(s) read", nullptr, int(records.samples.size()));
    if (records.clipped > 0)
        text += QLatin1String("; ")
                + tr("%n with channel 3 or 4 beyond 16 bits, shown at the nearest 16-bit value",
                     nullptr, int(records.clipped));
    if (!records.error.isEmpty())
        text += QLatin1String(": ") + records.error;
    showStatus(text, !records.error.isEmpty() || records.clipped > 0);
}

} // namespace DriveDesk
