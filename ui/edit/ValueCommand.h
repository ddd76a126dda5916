#pragma once

#include "state/StateEditor.h"

#include <QUndoCommand>

#include <array>
#include <memory>
#include <optional>

namespace DriveDesk {

// One undoable change of one parameter, of a drive or of a parameter file: a value put into
// some sets, or those sets reset to their default, with what they held before. Redo and undo
// go through its Host (the drive's EditController, the file's DocumentEditor), which makes
// them with its StateEditor. The change is made before the command is pushed, so the first
// redo() does nothing.
class ValueCommand : public QUndoCommand
{
public:
    enum class Kind : quint8 { Write, ResetToDefault };
    enum class Direction : quint8 { Redo, Undo };
    using Values = StateEditor::Values;

    class Host
    {
    public:
        virtual ~Host() = default;
        virtual void perform(ValueCommand *command, Direction direction) = 0;
    };

    ValueCommand(Host *host, Kind kind, quint16 address, quint8 setMask, qint32 raw,
                 const Values &before, const QString &text, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    // The next redo() or undo() does nothing: the drive or file already holds that state.
    void skipNext() { m_skipNext = true; }

    Kind kind() const { return m_kind; }
    quint16 address() const { return m_address; }
    quint8 setMask() const { return m_setMask; }
    qint32 raw() const { return m_raw; }
    const Values &before() const { return m_before; }
    QList<WriteStep> redoSteps() const;
    // The sets of the mask whose earlier value is not known (a drive cannot put it back).
    quint8 unknownBeforeMask() const;
    // Expires with the command: a drive's answer may come after the stack deleted it.
    std::weak_ptr<const int> lifeToken() const { return m_life; }

private:
    Host *m_host = nullptr;
    Kind m_kind = Kind::Write;
    quint16 m_address = 0;
    quint8 m_setMask = 0;
    qint32 m_raw = 0;
    Values m_before {};
    bool m_skipNext = true;
    std::shared_ptr<const int> m_life = std::make_shared<const int>(0);
};

} // namespace DriveDesk
