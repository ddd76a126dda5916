// ParameterModel: the cells' edit states (pending, written, failed, changed) and what a write's
// outcome and a read-back show in them.
#include "ParameterModel.h"

#include "parameters/ParameterAccess.h"
#include "session/ValueChange.h"

#include <algorithm>

namespace DriveDesk {

void ParameterModel::showOutcome(const WriteOutcome &outcome, bool superseded)
{
    const quint16 address = outcome.address;
    const quint8 unknown = outcome.unknownMask();
    const quint8 refused = outcome.refusedMask & quint8(~unknown);
    if (refused && !superseded)
        markFailed(address, refused, outcome.error);
    if (unknown && !superseded)
        markUnknown(address, unknown, outcome.error);
    // A write whose answer never came, settled by reading the set: it holds another value.
    for (int set = 0; set < kParameterSets; ++set) {
        const auto bit = quint8(1u << set);
        const std::optional<qint32> held = outcome.readBack[std::size_t(set)];
        if ((refused & bit) && held)
            setValue(address, set, *held);
    }
    for (int set = 0; set < kParameterSets; ++set) {
        if (!(outcome.acknowledgedMask & (1u << set)))
            continue;
        if (const std::optional<qint32> value = outcome.readBack[std::size_t(set)]) {
            if (superseded)
                setValue(address, set, *value);
            else
                confirmReadBack(address, set, *value);
        } else if (!superseded) {
            // The drive acknowledged the write; only the confirmation is missing.
            markWritten(address, quint8(1u << set));
        }
    }
}

template<typename Change>
void ParameterModel::changeCells(quint16 address, quint8 setMask, Change change)
{
    ParameterRow *row = rowAt(address);
    if (!row)
        return;
    int first = kParameterSets;
    int last = -1;
    for (int set = 0; set < kParameterSets; ++set) {
        if (!(setMask & (1u << set)))
            continue;
        const int cell = row->cellOf(set);
        first = std::min(first, cell);
        last = std::max(last, cell);
        change(*row, cell);
    }
    if (last >= 0)
        emit dataChanged(indexOf(address, columnOfSet(first)), indexOf(address, columnOfSet(last)));
}

void ParameterModel::markPending(quint16 address, quint8 setMask, qint32 raw)
{
    changeCells(address, setMask,
                [raw](ParameterRow &row, int cell) { row.markPending(cell, raw); });
}

void ParameterModel::markWritten(quint16 address, quint8 setMask)
{
    changeCells(address, setMask, [](ParameterRow &row, int cell) {
        if (row.requestedValue(cell))
            row.markWritten(cell);
    });
}

void ParameterModel::markFailed(quint16 address, quint8 setMask, const QString &reason)
{
    changeCells(address, setMask,
                [&reason](ParameterRow &row, int cell) { row.markFailed(cell, reason); });
}

void ParameterModel::markUnknown(quint16 address, quint8 setMask, const QString &reason)
{
    changeCells(address, setMask,
                [&reason](ParameterRow &row, int cell) { row.markUnknown(cell, reason); });
}

void ParameterModel::markChanged(quint16 address, quint8 setMask)
{
    changeCells(address, setMask, [](ParameterRow &row, int cell) { row.markChanged(cell); });
}

void ParameterModel::confirmReadBack(quint16 address, int set, qint32 raw)
{
    if (set < 0 || set >= kParameterSets)
        return;
    changeCells(address, quint8(1u << set), [this, raw](ParameterRow &row, int cell) {
        const std::optional<qint32> requested = row.requestedValue(cell);
        row.setValue(cell, raw);
        if (!requested)
            return;
        if (readBackMayDiffer(row.description())) {
            row.markWritten(cell, raw);
            return;
        }
        if (*requested == raw) {
            row.markWritten(cell);
            return;
        }
        row.markFailed(
            cell,
            tr("the drive holds %1, not %2").arg(valueText(row, raw), valueText(row, *requested)));
    });
}

void ParameterModel::clearEditStates()
{
    for (Group &group : m_groups) {
        for (ParameterRow &row : group.rows) {
            for (int cell = 0; cell < row.cellCount(); ++cell)
                row.clearEditState(cell);
        }
    }
    emitAllChanged();
}

void ParameterModel::clearEditState(quint16 address, quint8 setMask)
{
    changeCells(address, setMask, [](ParameterRow &row, int cell) { row.clearEditState(cell); });
}

EditState ParameterModel::editState(quint16 address, int set) const
{
    const ParameterRow *row = rowAt(address);
    if (!row || set < 0 || set >= kParameterSets)
        return EditState::None;
    return row->editState(row->cellOf(set));
}

} // namespace DriveDesk
