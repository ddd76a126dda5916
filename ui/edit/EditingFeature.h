#pragma once

#include "frame/WindowFeature.h"
#include "parameters/PasswordLevel.h"

class QProgressBar;

namespace DriveDesk {

class DocumentEditor;
class EditController;
class WriteJournal;

// Editing in the window, of the drive or of the parameter file open instead: undo and redo,
// reset to default, write to several sets, copy a set, and the progress of the edit
// controller's long jobs. The drive's edits go through an EditController made for each session,
// the file's through a DocumentEditor made for each file shown.
class EditingFeature : public WindowFeature
{
    Q_OBJECT
public:
    explicit EditingFeature(WindowFrame &frame, QObject *parent = nullptr);

    void attach(DriveSession *session) override;
    void attachFile(const QString &path) override;
    void updateActions() override;
    ParameterEditing *editing() const override;
    // A higher password level opens values the drive refused until now: they are read at once,
    // not left as "?" until the next refresh.
    void readOpenedValues(DriveDesk::PasswordLevel from, DriveDesk::PasswordLevel to);
    // Drive > Journal Every Write is on: every value the window writes is journaled.
    bool journalsWrites() const;

private:
    void resetToDefault();
    void writeToSets();
    void copySet();
    int activeSet() const; // the drive's (Fr.02); -1 when unknown or no drive

    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_resetAction = nullptr;
    QAction *m_writeSetsAction = nullptr;
    QAction *m_copySetAction = nullptr;
    QProgressBar *m_busy = nullptr;
    EditController *m_edit = nullptr; // child, of the session of the moment
    WriteJournal *m_journal = nullptr; // child: the session's edits journaled
    DocumentEditor *m_document = nullptr; // child while a parameter file is shown
};

} // namespace DriveDesk
