#pragma once

#include "parameters/ParameterFormat.h"

#include "parameters/DriveDescription.h"
#include "parameters/ParameterProperties.h"

#include <QString>

#include <array>
#include <optional>

namespace DriveDesk {

// Where a value cell stands with the write the user asked for.
enum class EditState : quint8 {
    None,
    Pending, // the write was sent; the cell shows the value asked for
    Written, // the drive holds what was written
    Failed, // the drive refused or holds something else; the reason is kept
    Unknown, // no answer came, and reading the value could not settle whether the drive took it
    Changed, // an open parameter file's value, changed here and not saved (no drive involved)
};

// One parameter of the ParameterModel: its description with the drive's values, the edit state
// of each value cell and the texts shown and searched, built once and again only when a value
// changes. Not set-programmable parameters have one cell, set 0.
class ParameterRow
{
public:
    ParameterRow(const ParameterDescription &description, const QString &id);

    const ParameterDescription &description() const { return m_description; }
    const ParameterFormat &format() const { return m_format; }
    const ParameterProperties &properties() const { return m_properties; }
    const QString &id() const { return m_id; }
    quint16 address() const { return m_description.address; }
    int cellCount() const { return m_description.isSetProgrammable() ? kParameterSets : 1; }
    bool hasCell(int set) const { return set >= 0 && set < cellCount(); }
    // The cell a set's value lives in: set 0 for parameters that are not set-programmable.
    int cellOf(int set) const { return m_description.isSetProgrammable() ? set : 0; }

    // The drive's value; nothing where it was never read.
    std::optional<qint32> value(int cell) const { return m_description.values[std::size_t(cell)]; }
    // The value asked for while its write is pending, otherwise the drive's.
    std::optional<qint32> shownValue(int cell) const;
    // Stores what the drive reported (or, for an open parameter file, nothing: a value not
    // read); false when the value did not change.
    bool setValue(int cell, std::optional<qint32> raw);
    // When a value of this parameter last came from the drive (ms since the epoch; 0: never).
    qint64 readAtMs() const { return m_readAtMs; }
    void markRead(qint64 msecsSinceEpoch) { m_readAtMs = msecsSinceEpoch; }

    EditState editState(int cell) const { return m_states[std::size_t(cell)]; }
    std::optional<qint32> requestedValue(int cell) const;
    const QString &failure(int cell) const { return m_failures[std::size_t(cell)]; }
    void markPending(int cell, qint32 raw);
    void markWritten(int cell);
    // Written, and the drive holds `held`: a parameter that changes what was written to it.
    void markWritten(int cell, qint32 held);
    void markFailed(int cell, const QString &reason);
    void markUnknown(int cell, const QString &reason);
    void markChanged(int cell);
    bool clearEditState(int cell);

    // The shown value as text, scaled or as plaintext, or the raw integer; empty when unknown.
    QString text(int cell, bool raw) const;
    bool differsFromDefault() const;
    // Lower-case: the id with and without leading zero ("ru.03", "ru.3"), the hexadecimal
    // address, the name and every shown value, separated by line breaks.
    const QString &searchText(bool raw) const;

private:
    void invalidate(int cell);

    ParameterDescription m_description;
    ParameterFormat m_format;
    ParameterProperties m_properties;
    QString m_id;
    QString m_staticSearchText;
    std::array<EditState, kParameterSets> m_states {};
    std::array<qint32, kParameterSets> m_requested {};
    std::array<QString, kParameterSets> m_failures;
    qint64 m_readAtMs = 0;

    // Built when first asked for; a changed value drops its cell's text and the search text.
    mutable std::array<QString, kParameterSets> m_texts;
    mutable quint8 m_textValid = 0;
    mutable QString m_searchText;
    mutable bool m_searchValid = false;
    mutable bool m_searchRaw = false;
};

} // namespace DriveDesk
