#include "ScopeDock.h"

#include "ScopeChannelPanel.h"
#include "ScopeChart.h"
#include "ScopeCursorTable.h"
#include "ScopeMathChannels.h"
#include "ScopeMathDialog.h"
#include "ScopeMeasurementTable.h"

#include "client/DriveClient.h"
#include "frame/WindowFeature.h"
#include "scope/ScopeCsv.h"
#include "scope/ScopeFileReader.h"
#include "scope/ScopeRecording.h"
#include "session/ScopeOfflineJob.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace DriveDesk {

namespace {

const QString kGroup = QStringLiteral("scope");

} // namespace

ScopeDock::ScopeDock(WindowFrame &frame, QWidget *parent)
    : QDockWidget(tr("Scope"), parent)
    , m_frame(frame)
    , m_recording(std::make_unique<ScopeRecording>())
    , m_math(new ScopeMathChannels(this))
{
    setObjectName(QStringLiteral("scopeDock"));
    auto *content = new QWidget(this);
    auto *layout = new QVBoxLayout(content);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(2);

    m_chart = new ScopeChart(content);
    m_chart->setObjectName(QStringLiteral("scopeChart"));
    m_chart->setRecording(m_recording.get());
    // A chart to read, not a strip: beside another dock (the telegram monitor) the splitter
    // and the window give room to it rather than squeeze it to a few pixels.
    m_chart->setMinimumSize(320, 280);
    m_panel = new ScopeChannelPanel(content);
    m_panel->setObjectName(QStringLiteral("scopeChannels"));
    buildToolBars();
    // The tool bars whole, none of their buttons behind an overflow arrow: the dock asks the
    // window for their width (German texts are longer).
    int barsWidth = 0;
    for (QToolBar *bar : content->findChildren<QToolBar *>(Qt::FindDirectChildrenOnly)) {
        layout->addWidget(bar);
        barsWidth = std::max(barsWidth, bar->sizeHint().width());
    }
    content->setMinimumWidth(barsWidth + layout->contentsMargins().left()
                             + layout->contentsMargins().right());

    auto *splitter = new QSplitter(Qt::Horizontal, content);
    splitter->setChildrenCollapsible(false);
    auto *side = new QWidget(splitter);
    auto *sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(m_panel);
    // The cursors' read-out beside the chart, not under it: the chart keeps its height.
    sideLayout->addWidget(m_chart->cursorTable());
    m_measurements = new ScopeMeasurementTable(side);
    m_measurements->setObjectName(QStringLiteral("scopeMeasurements"));
    sideLayout->addWidget(m_measurements);
    sideLayout->addStretch(1);
    splitter->addWidget(side);
    splitter->addWidget(m_chart);
    splitter->setStretchFactor(1, 1);
    layout->addWidget(splitter, 1);

    auto *statusRow = new QHBoxLayout;
    m_status = new QLabel(content);
    m_status->setObjectName(QStringLiteral("scopeStatus"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Wrapped, as the monitor's: the counts while recording must not widen the window.
    m_status->setWordWrap(true);
    m_progress = new QProgressBar(content);
    m_progress->setMaximumWidth(200);
    m_progress->hide();
    statusRow->addWidget(m_status, 1);
    statusRow->addWidget(m_progress);
    layout->addLayout(statusRow);
    setWidget(content);

    connect(m_panel, &ScopeChannelPanel::choicesChanged, this, &ScopeDock::previewChannels);
    connect(m_panel, &ScopeChannelPanel::visibilityChanged, m_chart, &ScopeChart::setChannelVisible);
    connect(m_panel, &ScopeChannelPanel::colorChanged, m_chart, &ScopeChart::setChannelColor);
    connect(m_panel, &ScopeChannelPanel::ownAxisChanged, m_chart, &ScopeChart::setChannelOwnAxis);
    connect(m_chart, &ScopeChart::followChanged, m_rollAction, &QAction::setChecked);
    connect(m_chart, &ScopeChart::autoScaleChanged, m_autoScaleAction, &QAction::setChecked);
    connect(m_chart, &ScopeChart::frozenChanged, m_freezeAction, &QAction::setChecked);
    connect(m_chart, &ScopeChart::cursorsChanged, this, &ScopeDock::measureBetweenCursors);
    connect(m_math, &ScopeMathChannels::seriesChanged, this, &ScopeDock::mathComputed);

    restoreSettings();
    for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
        m_chart->setChannelVisible(channel, m_panel->isChannelVisible(channel));
        m_chart->setChannelColor(channel, m_panel->channelColor(channel));
        m_chart->setChannelOwnAxis(channel, m_panel->hasOwnAxis(channel));
    }
    updateActions();
}

ScopeDock::~ScopeDock()
{
    delete m_recorder; // before the recording it writes to
    m_recorder = nullptr;
}

void ScopeDock::setClient(DriveClient *client)
{
    if (m_recorder && m_client != client) {
        m_recorder->stop();
        delete m_recorder; // its job ends with the client it ran on
        m_recorder = nullptr;
        m_recordAction->setChecked(false);
    }
    m_client = client;
    // An assignment on its way went with the old connection's edits.
    m_assigning = false;
    m_hasDrive = false;
    m_panel->setDrive(nullptr);
    if (client && !m_recorder) {
        m_recorder = new ScopeRecorder(client, this);
        connect(m_recorder, &ScopeRecorder::samplesAppended, this, &ScopeDock::samplesAppended);
        connect(m_recorder, &ScopeRecorder::statusChanged, this, &ScopeDock::recorderStatus);
        connect(m_recorder, &ScopeRecorder::finished, this, &ScopeDock::recordingFinished);
    }
    updateActions();
}

void ScopeDock::setDrive(const DriveDescription &drive)
{
    m_drive = drive;
    m_hasDrive = true;
    m_panel->setDrive(&m_drive);
    previewChannels();
    updateActions();
}

void ScopeDock::previewChannels()
{
    if (!m_hasDrive || m_recording->buffer.count() > 0 || isRecording() || m_assigning)
        return;
    m_recording->channels = scopeChannels(m_drive, m_panel->choices());
    m_panel->setChannels(m_recording->channels);
    m_chart->recordingChanged();
    triggerChannelChanged();
}

void ScopeDock::measureBetweenCursors()
{
    QList<ScopeMeasuredSeries> math;
    for (const std::shared_ptr<const ScopeSeries> &series : m_math->series())
        math << ScopeMeasuredSeries { series->title, series };
    m_measurements->measure(*m_recording, m_chart->shownSampleCount(), m_chart->cursorReadout(),
                            math);
}

void ScopeDock::addMathChannel()
{
    QStringList channels;
    for (int channel = 0; channel < m_recording->channels.size(); ++channel)
        channels << m_recording->channels.at(channel).title(channel);
    auto *dialog = new ScopeMathDialog(channels, this);
    connect(dialog, &QDialog::finished, dialog, &QObject::deleteLater);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        m_recording->math << dialog->definition();
        computeMath();
    });
    dialog->open();
}

