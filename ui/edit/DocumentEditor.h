#pragma once

#include "ValueCommand.h"
#include "frame/ParameterEditing.h"

#include "state/FileEdits.h"

#include <QHash>
#include <QObject>

class QUndoCommand;
class QUndoStack;

namespace DriveDesk {

class ParameterModel;

// Carries the user's edits into the parameter file the window shows instead of a drive: a value
// typed into the table, a reset to default, a copied set, each made through core's FileEdits
// in the file's DriveState and kept as a ValueCommand on the window's undo stack, the command
// type a drive's edits use too. The rule is a drive's (EditCheck). Nothing is ever sent to a
// drive.
// A cell whose value is no longer the one the file holds on disk is marked changed
// (EditState::Changed) until an undo brings that value back or the file is saved (the undo
// stack made clean). Lives in the GUI thread; the model and the undo stack outlive it.
class DocumentEditor : public QObject, public ParameterEditing, public ValueCommand::Host
{
    Q_OBJECT
public:
    DocumentEditor(ParameterModel *model, QUndoStack *undoStack, QObject *parent = nullptr);

    // Connected to ParameterModel::valueEdited by the editor itself: the value goes into the
    // sets of the mask, or is refused with the reason (message()) and the cells stay as they
    // were. Messages name the change as the drive's edits do (EditText).
    void write(quint16 address, quint8 setMask, qint32 raw);
    void resetToDefault(quint16 address, quint8 setMask) override;
    void copySet(int fromSet, int toSet) override;
    bool isBusy() const override { return false; } // every change is made at once

    // Undo and redo of a command on the stack: the file's values as they were, exactly (a value
    // never read included), or as the change made them.
    void perform(ValueCommand *command, ValueCommand::Direction direction) override;

signals:
    void message(const QString &text); // for the status bar: results and refusals in words

private:
    // Puts `raw` into the sets of the mask (FileEdits) and gives the command that undoes it, or
    // changes nothing and gives nullptr with the reason: no such parameter, not editable,
    // outside the limits (EditCheck), or none where the sets hold `raw` already. `setMask` comes
    // back as applied (set 0 for a parameter without sets).
    QUndoCommand *makeChange(quint16 address, quint8 *setMask, qint32 raw, ValueCommand::Kind kind,
                             const QString &text, QString *refusal,
                             QUndoCommand *parent = nullptr);
    // The undo history's name of a change: "Change oP.11 to 5.00 s".
    QString commandText(quint16 address, quint8 setMask, qint32 raw) const;

    // Keeps the value on disk of a parameter about to change for the first time.
    void rememberSaved(quint16 address);
    // Marks the cells of the remembered parameters that differ from the file on disk, and
    // clears the others' marks.
    void markChanges();
    void onCleanChanged(bool clean);
    // Every change of the file goes on the stack here: the stack's moves that come from
    // elsewhere are undo and redo, and say so.
    void push(QUndoCommand *command);
    void onIndexChanged(int index);

    ParameterModel *m_model = nullptr;
    QUndoStack *m_undoStack = nullptr;
    int m_index = 0;        // the stack's index as last seen
    bool m_pushing = false; // a change of ours goes on the stack
    // The values on disk of the parameters changed here since the file was opened.
    QHash<quint16, ValueCommand::Values> m_saved;
    FileEdits m_files; // every change of the file's values, undo and redo included
};

} // namespace DriveDesk
