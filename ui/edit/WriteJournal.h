#pragma once

#include <QObject>
#include <QPointer>

#include <memory>

class QAction;

namespace DriveDesk {

class DriveSession;
class EditController;
class EditJournal;
class Journal;
class WindowFrame;

// The window's journal of the values it writes (docs/journal.md): opened for each drive
// session and handed to its EditController, so that each edit, undo and redo is journaled
// before it goes out. Drive > Journal Every Write (remembered) is the user's choice to write
// without it; while it is on and the journal cannot be written, every write is refused with
// the reason.
class WriteJournal : public QObject
{
    Q_OBJECT
public:
    WriteJournal(WindowFrame &frame, QObject *parent = nullptr);
    ~WriteJournal() override;

    // The session's edits from now on; none: no session.
    void attach(DriveSession *session, EditController *edit);
    QAction *action() const { return m_action; }
    // Drive > Journal Every Write: the window's writes are journaled.
    bool isOn() const;

private:
    void apply();

    WindowFrame &m_frame;
    QAction *m_action = nullptr;
    QPointer<DriveSession> m_session;
    QPointer<EditController> m_edit;
    std::unique_ptr<Journal> m_journal;
    std::unique_ptr<EditJournal> m_editJournal;
};

} // namespace DriveDesk
