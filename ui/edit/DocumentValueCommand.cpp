#include "DocumentValueCommand.h"

#include "model/ParameterModel.h"

namespace DriveDesk {

DocumentValueCommand::DocumentValueCommand(ParameterModel *model, quint16 address, quint8 setMask,
                                           const Values &before, const Values &after,
                                           const QString &text, QUndoCommand *parent)
    : QUndoCommand(text, parent)
    , m_model(model)
    , m_address(address)
    , m_setMask(setMask)
    , m_before(before)
    , m_after(after)
{ }

void DocumentValueCommand::redo()
{
    put(m_after);
}

void DocumentValueCommand::undo()
{
    put(m_before);
}

void DocumentValueCommand::put(const Values &values)
{
    for (int set = 0; set < kParameterSets; ++set) {
        if (m_setMask & (1u << set))
            m_model->state()->putValue(m_address, set, values[std::size_t(set)]);
    }
}

} // namespace DriveDesk
