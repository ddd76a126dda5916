#pragma once

#include "parameters/DriveDescription.h"
#include "parameters/ParameterFormat.h"
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

// One parameter of a DriveState: what the drive (or the file) says about it, the values it
// holds per set, when they were last read and where each cell stands with an edit. A parameter
// that is not set-programmable has one cell, set 0.
class ParameterState
{
public:
    ParameterState(const ParameterDescription &description, const QString &id);

    const ParameterDescription &description() const { return m_description; }
    const ParameterFormat &format() const { return m_format; }
    const ParameterProperties &properties() const { return m_properties; }
    // As every message and table names it ("ru.03").
    const QString &id() const { return m_id; }
    quint16 address() const { return m_description.address; }
    int cellCount() const { return m_description.isSetProgrammable() ? kParameterSets : 1; }
    bool hasCell(int set) const { return set >= 0 && set < cellCount(); }
    // The cell a set's value lives in: set 0 for parameters that are not set-programmable.
    int cellOf(int set) const { return m_description.isSetProgrammable() ? set : 0; }

    // The value held; nothing where it was never read.
    std::optional<qint32> value(int cell) const { return m_description.values[std::size_t(cell)]; }
    // The value asked for while its write is pending, otherwise the one held.
    std::optional<qint32> shownValue(int cell) const;
    // False when the value did not change.
    bool setValue(int cell, std::optional<qint32> raw);
    // When a value of this parameter last came from the drive (ms since the epoch; 0: never).
    qint64 readAtMs() const { return m_readAtMs; }
    void markRead(qint64 msecsSinceEpoch) { m_readAtMs = msecsSinceEpoch; }

    EditState editState(int cell) const { return m_states[std::size_t(cell)]; }
    // What a write asked for (pending, written, failed, unknown); nothing otherwise.
    std::optional<qint32> requestedValue(int cell) const;
    // Why a write failed or is unknown.
    const QString &failure(int cell) const { return m_failures[std::size_t(cell)]; }
    void markPending(int cell, qint32 raw);
    void markWritten(int cell);
    // Written, and the drive holds `held`: a parameter that changes what was written to it.
    void markWritten(int cell, qint32 held);
    void markFailed(int cell, const QString &reason);
    void markUnknown(int cell, const QString &reason);
    void markChanged(int cell);
    bool clearEditState(int cell);

    // A user setting (isUserSetting) whose shown value in some cell differs from the default.
    bool differsFromDefault() const;

private:
    ParameterDescription m_description;
    ParameterFormat m_format;
    ParameterProperties m_properties;
    QString m_id;
    std::array<EditState, kParameterSets> m_states {};
    std::array<qint32, kParameterSets> m_requested {};
    std::array<QString, kParameterSets> m_failures;
    qint64 m_readAtMs = 0;
};

} // namespace DriveDesk
