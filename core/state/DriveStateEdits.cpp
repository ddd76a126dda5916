// DriveState: the cells' edit states (pending, written, failed, unknown, changed) and what a
// write's outcome and a read-back make of them.
#include "DriveState.h"

#include "parameters/ParameterAccess.h"
#include "session/ValueChange.h"

#include <algorithm>

namespace DriveDesk {

template<typename Change>
void DriveState::changeCells(quint16 address, quint8 setMask, Change change)
{
    ParameterState *found = findMutable(address);
    if (!found)
        return;
    int first = kParameterSets;
    int last = -1;
    for (int set = 0; set < kParameterSets; ++set) {
        if (!(setMask & (1u << set)))
            continue;
        const int cell = found->cellOf(set);
        first = std::min(first, cell);
        last = std::max(last, cell);
        change(*found, cell);
    }
    if (last >= 0)
        cellsChangedAt(address, first, last);
}

void DriveState::markPending(quint16 address, quint8 setMask, qint32 raw)
{
    changeCells(address, setMask,
                [raw](ParameterState &parameter, int cell) { parameter.markPending(cell, raw); });
}

void DriveState::markWritten(quint16 address, quint8 setMask)
{
    changeCells(address, setMask, [](ParameterState &parameter, int cell) {
        if (parameter.requestedValue(cell))
            parameter.markWritten(cell);
    });
}

void DriveState::markFailed(quint16 address, quint8 setMask, const QString &reason)
{
    changeCells(address, setMask, [&reason](ParameterState &parameter, int cell) {
        parameter.markFailed(cell, reason);
    });
}

void DriveState::markUnknown(quint16 address, quint8 setMask, const QString &reason)
{
    changeCells(address, setMask, [&reason](ParameterState &parameter, int cell) {
        parameter.markUnknown(cell, reason);
    });
}

void DriveState::markChanged(quint16 address, quint8 setMask)
{
    changeCells(address, setMask,
                [](ParameterState &parameter, int cell) { parameter.markChanged(cell); });
}

void DriveState::confirmReadBack(quint16 address, int set, qint32 raw)
{
    if (set < 0 || set >= kParameterSets)
        return;
    changeCells(address, quint8(1u << set), [raw](ParameterState &parameter, int cell) {
        const std::optional<qint32> requested = parameter.requestedValue(cell);
        parameter.setValue(cell, raw);
        if (!requested)
            return;
        if (readBackMayDiffer(parameter.description())) {
            parameter.markWritten(cell, raw);
            return;
        }
        if (*requested == raw) {
            parameter.markWritten(cell);
            return;
        }
        const ParameterFormat &format = parameter.format();
        parameter.markFailed(cell, tr("the drive holds %1, not %2")
                                       .arg(format.text(raw), format.text(*requested)));
    });
}

void DriveState::showOutcome(const WriteOutcome &outcome, bool superseded)
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

void DriveState::clearEditStates()
{
    for (Group &group : m_groups) {
        for (ParameterState &parameter : group.rows) {
            bool changed = false;
            for (int cell = 0; cell < parameter.cellCount(); ++cell)
                changed = parameter.clearEditState(cell) || changed;
            if (changed)
                cellsChangedAt(parameter.address(), 0, parameter.cellCount() - 1);
        }
    }
}

void DriveState::clearEditState(quint16 address, quint8 setMask)
{
    changeCells(address, setMask,
                [](ParameterState &parameter, int cell) { parameter.clearEditState(cell); });
}

EditState DriveState::editState(quint16 address, int set) const
{
    const ParameterState *found = find(address);
    if (!found || set < 0 || set >= kParameterSets)
        return EditState::None;
    return found->editState(found->cellOf(set));
}

} // namespace DriveDesk
