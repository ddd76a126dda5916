#include "ParameterState.h"

#include "parameters/ParameterAccess.h"

namespace DriveDesk {

ParameterState::ParameterState(const ParameterDescription &description, const QString &id)
    : m_description(description)
    , m_format(description)
    , m_properties(description.properties1, description.properties2)
    , m_id(id)
{ }

std::optional<qint32> ParameterState::shownValue(int cell) const
{
    if (m_states[std::size_t(cell)] == EditState::Pending)
        return m_requested[std::size_t(cell)];
    return value(cell);
}

bool ParameterState::setValue(int cell, std::optional<qint32> raw)
{
    auto &stored = m_description.values[std::size_t(cell)];
    if (stored == raw)
        return false;
    stored = raw;
    // A value that moved away from what was written is no longer "written".
    EditState &state = m_states[std::size_t(cell)];
    if (state == EditState::Written && raw != m_requested[std::size_t(cell)])
        state = EditState::None;
    return true;
}

std::optional<qint32> ParameterState::requestedValue(int cell) const
{
    // A changed file cell asked nothing of a drive.
    const EditState state = m_states[std::size_t(cell)];
    if (state == EditState::None || state == EditState::Changed)
        return std::nullopt;
    return m_requested[std::size_t(cell)];
}

void ParameterState::markPending(int cell, qint32 raw)
{
    m_states[std::size_t(cell)] = EditState::Pending;
    m_requested[std::size_t(cell)] = raw;
    m_failures[std::size_t(cell)].clear();
}

void ParameterState::markWritten(int cell)
{
    m_states[std::size_t(cell)] = EditState::Written;
    m_description.values[std::size_t(cell)] = m_requested[std::size_t(cell)];
    m_failures[std::size_t(cell)].clear();
}

void ParameterState::markWritten(int cell, qint32 held)
{
    m_requested[std::size_t(cell)] = held;
    markWritten(cell);
}

void ParameterState::markFailed(int cell, const QString &reason)
{
    m_states[std::size_t(cell)] = EditState::Failed;
    m_failures[std::size_t(cell)] = reason;
}

void ParameterState::markUnknown(int cell, const QString &reason)
{
    m_states[std::size_t(cell)] = EditState::Unknown;
    m_failures[std::size_t(cell)] = reason;
}

void ParameterState::markChanged(int cell)
{
    m_states[std::size_t(cell)] = EditState::Changed;
    m_failures[std::size_t(cell)].clear();
}

bool ParameterState::clearEditState(int cell)
{
    if (m_states[std::size_t(cell)] == EditState::None)
        return false;
    m_states[std::size_t(cell)] = EditState::None;
    m_failures[std::size_t(cell)].clear();
    return true;
}

bool ParameterState::differsFromDefault() const
{
    // Live values, counters and read-only values differ from their default by nature; they
    // would bury the settings someone changed.
    if (!isUserSetting(m_description))
        return false;
    for (int cell = 0; cell < cellCount(); ++cell) {
        const std::optional<qint32> shown = shownValue(cell);
        if (shown && *shown != m_description.defaultValue)
            return true;
    }
    return false;
}

} // namespace DriveDesk