void ScopeDock::removeMathChannels()
{
    m_recording->math.clear();
    computeMath();
}

void ScopeDock::computeMath()
{
    m_removeMathAction->setEnabled(!m_recording->math.isEmpty());
    m_math->compute(*m_recording, m_chart->shownSampleCount());
}

void ScopeDock::mathComputed()
{
    m_chart->setMathSeries(m_math->series(), m_math->levels());
    measureBetweenCursors();
    if (!m_math->errors().isEmpty())
        showStatus(tr("A math channel cannot be computed: %1")
                       .arg(m_math->errors().join(QStringLiteral("; "))),
                   true);
}

bool ScopeDock::isRecording() const
{
    return m_recorder && m_recorder->isRecording();
}

void ScopeDock::updateActions()
{
    const bool connected = m_client && m_client->state() == DriveClient::State::Connected;
    const bool busy = isRecording() || m_assigning || m_readingOffline;
    m_recordAction->setEnabled(connected && m_hasDrive && !m_readingOffline);
    m_recordAction->setChecked(isRecording() || m_assigning);
    // Offered only where the connection carries service 21 (DIN66019II; HSP5 only with
    // DriveDesk's extensions).
    const bool offlineCarried = !m_client || ScopeOfflineJob::isCarriedBy(m_client->settings());
    m_offlineAction->setVisible(offlineCarried);
    m_offlineAction->setEnabled(connected && m_hasDrive && !busy && offlineCarried);
    m_triggerAction->setEnabled(connected && m_hasDrive && !m_readingOffline);
    m_toFileAction->setEnabled(!busy);
    m_panel->setSourcesEditable(!busy);
    if (!busy && m_recording->buffer.count() == 0 && (m_hintShown || m_status->text().isEmpty())) {
        showStatus(connected && m_hasDrive
                       ? tr("Choose the sources and press Record (F9), or open a recording.")
                       : tr("Connect to a drive to record, or open a recording."));
        m_hintShown = true;
    }
}

void ScopeDock::showStatus(const QString &text, bool problem)
{
    m_hintShown = false;
    m_status->setText(text);
    m_status->setStyleSheet(problem ? QStringLiteral("color: #b00020;") : QString());
}

