#pragma once

#include "state/ParameterState.h"

#include <QString>

#include <array>

namespace DriveDesk {

// One parameter row of the ParameterModel: the texts the table shows and searches for a
// parameter of the DriveState, built once and again only when one of its values changes.
// Everything else it reads from the state.
class ParameterRow
{
public:
    explicit ParameterRow(const ParameterState &state);

    const ParameterState &state() const { return *m_state; }
    const ParameterDescription &description() const { return m_state->description(); }
    const ParameterFormat &format() const { return m_state->format(); }
    const ParameterProperties &properties() const { return m_state->properties(); }
    const QString &id() const { return m_state->id(); }
    quint16 address() const { return m_state->address(); }
    bool hasCell(int set) const { return m_state->hasCell(set); }
    std::optional<qint32> value(int cell) const { return m_state->value(cell); }
    std::optional<qint32> shownValue(int cell) const { return m_state->shownValue(cell); }
    EditState editState(int cell) const { return m_state->editState(cell); }
    std::optional<qint32> requestedValue(int cell) const { return m_state->requestedValue(cell); }
    const QString &failure(int cell) const { return m_state->failure(cell); }
    qint64 readAtMs() const { return m_state->readAtMs(); }

    // The shown value as text, scaled or as plaintext, or the raw integer; empty when unknown.
    QString text(int cell, bool raw) const;
    // Lower-case: the id with and without leading zero ("ru.03", "ru.3"), the hexadecimal
    // address, the name and every shown value, separated by line breaks.
    const QString &searchText(bool raw) const;
    // The cell's value or edit state changed: its text is built again when next asked for.
    void invalidate(int cell);

private:
    const ParameterState *m_state;
    QString m_staticSearchText;

    // Built when first asked for; a changed value drops its cell's text and the search text.
    mutable std::array<QString, kParameterSets> m_texts;
    mutable quint8 m_textValid = 0;
    mutable QString m_searchText;
    mutable bool m_searchValid = false;
    mutable bool m_searchRaw = false;
};

} // namespace DriveDesk
