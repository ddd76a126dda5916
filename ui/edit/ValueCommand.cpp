#include "ValueCommand.h"

namespace DriveDesk {

ValueCommand::ValueCommand(Host *host, Kind kind, quint16 address, quint8 setMask, qint32 raw,
                           const Values &before, const QString &text, QUndoCommand *parent)
    : QUndoCommand(text, parent)
    , m_host(host)
    , m_kind(kind)
    , m_address(address)
    , m_setMask(setMask)
    , m_raw(raw)
    , m_before(before)
{ }

void ValueCommand::redo()
{
    if (m_skipNext) {
        m_skipNext = false;
        return;
    }
    m_host->perform(this, Direction::Redo);
}

void ValueCommand::undo()
{
    if (m_skipNext) {
        m_skipNext = false;
        return;
    }
    m_host->perform(this, Direction::Undo);
}

QList<WriteStep> ValueCommand::redoSteps() const
{
    return { WriteStep { m_setMask, m_raw, m_kind == Kind::ResetToDefault } };
}

quint8 ValueCommand::unknownBeforeMask() const
{
    quint8 unknown = 0;
    for (int set = 0; set < kParameterSets; ++set) {
        if ((m_setMask & (1u << set)) && !m_before[std::size_t(set)])
            unknown |= quint8(1u << set);
    }
    return unknown;
}

} // namespace DriveDesk
