#include "JournalFeature.h"

#include "JournalDock.h"
#include "JournalReader.h"
#include "JournalTableModel.h"

#include "frame/DriveSession.h"
#include "frame/FileProblem.h"
#include "journal/JournalRevert.h"
#include "state/DriveState.h"
#include "session/EditJournal.h"

#include <QAction>
#include <QMenu>
#include <QTimer>

#include <algorithm>
#include <optional>

namespace DriveDesk {

namespace {

// Writes come in bursts (a download, a copy): one reading a moment after the last.
constexpr int kWrittenDelayMs = 400;

} // namespace

JournalFeature::JournalFeature(WindowFrame &frame, const QString &journalPath, QObject *parent)
    : WindowFeature(frame, parent)
    , m_dock(new JournalDock(frame.frameWidget(), journalPath))
    , m_changes(new JournalReader(journalPath, this))
    , m_written(new QTimer(this))
{
    frame.addDock(m_dock);
    m_action = m_dock->toggleViewAction();
    m_action->setObjectName(QStringLiteral("journalViewAction"));
    m_action->setText(tr("&Journal"));
    m_action->setToolTip(tr("The values written to drives: who, when, before and after"));
    frame.menu(WindowFrame::Menu::View)->addAction(m_action);

    m_written->setSingleShot(true);
    m_written->setInterval(kWrittenDelayMs);
    connect(m_written, &QTimer::timeout, this, [this] {
        if (m_dock->isVisible())
            m_dock->refresh();
        if (!m_drive.link.isEmpty()) {
            JournalFilter newer;
            newer.setAfterEntry(m_changesUpTo);
            m_changes->read(newer, m_changesGeneration);
        }
    });
    // A value written shows in the state's cells: its entry is in the journal by then.
    connect(frame.state(), &DriveState::cellsChanged, m_written, [this] {
        if (!m_written->isActive())
            m_written->start(); // not restarted: polling would put it off for good
    });
    connect(m_changes, &JournalReader::done, this, &JournalFeature::onChangesRead);
    connect(m_dock, &JournalDock::revertRequested, this, &JournalFeature::revert);
}

void JournalFeature::attach(DriveSession *session)
{
    m_session = session;
    m_drive = {};
    ++m_changesGeneration;
    frame().state()->setJournalChanges({});
    m_dock->setConnectedDrive({});
    if (session)
        connect(session, &DriveSession::ready, this, &JournalFeature::driveRead);
    updateActions();
}

void JournalFeature::attachFile(const QString &path)
{
    Q_UNUSED(path)
    attach(nullptr);
}

void JournalFeature::updateActions()
{
    m_dock->setRevertEnabled(frame().isReady() && !m_drive.link.isEmpty());
}

void JournalFeature::saveSettings()
{
    m_dock->saveSettings();
}

std::optional<JournalDrive> JournalFeature::connectedDrive() const
{
    if (!m_session || !frame().isReady())
        return std::nullopt;
    return EditJournal::driveOf(m_session->settings(), frame().state()->description());
}

void JournalFeature::driveRead()
{
    const std::optional<JournalDrive> drive = connectedDrive();
    if (!drive)
        return;
    m_drive = *drive;
    m_dock->setConnectedDrive(m_drive.name());
    // The drive's own entries, found by what the journal indexes; isSameDrive() decides.
    JournalFilter filter;
    QString unused;
    filter.setDrive(m_drive.name(), &unused);
    ++m_changesGeneration;
    m_changesUpTo = 0;
    frame().state()->setJournalChanges({});
    m_changes->read(filter, m_changesGeneration);
    updateActions();
}

void JournalFeature::onChangesRead(const JournalReading &reading)
{
    if (reading.tag != m_changesGeneration || !reading.error.isEmpty())
        return; // the tooltips go without; the view says what is wrong with the journal
    QList<JournalEntry> ofThisDrive;
    qint64 upTo = m_changesUpTo;
    std::optional<qint64> open;
    for (const JournalEntry &entry : reading.entries) {
        upTo = std::max(upTo, entry.id);
        // Begun but not yet answered (a busy machine, a slow line): read again next time, or
        // its change would never reach the tooltip.
        if (entry.outcome == JournalOutcome::Unknown && !entry.completedTime.isValid())
            open = std::min(open.value_or(entry.id), entry.id);
        if (entry.drive.isSameDrive(m_drive))
            ofThisDrive << entry;
    }
    m_changesUpTo = open ? *open - 1 : upTo;
    JournalChanges changes = frame().state()->journalChanges();
    changes.add(ofThisDrive);
    frame().state()->setJournalChanges(changes);
    emit changesRead();
}

void JournalFeature::revert(const QList<qint64> &ids)
{
    const std::optional<JournalDrive> connected = connectedDrive();
    const QString title = tr("Revert");
    if (!connected) {
        showFileProblem(frame().frameWidget(), title,
                        tr("Nothing was written: no drive is connected."));
        return;
    }
    QList<JournalEntry> entries;
    for (const qint64 id : ids) {
        if (const JournalEntry *entry = m_dock->model()->entryById(id))
            entries << *entry;
    }
    const DriveDescription &drive = frame().state()->description();
    const JournalRevertPlan plan = JournalRevert::ofEntries(ids, entries, *connected, drive);
    if (!plan.refusals.isEmpty()) {
        showFileProblem(frame().frameWidget(), title,
                        tr("Nothing was written:\n%1").arg(plan.refusals.join(QLatin1Char('\n'))));
        return;
    }
    if (plan.values.isEmpty())
        return;
    emit revertRequested(plan.selection(drive), plan.what(), plan.job());
}

} // namespace DriveDesk
