#include "PollingFeature.h"

#include "PollingController.h"

#include "frame/DriveSession.h"
#include "frame/FrameSupport.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QMenu>
#include <QSettings>
#include <QToolBar>

namespace DriveDesk {

namespace {

const QString kPollingKey = QStringLiteral("polling/enabled");
const QString kIntervalKey = QStringLiteral("polling/intervalMs");
const QString kLiveGroup = QStringLiteral("ru"); // the run display
const int kIntervalsMs[] = { 100, 200, 500, 1000, 2000, 5000 };

QString intervalText(int ms)
{
    return ms < 1000 ? PollingFeature::tr("%1 ms").arg(ms)
                     : PollingFeature::tr("%1 s").arg(ms / 1000);
}

} // namespace

PollingFeature::PollingFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_pollingAction = new QAction(themedIcon("media-playback-start", QStyle::SP_MediaPlay),
                                  tr("&Poll Live Values"), this);
    m_pollingAction->setObjectName(QStringLiteral("pollingAction"));
    m_pollingAction->setCheckable(true);
    m_pollingAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_pollingAction->setToolTip(tr("Read the run display (ru) again and again"));
    connect(m_pollingAction, &QAction::toggled, this, &PollingFeature::applyPolling);
    m_intervalGroup = new QActionGroup(this);
    for (int ms : kIntervalsMs) {
        QAction *action = m_intervalGroup->addAction(tr("Every %1").arg(intervalText(ms)));
        action->setCheckable(true);
        action->setData(ms);
        connect(action, &QAction::triggered, this, [this, ms] { setInterval(ms); });
    }
    m_intervalBox = new QComboBox;
    m_intervalBox->setObjectName(QStringLiteral("pollingInterval"));
    m_intervalBox->setToolTip(tr("How often the live values are read"));
    for (int ms : kIntervalsMs)
        m_intervalBox->addItem(intervalText(ms), ms);
    connect(m_intervalBox, &QComboBox::activated, this,
            [this](int index) { setInterval(m_intervalBox->itemData(index).toInt()); });

    QMenu *drive = frame.menu(WindowFrame::Menu::Drive);
    drive->addAction(m_pollingAction);
    drive->addMenu(tr("Polling &Interval"))->addActions(m_intervalGroup->actions());
    QToolBar *bar = frame.toolBar();
    bar->addAction(m_pollingAction);
    bar->addWidget(m_intervalBox);

    QSettings settings;
    m_pollingAction->setChecked(settings.value(kPollingKey, false).toBool());
    setInterval(settings.value(kIntervalKey, m_intervalMs).toInt());
}

void PollingFeature::attach(DriveSession *session)
{
    // It holds the old session's client, which goes after this.
    delete m_polling;
    m_polling = nullptr;
    if (!session)
        return;
    m_polling = new PollingController(session->client(), frame().state(), this);
    m_polling->setGroup(kLiveGroup);
    m_polling->setIntervalMs(m_intervalMs);
    connect(m_polling, &PollingController::message, this,
            [this](const QString &text) { frame().showMessage(text); });
    connect(m_polling, &PollingController::problemOver, this,
            [this](const QString &text) { frame().withdrawMessage(text); });
    // Off at once when the link is to close or a scan starts; on again once the drive is read.
    connect(session, &DriveSession::closing, m_polling,
            [polling = m_polling] { polling->setEnabled(false); });
    connect(session, &DriveSession::ready, this, &PollingFeature::applyPolling);
    connect(session, &DriveSession::scanStarted, this, &PollingFeature::applyPolling);
    // Back after a lost link it starts with ready(), not as soon as the link stands.
    connect(session->client(), &DriveClient::stateChanged, this, [this](DriveClient::State state) {
        if (state != DriveClient::State::Connected)
            applyPolling();
    });
    connect(session->client(), &DriveClient::linkLost, this, &PollingFeature::applyPolling);
    connect(session, &DriveSession::scanFinished, this, &PollingFeature::applyPolling);
    connect(session, &DriveSession::scanDiscarded, this, &PollingFeature::applyPolling);
    applyPolling();
}

void PollingFeature::applyPolling()
{
    if (!m_polling)
        return;
    const DriveSession *session = frame().session();
    m_polling->setEnabled(m_pollingAction->isChecked() && session && session->isReady());
}

// Switched on without a connection it would do nothing, and say nothing: off until there is one.
// Whether it is wanted stays checked, and polling starts again with the next connection.
void PollingFeature::updateActions()
{
    const DriveSession *session = frame().session();
    m_pollingAction->setEnabled(session && session->state() == DriveClient::State::Connected);
}

void PollingFeature::saveSettings()
{
    QSettings settings;
    settings.setValue(kPollingKey, m_pollingAction->isChecked());
    settings.setValue(kIntervalKey, m_intervalMs);
}

void PollingFeature::setInterval(int ms)
{
    m_intervalMs = std::clamp(ms, int(PollingController::kMinimumIntervalMs),
                              int(PollingController::kMaximumIntervalMs));
    for (QAction *action : m_intervalGroup->actions())
        action->setChecked(action->data().toInt() == m_intervalMs);
    const int index = m_intervalBox->findData(m_intervalMs);
    if (index >= 0)
        m_intervalBox->setCurrentIndex(index);
    if (m_polling)
        m_polling->setIntervalMs(m_intervalMs);
}

} // namespace DriveDesk
