#pragma once

#include <QtGlobal>

namespace DriveDesk {

class ValueEdits;

// Where the window's edit actions go: the connected drive (EditController) or the parameter
// file open instead of one (DocumentEditor). Values typed into the table reach either through
// ParameterModel::valueEdited; these are the edits that start from an action.
class ParameterEditing
{
public:
    virtual ~ParameterEditing() = default;

    // Sets the sets in the mask to the parameter's default; undoable.
    virtual void resetToDefault(quint16 address, quint8 setMask) = 0;
    // Every set-programmable value the user may change from `fromSet` to `toSet`; one step on
    // the undo stack.
    virtual void copySet(int fromSet, int toSet) = 0;
    // A change is on its way: undo and redo wait for it.
    virtual bool isBusy() const = 0;
    // The connected drive's edit path, for the other values a feature writes to it (the
    // scope's channels), so that they are ordered with these edits, journaled and shown; none
    // for a parameter file.
    virtual ValueEdits *driveEdits() const { return nullptr; }
};

} // namespace DriveDesk