bool ScopeDock::openRecording(const QString &path, QString *error)
{
    auto recording = std::make_unique<ScopeRecording>();
    QStringList warnings;
    if (!readScopeFile(path, *recording, error, &warnings))
        return false;
    replaceRecording(std::move(recording));
    m_unsaved = false;
    m_chart->showAll();
    showStatus(warnings.isEmpty()
                   ? tr("%1: %Ln sample(s)", nullptr, int(m_recording->buffer.count())).arg(path)
                   : warnings.join(QLatin1Char(' ')),
               !warnings.isEmpty());
    return true;
}

bool ScopeDock::exportCsv(const QString &path, bool visibleOnly, QString *error)
{
    ScopeCsvOptions options;
    if (visibleOnly) {
        const ScopeTimeRange range = m_chart->visibleTimeRange();
        options.fromMs = range.fromMs;
        options.toMs = range.toMs;
    }
    options.channels = m_recording->recordedChannels();
    for (const std::shared_ptr<const ScopeSeries> &series : m_math->series())
        options.math << series.get();
    const std::optional<double> first = m_chart->cursorTime(0);
    const std::optional<double> second = m_chart->cursorTime(1);
    if (first && second)
        options.measureBetweenMs = std::pair(*first, *second);
    return saveScopeCsv(path, *m_recording, options, error);
}

void ScopeDock::restoreSettings()
{
    QSettings settings;
    settings.beginGroup(kGroup);
    ScopeAssignment choices;
    for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
        const QString key = QStringLiteral("channel%1/").arg(channel + 1);
        m_panel->setChannelVisible(channel, settings.value(key + QLatin1String("visible"), true).toBool());
        const QColor color(settings.value(key + QLatin1String("color")).toString());
        if (color.isValid())
            m_panel->setChannelColor(channel, color);
        m_panel->setOwnAxis(channel, settings.value(key + QLatin1String("ownAxis"), false).toBool());
        const QVariant source = settings.value(key + QLatin1String("source"));
        const int mask = settings.value(key + QLatin1String("setMask"), 0x01).toInt();
        if (source.isValid())
            choices[std::size_t(channel)]
                = ChannelAssignment{source.toInt(), quint8(mask > 0 && mask <= 0xFF ? mask : 0x01)};
    }
    m_panel->setChoices(choices);
    m_rollSeconds->setValue(settings.value(QStringLiteral("rollSeconds"),
                                           ScopeChart::kDefaultRollSeconds).toDouble());
    m_rateLimit->setValue(settings.value(QStringLiteral("rateLimit"), 0).toInt());
    m_triggerChannel->setCurrentIndex(settings.value(QStringLiteral("trigger/channel"), 0).toInt());
    m_triggerEdge->setCurrentIndex(settings.value(QStringLiteral("trigger/falling"), false).toBool() ? 1 : 0);
    m_triggerLevel->setValue(settings.value(QStringLiteral("trigger/level"), 0.0).toDouble());
    m_triggerPre->setValue(settings.value(QStringLiteral("trigger/preTrigger"), 20).toInt());
    m_triggerWindow->setValue(settings.value(QStringLiteral("trigger/shotSeconds"), 1.0).toDouble());
}

void ScopeDock::saveSettings() const
{
    QSettings settings;
    settings.beginGroup(kGroup);
    const ScopeAssignment choices = m_panel->wantedChoices();
    for (int channel = 0; channel < ScopeChart::kChannels; ++channel) {
        const QString key = QStringLiteral("channel%1/").arg(channel + 1);
        settings.setValue(key + QLatin1String("visible"), m_panel->isChannelVisible(channel));
        settings.setValue(key + QLatin1String("color"), m_panel->channelColor(channel).name());
        settings.setValue(key + QLatin1String("ownAxis"), m_panel->hasOwnAxis(channel));
        if (const auto &choice = choices[std::size_t(channel)]) {
            settings.setValue(key + QLatin1String("source"), choice->source);
            settings.setValue(key + QLatin1String("setMask"), int(choice->setMask));
        } else {
            settings.remove(key + QLatin1String("source"));
            settings.remove(key + QLatin1String("setMask"));
        }
    }
    settings.setValue(QStringLiteral("rollSeconds"), m_rollSeconds->value());
    settings.setValue(QStringLiteral("rateLimit"), m_rateLimit->value());
    settings.setValue(QStringLiteral("trigger/channel"), m_triggerChannel->currentIndex());
    settings.setValue(QStringLiteral("trigger/falling"), m_triggerEdge->currentIndex() == 1);
    settings.setValue(QStringLiteral("trigger/level"), m_triggerLevel->value());
    settings.setValue(QStringLiteral("trigger/preTrigger"), m_triggerPre->value());
    settings.setValue(QStringLiteral("trigger/shotSeconds"), m_triggerWindow->value());
}

} // namespace DriveDesk
