#pragma once

#include "session/ValueChange.h"

#include <QUndoCommand>

#include <array>
#include <memory>
#include <optional>

namespace DriveDesk {

class EditController;

// One undoable change of one parameter: a value written to some sets, or those sets reset to
// their default. Redo and undo go to the drive through the EditController, which reads the
// sets back. The change is made before the command is pushed, so the first redo() does nothing.
class WriteValueCommand : public QUndoCommand
{
public:
    enum class Kind : quint8 { Write, ResetToDefault };
    using Values = std::array<std::optional<qint32>, kParameterSets>;

    WriteValueCommand(EditController *controller, Kind kind, quint16 address, quint8 setMask,
                      qint32 raw, const Values &before, const QString &text,
                      QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

    // The next redo() or undo() does nothing: the drive already holds that state.
    void skipNext() { m_skipNext = true; }

    Kind kind() const { return m_kind; }
    quint16 address() const { return m_address; }
    quint8 setMask() const { return m_setMask; }
    qint32 raw() const { return m_raw; }
    const Values &before() const { return m_before; }

    QList<WriteStep> redoSteps() const;
    // One write per distinct earlier value; sets whose earlier value is unknown are left out.
    QList<WriteStep> undoSteps() const;
    quint8 unknownBeforeMask() const;
    // Expires with the command: the drive's answer may come after the stack deleted it.
    std::weak_ptr<const int> lifeToken() const { return m_life; }

private:
    EditController *m_controller = nullptr;
    Kind m_kind = Kind::Write;
    quint16 m_address = 0;
    quint8 m_setMask = 0;
    qint32 m_raw = 0;
    Values m_before {};
    bool m_skipNext = true;
    std::shared_ptr<const int> m_life = std::make_shared<const int>(0);
};

} // namespace DriveDesk
