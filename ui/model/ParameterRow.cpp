#include "ParameterRow.h"

#include "parameters/ParameterId.h"

namespace DriveDesk {

ParameterRow::ParameterRow(const ParameterState &state)
    : m_state(&state)
{
    const QString &id = state.id();
    QString unpadded = id;
    const qsizetype dot = id.lastIndexOf(QLatin1Char('.'));
    if (dot >= 0 && id.size() > dot + 2 && id.at(dot + 1) == QLatin1Char('0'))
        unpadded.remove(dot + 1, 1);
    m_staticSearchText
        = (id + QLatin1Char('\n') + unpadded + QLatin1Char('\n')
           + ParameterId::hexAddress(state.address()) + QLatin1Char('\n')
           + state.description().name)
              .toLower();
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
        m_texts[std::size_t(cell)] = format().text(*shown);
        m_textValid |= bit;
    }
    return m_texts[std::size_t(cell)];
}

const QString &ParameterRow::searchText(bool raw) const
{
    if (!m_searchValid || m_searchRaw != raw) {
        QString values;
        for (int cell = 0; cell < m_state->cellCount(); ++cell)
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
