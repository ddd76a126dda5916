#pragma once

#include "parameters/DriveDescription.h"
#include "scope/ScopePreset.h"
#include "scope/ScopeTrigger.h"
#include "session/ScopeAssignment.h"
#include "session/ScopeRecorder.h"

#include <QDockWidget>
#include <QPointer>

#include <functional>
#include <memory>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QProgressBar;
class QSpinBox;
class QToolBar;

namespace DriveDesk {

class DriveClient;
class ScopeChannelPanel;
class ScopeChart;
class ScopeMathChannels;
class ScopeMeasurementTable;
class WindowFrame;
struct ScopeChannelsOutcome;
struct ScopeOfflineRecords;
class ScopeOverlay;
struct ScopeRecording;

// The scope in the main window: the chart of a recording, the channels' sources and looks,
// recording from the drive (optionally into a file as it goes), a single-shot trigger, the
// drive's offline records, recordings loaded from files, and export as CSV, PNG and PDF.
// What it records and how is core's (ScopeRecorder, ScopeChannelsJob, ScopeTrigger, ScopeCsv,
// the recording file); the dock arranges it and remembers its settings.
class ScopeDock : public QDockWidget
{
    Q_OBJECT
public:
    ScopeDock(WindowFrame &frame, QWidget *parent = nullptr);
    ~ScopeDock() override;

    // The drive to record from; nullptr: none (a recording already there stays to be viewed).
    void setClient(DriveClient *client);
    // What the scan found: the channel-assignment parameters and the sources offered.
    void setDrive(const DriveDescription &drive);

    ScopeChart *chart() const { return m_chart; }
    ScopeChannelPanel *channelPanel() const { return m_panel; }
    ScopeMeasurementTable *measurementTable() const { return m_measurements; }
    ScopeMathChannels *mathChannels() const { return m_math; }
    const ScopeRecording *recording() const { return m_recording.get(); }
    bool isRecording() const;

    // Opens a recording file to view it (the same view, no drive); false with the reason.
    bool openRecording(const QString &path, QString *error = nullptr);
    // Reads a recording file in the thread pool and draws it over the one shown (the chart's
    // overlay), replacing an overlay before; a file that cannot be read is named in the status.
    void openOverlay(const QString &path);
    // Where the next recordings also go as they are recorded (.ddscope); empty: memory only.
    void setRecordFile(const QString &path);
    QString recordFile() const { return m_recordFile; }
    // The recording shown, whole, as a recording file (.ddscope): saved, a new recording
    // replaces it without asking. False with the reason, and no file at `path`.
    bool saveRecording(const QString &path, QString *error = nullptr);
    // The recording as CSV: everything, or only the visible time range; with both cursors
    // placed, their measurements after the samples.
    bool exportCsv(const QString &path, bool visibleOnly, QString *error = nullptr);

    void saveSettings() const;

    // Presets (ScopeDockPresets.cpp). The plant file open in the window: its presets are kept
    // beside it; empty: none.
    void setPlantFile(const QString &path);
    // The set-up shown, as a preset named `name`.
    ScopePreset currentPreset(const QString &name) const;
    // Saves the set-up shown for this kind of drive (ScopePresetLibrary), its file's path in
    // `path`; false with the reason.
    bool savePreset(const QString &name, QString *path, QString *error = nullptr);
    // Shows a preset's sources (written to the drive at Record, as the panel's), looks,
    // trigger, roll and rate limit. Returns what could not be applied, a channel a line (a
    // source this drive does not have or permit, its channel then off); the rest is applied.
    QStringList applyPreset(const ScopePreset &preset);

    // The connection changed state: what can be done now.
    void updateActions();

    // The recording shown holds samples that are in memory only.
    bool hasUnsavedRecording() const;
    // Before the window closes: `proceed` at once when nothing unsaved would be lost; otherwise
    // once the recording is saved or discarded (asked, without blocking). Nothing on Cancel.
    void settleBeforeClosing(const std::function<void()> &proceed);

private:
    void buildToolBars();
    void buildTriggerBar(QToolBar *bar);
    void restoreSettings();
    void showStatus(const QString &text, bool problem = false);
    // Before anything is recorded, the chart's legend and axes name the sources chosen.
    void previewChannels();
    void measureBetweenCursors();
    // Math channels: the recording's definitions, computed and drawn.
    void addMathChannel();
    void removeMathChannels();
    void computeMath();
    void mathComputed();

