#include "FileEdits.h"

#include "parameters/SetList.h"
#include "state/DriveState.h"

namespace DriveDesk {

namespace {

// What a file's sets hold after a change: every set changed counts as written and read back.
EditOutcome heldAfter(const DriveState &state, quint16 address, quint8 setMask)
{
    EditOutcome outcome;
    outcome.address = address;
    outcome.acknowledgedMask = setMask;
    for (int set = 0; set < kParameterSets; ++set) {
        if (setMask & (1u << set))
            outcome.readBack[std::size_t(set)] = state.value(address, set);
    }
    return outcome;
}

} // namespace

FileEdits::FileEdits(DriveState *state)
    : m_state(state)
{ }

void FileEdits::apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
                      Done done)
{
    const quint16 address = parameter.address;
    Values before {};
    quint8 changed = 0;
    for (WriteStep &step : steps) {
        step.setMask = SetList::setsWritten(parameter, step.setMask);
        if (step.reset)
            step.raw = parameter.defaultValue;
        for (int set = 0; set < kParameterSets; ++set) {
            if (!(step.setMask & (1u << set)))
                continue;
            if (!(changed & (1u << set)))
                before[std::size_t(set)] = m_state->value(address, set);
            m_state->putValue(address, set, step.raw);
            changed |= quint8(1u << set);
        }
    }
    EditOutcome outcome = heldAfter(*m_state, address, changed);
    outcome.reset = reset;
    outcome.steps = std::move(steps);
    outcome.before = before;
    if (done)
        done(outcome);
}

void FileEdits::restore(const ParameterDescription &parameter, quint8 setMask,
                        const Values &before, Done done)
{
    for (int set = 0; set < kParameterSets; ++set) {
        if (setMask & (1u << set))
            m_state->putValue(parameter.address, set, before[std::size_t(set)]);
    }
    if (done)
        done(heldAfter(*m_state, parameter.address, setMask));
}

} // namespace DriveDesk
