#include "WriteValueCommand.h"

#include "EditController.h"

#include <QMap>

namespace DriveDesk {

WriteValueCommand::WriteValueCommand(EditController *controller, Kind kind, quint16 address,
                                     quint8 setMask, qint32 raw, const Values &before,
                                     const QString &text, QUndoCommand *parent)
    : QUndoCommand(text, parent)
    , m_controller(controller)
    , m_kind(kind)
    , m_address(address)
    , m_setMask(setMask)
    , m_raw(raw)
    , m_before(before)
{ }

void WriteValueCommand::redo()
{
    if (m_skipNext) {
        m_skipNext = false;
        return;
    }
    m_controller->perform(this, EditController::Direction::Redo);
}

void WriteValueCommand::undo()
{
    if (m_skipNext) {
        m_skipNext = false;
        return;
    }
    m_controller->perform(this, EditController::Direction::Undo);
}

QList<WriteStep> WriteValueCommand::redoSteps() const
{
    return { WriteStep { m_setMask, m_raw, m_kind == Kind::ResetToDefault } };
}

QList<WriteStep> WriteValueCommand::undoSteps() const
{
    QMap<qint32, quint8> masks; // earlier value -> its sets, in a stable order
    for (int set = 0; set < kParameterSets; ++set) {
        const std::optional<qint32> value = m_before[std::size_t(set)];
        if ((m_setMask & (1u << set)) && value)
            masks[*value] |= quint8(1u << set);
    }
    QList<WriteStep> steps;
    for (auto it = masks.cbegin(); it != masks.cend(); ++it)
        steps << WriteStep { it.value(), it.key(), false };
    return steps;
}

quint8 WriteValueCommand::unknownBeforeMask() const
{
    quint8 unknown = 0;
    for (int set = 0; set < kParameterSets; ++set) {
        if ((m_setMask & (1u << set)) && !m_before[std::size_t(set)])
            unknown |= quint8(1u << set);
    }
    return unknown;
}

} // namespace DriveDesk
