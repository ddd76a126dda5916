#pragma once

#include "parameters/ParameterFormat.h"

#include <QString>

#include <optional>

namespace DriveDesk {

// What every editor of a parameter value offers the ParameterDelegate, whatever its widget.
// The editor remembers the value it started with: committing it unchanged writes nothing, and
// a starting value outside the limits is no reason to refuse an editor the user left alone.
class ValueEditor
{
public:
    explicit ValueEditor(const ParameterFormat &format)
        : m_format(format)
    { }
    virtual ~ValueEditor() = default;

    const ParameterFormat &format() const { return m_format; }

    // The first call sets the starting value; later calls (a view repeats them whenever the
    // cell's data changes) are ignored so that what the user is entering stays.
    void start(qint32 raw)
    {
        if (m_initial)
            return;
        m_initial = raw;
        setRawValue(raw);
    }
    std::optional<qint32> initialValue() const { return m_initial; }

    // The raw value to write, or nothing with the reason it cannot be written.
    std::optional<qint32> rawValue(QString *problem = nullptr) const
    {
        const std::optional<qint32> raw = editedValue(problem);
        if (!raw || raw == m_initial || m_format.isWithinLimits(*raw))
            return raw;
        if (problem)
            *problem = m_format.limitsProblem(*raw);
        return std::nullopt;
    }

protected:
    virtual void setRawValue(qint32 raw) = 0;
    // What the editor holds, limits not yet checked; nothing with the reason otherwise.
    virtual std::optional<qint32> editedValue(QString *problem) const = 0;

private:
    ParameterFormat m_format;
    std::optional<qint32> m_initial;
};

} // namespace DriveDesk