    // ScopeDockRecording.cpp
    void toggleRecording(bool on);
    void startRecording();
    void startRecordingNow();
    void channelsAssigned(const ScopeChannelsOutcome &outcome);
    void showAssignmentInTable(const ScopeAssignment &assignment);
    void stopRecording();
    void samplesAppended();
    void recorderStatus(const ScopeRecorderStatus &status);
    void recordingFinished(const ScopePollEnd &end);
    void armTrigger(bool on);
    ScopeTriggerSettings triggerSettings() const;
    void triggerChannelChanged();
    void keepShot();
    void readOfflineRecords();
    void readOfflineRecordsNow();
    void readOfflineRecordsOf(const ScopeChannels &channels);
    void offlineRecordsRead(const ScopeOfflineRecords &records, const ScopeChannels &channels);
    void replaceRecording(std::unique_ptr<ScopeRecording> recording);

    // ScopeDockOverlay.cpp
    void buildOverlayMenu(QMenu *menu);
    void chooseOverlay();
    void overlayLoaded(const ScopeOverlay &overlay);
    void alignOverlay();
    void removeOverlay();
    void showOverlayStatus(const QStringList &warnings = {});

    // ScopeDockFiles.cpp
    static QString recordingFilter();
    void chooseRecordingToOpen();
    void chooseRecordingFile(bool on);
    void chooseRecordingToSave();
    // Save As, then `saved` once the recording is in the file.
    void saveRecordingThen(const std::function<void()> &saved);
    void chooseCsv(bool visibleOnly);
    void chooseImage(bool pdf);
    // Before the recording shown is replaced: `proceed` at once when nothing unsaved would be
    // lost; otherwise asks, without blocking, Save / Discard / Cancel, and runs `proceed` once
    // the recording is saved or discarded. Nothing on Cancel.
    void confirmReplacing(const QString &title, const QString &text,
                          const std::function<void()> &proceed);

    // ScopeDockPresets.cpp
    void buildPresetButton(QToolBar *bar);
    void fillPresetMenu();
    void choosePresetName();
    // A preset of that name is saved there already: replaced only when the user says so.
    void askToReplacePreset(const QString &name, const QString &path);
    void saveAndSayPreset(const QString &name);
    void loadPreset(const QString &path);

    WindowFrame &m_frame;
    QPointer<DriveClient> m_client;
    DriveDescription m_drive;
    bool m_hasDrive = false;
    std::unique_ptr<ScopeRecording> m_recording;
    ScopeRecorder *m_recorder = nullptr;
    ScopeTrigger m_trigger;
    bool m_assigning = false;
    bool m_readingOffline = false;
    bool m_unsaved = false; // the recording shown is in memory only
    // The status line shows the hint of an empty dock, not the outcome of something the user
    // did (a preset loaded, a file refused): only a hint is replaced by the next hint.
    bool m_hintShown = false;
    QString m_recordFile; // where the next recording also goes; empty: memory only
    QString m_plantFile; // the plant open in the window; empty: none
    QString m_presetName; // the preset saved or loaded last, offered as the next name

    ScopeChart *m_chart = nullptr;
    ScopeChannelPanel *m_panel = nullptr;
    ScopeMeasurementTable *m_measurements = nullptr;
    ScopeMathChannels *m_math = nullptr;
    QAction *m_removeMathAction = nullptr;
    QMenu *m_presetMenu = nullptr;
    QAction *m_overlayTriggerAction = nullptr;
    QAction *m_overlayStartAction = nullptr;
    QAction *m_removeOverlayAction = nullptr;
    quint64 m_overlayRequest = 0; // the newest file asked for; an older one read later is dropped
    QLabel *m_status = nullptr;
    QProgressBar *m_progress = nullptr;
    QAction *m_recordAction = nullptr;
    QAction *m_freezeAction = nullptr;
    QAction *m_rollAction = nullptr;
    QAction *m_wholeAction = nullptr;
    QAction *m_autoScaleAction = nullptr;
    QAction *m_triggerAction = nullptr;
    QAction *m_toFileAction = nullptr;
    QAction *m_offlineAction = nullptr;
    QDoubleSpinBox *m_rollSeconds = nullptr;
    QSpinBox *m_rateLimit = nullptr;
    QComboBox *m_triggerChannel = nullptr;
    QComboBox *m_triggerEdge = nullptr;
    QDoubleSpinBox *m_triggerLevel = nullptr;
    QSpinBox *m_triggerPre = nullptr;
    QDoubleSpinBox *m_triggerWindow = nullptr;
};

} // namespace DriveDesk
