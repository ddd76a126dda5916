#include "WriteJournal.h"

#include "EditController.h"

#include "frame/DriveSession.h"
#include "frame/WindowFrame.h"
#include "journal/Journal.h"
#include "session/EditJournal.h"
#include "state/DriveState.h"

#include <QAction>
#include <QMenu>
#include <QSettings>

namespace DriveDesk {

namespace {

const QString kWritesKey = QStringLiteral("journal/writes");

} // namespace

WriteJournal::WriteJournal(WindowFrame &frame, QObject *parent)
    : QObject(parent)
    , m_frame(frame)
{
    m_action = new QAction(tr("&Journal Every Write"), this);
    m_action->setObjectName(QStringLiteral("journalWritesAction"));
    m_action->setCheckable(true);
    m_action->setChecked(QSettings().value(kWritesKey, true).toBool());
    m_action->setToolTip(tr("Record every value written to the drive, with the value before and "
                            "after, in the journal %1")
                             .arg(Journal::defaultPath()));
    connect(m_action, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue(kWritesKey, on);
        apply();
        m_frame.showMessage(on ? tr("Every value written is journaled.")
                               : tr("Values written are not journaled."));
    });
    QMenu *drive = frame.menu(WindowFrame::Menu::Drive);
    drive->addSeparator();
    drive->addAction(m_action);
}

WriteJournal::~WriteJournal() = default;

void WriteJournal::attach(DriveSession *session, EditController *edit)
{
    m_session = session;
    m_edit = edit;
    m_editJournal.reset();
    m_journal.reset();
    if (session) {
        // The drive as the journal names it, once it has been read.
        connect(session, &DriveSession::ready, this, [this] {
            if (m_editJournal && m_session) {
                m_editJournal->setDrive(
                    EditJournal::driveOf(m_session->settings(), m_frame.state()->description()));
            }
        });
    }
    apply();
}

bool WriteJournal::isOn() const
{
    return m_action->isChecked();
}

void WriteJournal::apply()
{
    if (!m_edit || !m_session)
        return;
    if (!m_action->isChecked()) {
        m_edit->setJournal(nullptr);
        m_editJournal.reset();
        m_journal.reset();
        return;
    }
    if (!m_editJournal) {
        m_journal = std::make_unique<Journal>();
        m_editJournal = std::make_unique<EditJournal>(
            m_journal.get(),
            EditJournal::driveOf(m_session->settings(), m_frame.state()->description()),
            tr("edit"));
        if (!m_journal->open()) {
            m_editJournal->setUnavailable(
                tr("%1 (Drive > Journal Every Write off writes without it)")
                    .arg(m_journal->errorString()));
        }
    }
    m_edit->setJournal(m_editJournal.get());
}

} // namespace DriveDesk
