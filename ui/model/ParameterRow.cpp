#include "ParameterRow.h"

#include "parameters/ParameterAccess.h"
#include "parameters/ParameterId.h"

namespace DriveDesk {

ParameterRow::ParameterRow(const ParameterDescription &description, const QString &id)
    : m_description(description)
    , m_format(description)
    , m_properties(description.properties1, description.properties2)
    , m_id(id)
{
    QString unpadded = id;
    const qsizetype dot = id.lastIndexOf(QLatin1Char('.'));
    if (dot >= 0 && id.size() > dot + 2 && id.at(dot + 1) == QLatin1Char('0'))
        unpadded.remove(dot + 1, 1);
    m_staticSearchText
        = (id + QLatin1Char('\n') + unpadded + QLatin1Char('\n')
           + ParameterId::hexAddress(description.address) + QLatin1Char('\n') + description.name)
              .toLower();
}

std::optional<qint32> ParameterRow::shownValue(int cell) const
{
    if (m_states[std::size_t(cell)] == EditState::Pending)
        return m_requested[std::size_t(cell)];
    return value(cell);
}

bool ParameterRow::setValue(int cell, std::optional<qint32> raw)
{
    auto &stored = m_description.values[std::size_t(cell)];
    EditState &state = m_states[std::size_t(cell)];
    if (stored == raw)
        return false;
    stored = raw;
    // A value that moved away from what was written is no longer "written".
    if (state == EditState::Written && raw != m_requested[std::size_t(cell)])
        state = EditState::None;
    invalidate(cell);
    return true;
}

std::optional<qint32> ParameterRow::requestedValue(int cell) const
{
    // A changed file cell asked nothing of a drive.
    const EditState state = m_states[std::size_t(cell)];
    if (state == EditState::None || state == EditState::Changed)
        return std::nullopt;
    return m_requested[std::size_t(cell)];
}

void ParameterRow::markPending(int cell, qint32 raw)
{
    m_states[std::size_t(cell)] = EditState::Pending;
    m_requested[std::size_t(cell)] = raw;
    m_failures[std::size_t(cell)].clear();
    invalidate(cell);
}

void ParameterRow::markWritten(int cell)
{
    m_states[std::size_t(cell)] = EditState::Written;
    m_description.values[std::size_t(cell)] = m_requested[std::size_t(cell)];
    m_failures[std::size_t(cell)].clear();
    invalidate(cell);
}

void ParameterRow::markWritten(int cell, qint32 held)
{
    m_requested[std::size_t(cell)] = held;
    markWritten(cell);
}

void ParameterRow::markFailed(int cell, const QString &reason)
{
    m_states[std::size_t(cell)] = EditState::Failed;
    m_failures[std::size_t(cell)] = reason;
    invalidate(cell);
}

void ParameterRow::markUnknown(int cell, const QString &reason)
{
    m_states[std::size_t(cell)] = EditState::Unknown;
    m_failures[std::size_t(cell)] = reason;
    invalidate(cell);
}

void ParameterRow::markChanged(int cell)
{
    m_states[std::size_t(cell)] = EditState::Changed;
    m_failures[std::size_t(cell)].clear();
    invalidate(cell);
}

bool ParameterRow::clearEditState(int cell)
{
    if (m_states[std::size_t(cell)] == EditState::None)
        return false;
    m_states[std::size_t(cell)] = EditState::None;
    m_failures[std::size_t(cell)].clear();
    invalidate(cell);
    return true;
}

QString ParameterRow::text(int cell, bool raw) const
{
    const std::optional<qint32> shown = shownValue(cell);
    if (!shown)
        return {};
    if (raw)
        return QString::number(*shown);
    const quint8 bit = quint8(1u << cell);
    if (!(m_textValid & bit)) {
        m_texts[std::size_t(cell)] = m_format.text(*shown);
        m_textValid |= bit;
    }
    return m_texts[std::size_t(cell)];
}

bool ParameterRow::differsFromDefault() const
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

const QString &ParameterRow::searchText(bool raw) const
{
    if (!m_searchValid || m_searchRaw != raw) {
        QString values;
        for (int cell = 0; cell < cellCount(); ++cell)
            values += QLatin1Char('\n') + text(cell, raw);
        m_searchText = m_staticSearchText + values.toLower();
        m_searchValid = true;
        m_searchRaw = raw;
    }
    return m_searchText;
}

void ParameterRow::invalidate(int cell)
{
    m_textValid &= quint8(~(1u << cell));
    m_searchValid = false;
}

} // namespace DriveDesk
