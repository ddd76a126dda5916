#pragma once

#include "parameters/DriveDescription.h"

#include <QUndoCommand>

#include <array>
#include <optional>

namespace DriveDesk {

class ParameterModel;

// One undoable change of one parameter in an open parameter file: the values of some sets
// before and after. Redo and undo put them into the model exactly as they were, a value never
// read included; nothing reaches a drive. The first redo() (on push) makes the change.
class DocumentValueCommand : public QUndoCommand
{
public:
    using Values = std::array<std::optional<qint32>, kParameterSets>;

    DocumentValueCommand(ParameterModel *model, quint16 address, quint8 setMask,
                         const Values &before, const Values &after, const QString &text,
                         QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

    quint16 address() const { return m_address; }
    quint8 setMask() const { return m_setMask; }

private:
    void put(const Values &values);

    ParameterModel *m_model = nullptr; // outlives the undo stack's commands
    quint16 m_address = 0;
    quint8 m_setMask = 0;
    Values m_before {};
    Values m_after {};
};

} // namespace DriveDesk
