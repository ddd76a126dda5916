#pragma once

#include "parameters/DisplayScaling.h"

#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// What one of the four scope channels carries: the parameter the drive delivers on it (where
// known) and how its raw integers are shown. A channel whose source is unknown is shown raw.
struct ScopeChannel
{
    // The parameter's bus address, or nothing where the drive did not say (no assignment
    // parameters) or the channel is off.
    std::optional<quint16> source;
    quint8 setMask = 1;  // the set(s) the drive reads the source from
    bool enabled = true; // false: the drive delivers nothing on it (assignment -1)
    QString id;          // "ru.03"; empty for an unknown source
    QString name;        // the parameter's name; empty for an unknown source
    DisplayScaling scaling; // identity for an unknown source

    // "ru.03 Actual frequency", "op.11 Maximum speed forward (set 2)" for a set other than 0,
    // or "Channel 2" for an unknown source (index counts from 0).
    QString title(int index) const;
    QString unit() const { return scaling.unitSymbol(); }
    // The display number of a raw value; the raw value itself where the scaling cannot.
    double toDisplay(qint32 raw) const
    {
        const std::optional<double> value = scaling.toDisplay(raw);
        return value ? *value : double(raw);
    }
    bool operator==(const ScopeChannel &other) const;
};

using ScopeChannels = QList<ScopeChannel>; // always ScopeSample::kChannelCount entries

} // namespace DriveDesk
