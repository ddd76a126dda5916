// The scope dock's tool bars: recording, the view, the rate limit, the files, the trigger.
#include "ScopeDock.h"

#include "ScopeChart.h"
#include "ScopeSpectrumView.h"

#include "frame/FrameSupport.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QSpinBox>
#include <QToolBar>
#include <QToolButton>

namespace DriveDesk {

void ScopeDock::buildToolBars()
{
    auto *bar = new QToolBar(tr("Scope"), m_chart->parentWidget());
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->setIconSize(QSize(16, 16));

    m_recordAction = bar->addAction(themedIcon("media-record", QStyle::SP_MediaPlay), tr("Record"));
    m_recordAction->setObjectName(QStringLiteral("scopeRecordAction"));
    m_recordAction->setCheckable(true);
    m_recordAction->setShortcut(QKeySequence(Qt::Key_F9));
    m_recordAction->setToolTip(tr("Record the drive's scope data; again to stop (F9)"));
    connect(m_recordAction, &QAction::triggered, this, &ScopeDock::toggleRecording);

    m_freezeAction = bar->addAction(themedIcon("media-playback-pause", QStyle::SP_MediaPause),
                                    tr("Pause View"));
    m_freezeAction->setObjectName(QStringLiteral("scopeFreezeAction"));
    m_freezeAction->setCheckable(true);
    m_freezeAction->setToolTip(tr("Hold the chart still; the recording goes on (Space in the "
                                  "chart)"));
    connect(m_freezeAction, &QAction::toggled, m_chart, &ScopeChart::setFrozen);
    bar->addSeparator();

    m_rollAction = bar->addAction(tr("Roll"));
    m_rollAction->setObjectName(QStringLiteral("scopeRollAction"));
    m_rollAction->setCheckable(true);
    m_rollAction->setChecked(true);
    m_rollAction->setToolTip(tr("Follow the newest samples (End in the chart)"));
    connect(m_rollAction, &QAction::triggered, m_chart, &ScopeChart::setFollow);
    m_rollSeconds = new QDoubleSpinBox(bar);
    m_rollSeconds->setObjectName(QStringLiteral("scopeRollSeconds"));
    m_rollSeconds->setRange(0.1, 3600);
    m_rollSeconds->setDecimals(1);
    m_rollSeconds->setValue(ScopeChart::kDefaultRollSeconds);
    m_rollSeconds->setSuffix(tr(" s"));
    m_rollSeconds->setToolTip(tr("How many seconds the rolling view shows"));
    connect(m_rollSeconds, &QDoubleSpinBox::valueChanged, m_chart, &ScopeChart::setRollSeconds);
    bar->addWidget(m_rollSeconds);
    m_wholeAction = bar->addAction(tr("Whole"));
    m_wholeAction->setObjectName(QStringLiteral("scopeWholeAction"));
    m_wholeAction->setToolTip(tr("Show the whole recording (Home in the chart)"));
    connect(m_wholeAction, &QAction::triggered, m_chart, &ScopeChart::showAll);
    m_autoScaleAction = bar->addAction(tr("Auto-scale"));
    m_autoScaleAction->setObjectName(QStringLiteral("scopeAutoScaleAction"));
    m_autoScaleAction->setCheckable(true);
    m_autoScaleAction->setChecked(true);
    m_autoScaleAction->setToolTip(tr("Fit the value axes to what is shown (A in the chart)"));
    connect(m_autoScaleAction, &QAction::triggered, m_chart, &ScopeChart::setAutoScale);
    bar->addSeparator();

    auto *rateLabel = new QLabel(tr("Max. rate"), bar);
    bar->addWidget(rateLabel);
    m_rateLimit = new QSpinBox(bar);
    m_rateLimit->setObjectName(QStringLiteral("scopeRateLimit"));
    m_rateLimit->setRange(0, 100000);
    m_rateLimit->setSuffix(tr(" Hz"));
    m_rateLimit->setSpecialValueText(tr("as fast as the link"));
    m_rateLimit->setToolTip(tr("Polls a second at most; 0: as fast as the link allows"));
    rateLabel->setBuddy(m_rateLimit);
    bar->addWidget(m_rateLimit);
    bar->addSeparator();

    auto *fileMenu = new QMenu(tr("Recording"), bar);
    fileMenu->addAction(tr("Open Recording..."), this, &ScopeDock::chooseRecordingToOpen)
        ->setObjectName(QStringLiteral("scopeOpenAction"));
    fileMenu->addAction(tr("Save Recording As..."), this, &ScopeDock::chooseRecordingToSave)
        ->setObjectName(QStringLiteral("scopeSaveAction"));
    m_toFileAction = fileMenu->addAction(tr("Record to File..."));
    m_toFileAction->setObjectName(QStringLiteral("scopeToFileAction"));
    m_toFileAction->setCheckable(true);
    connect(m_toFileAction, &QAction::triggered, this, &ScopeDock::chooseRecordingFile);
    m_offlineAction = fileMenu->addAction(tr("Read Offline Records"), this,
                                          &ScopeDock::readOfflineRecords);
    m_offlineAction->setObjectName(QStringLiteral("scopeOfflineAction"));
    fileMenu->addSeparator();
    fileMenu->addAction(tr("Add Math Channel..."), this, &ScopeDock::addMathChannel)
        ->setObjectName(QStringLiteral("scopeAddMathAction"));
    m_removeMathAction = fileMenu->addAction(tr("Remove Math Channels"), this,
                                             &ScopeDock::removeMathChannels);
    m_removeMathAction->setObjectName(QStringLiteral("scopeRemoveMathAction"));
    m_removeMathAction->setEnabled(false);
    ScopeSpectrumView::addOpenAction(fileMenu, this);
    fileMenu->addSeparator();
    buildOverlayMenu(fileMenu);
    fileMenu->addSeparator();
    fileMenu->addAction(tr("Export All as CSV..."), this, [this] { chooseCsv(false); })
        ->setObjectName(QStringLiteral("scopeCsvAllAction"));
    fileMenu->addAction(tr("Export Visible Range as CSV..."), this, [this] { chooseCsv(true); })
        ->setObjectName(QStringLiteral("scopeCsvVisibleAction"));
    fileMenu->addAction(tr("Export Chart as PNG..."), this, [this] { chooseImage(false); });
    fileMenu->addAction(tr("Export Chart as PDF..."), this, [this] { chooseImage(true); });

    auto *triggerBar = new QToolBar(tr("Trigger"), m_chart->parentWidget());
    triggerBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    buildTriggerBar(triggerBar);
    // The files at the end of the second row: the two rows are about as long.
    triggerBar->addSeparator();
    auto *fileButton = new QToolButton(triggerBar);
    fileButton->setText(tr("Recording"));
    fileButton->setMenu(fileMenu);
    fileButton->setPopupMode(QToolButton::InstantPopup);
    triggerBar->addWidget(fileButton);
    buildPresetButton(triggerBar);
}

void ScopeDock::buildTriggerBar(QToolBar *bar)
{
    m_triggerAction = bar->addAction(tr("Single Shot"));
    m_triggerAction->setObjectName(QStringLiteral("scopeTriggerAction"));
    m_triggerAction->setCheckable(true);
    m_triggerAction->setToolTip(tr("Wait for the trigger, record one shot around it and stop"));
    connect(m_triggerAction, &QAction::triggered, this, &ScopeDock::armTrigger);
    bar->addWidget(new QLabel(tr("Channel"), bar));
    m_triggerChannel = new QComboBox(bar);
    m_triggerChannel->setObjectName(QStringLiteral("scopeTriggerChannel"));
    // A width of its own, not its titles': the tool bar's width, which the dock asks the
    // window for, stays what it was when the dock was made. Long titles are cut.
    m_triggerChannel->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_triggerChannel->setMinimumContentsLength(12);
    for (int channel = 0; channel < ScopeChart::kChannels; ++channel)
        m_triggerChannel->addItem(QString::number(channel + 1));
    connect(m_triggerChannel, &QComboBox::currentIndexChanged, this,
            &ScopeDock::triggerChannelChanged);
    bar->addWidget(m_triggerChannel);
    m_triggerEdge = new QComboBox(bar);
    m_triggerEdge->setObjectName(QStringLiteral("scopeTriggerEdge"));
    m_triggerEdge->addItem(tr("rising"), int(ScopeTriggerSettings::Edge::Rising));
    m_triggerEdge->addItem(tr("falling"), int(ScopeTriggerSettings::Edge::Falling));
    bar->addWidget(m_triggerEdge);
    bar->addWidget(new QLabel(tr("Level"), bar));
    m_triggerLevel = new QDoubleSpinBox(bar);
    m_triggerLevel->setObjectName(QStringLiteral("scopeTriggerLevel"));
    m_triggerLevel->setRange(-1e9, 1e9);
    m_triggerLevel->setDecimals(2);
    // Its width fixed now, with room for a unit: the channel's unit, set later as a suffix,
    // would widen the tool bar past what the dock asked the window for, and push its last
    // buttons behind the overflow arrow.
    m_triggerLevel->setFixedWidth(m_triggerLevel->sizeHint().width()
                                  + m_triggerLevel->fontMetrics().horizontalAdvance(
                                      QStringLiteral(" 1/min")));
    bar->addWidget(m_triggerLevel);
    bar->addWidget(new QLabel(tr("Pre-trigger"), bar));
    m_triggerPre = new QSpinBox(bar);
    m_triggerPre->setObjectName(QStringLiteral("scopeTriggerPre"));
    m_triggerPre->setRange(0, 100);
    m_triggerPre->setValue(20);
    m_triggerPre->setSuffix(QStringLiteral(" %"));
    m_triggerPre->setToolTip(tr("The share of the shot before the trigger"));
    bar->addWidget(m_triggerPre);
    bar->addWidget(new QLabel(tr("Shot"), bar));
    m_triggerWindow = new QDoubleSpinBox(bar);
    m_triggerWindow->setObjectName(QStringLiteral("scopeTriggerWindow"));
    m_triggerWindow->setRange(0.01, 3600);
    m_triggerWindow->setValue(1.0);
    m_triggerWindow->setSuffix(tr(" s"));
    m_triggerWindow->setToolTip(tr("How long the shot is"));
    bar->addWidget(m_triggerWindow);
}

} // namespace DriveDesk
