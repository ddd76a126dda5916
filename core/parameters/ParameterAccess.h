#pragma once

#include "parameters/DriveDescription.h"
#include "parameters/ParameterProperties.h"

namespace DriveDesk {

// What the password level in force lets a user do with a parameter (properties 1, bits 0-5;
// properties 2, bit 3): one rule for the window, the command line and every job.
inline bool isReadable(const ParameterProperties &properties, PasswordLevel level)
{
    return properties.readLevel() <= level;
}

inline bool isWritable(const ParameterProperties &properties, PasswordLevel level)
{
    return !properties.isReadOnly() && isReadable(properties, level)
        && properties.writeLevel() <= level;
}

inline bool isReadable(const ParameterDescription &parameter, PasswordLevel level)
{
    return isReadable(ParameterProperties(parameter.properties1, parameter.properties2), level);
}

inline bool isWritable(const ParameterDescription &parameter, PasswordLevel level)
{
    return isWritable(ParameterProperties(parameter.properties1, parameter.properties2), level);
}

// The drive may hold something other than what was written, by the parameter's nature: the
// password parameter (written a password, it reads the level it opened) and every parameter
// whose properties say the inverter changes its value (properties 2, bit 9). Such a write is
// not judged by comparing its read-back, and is no step that can be undone.
inline bool readBackMayDiffer(const ParameterDescription &parameter)
{
    return parameter.address == kPasswordParameterAddress
        || ParameterProperties(parameter.properties1, parameter.properties2)
               .isChangedByInverter();
}

// A value the user sets: writable over the bus at some level and not one the drive changes by
// itself (live values, counters, the password parameter). Only these count as "differs from
// default".
inline bool isUserSetting(const ParameterDescription &parameter)
{
    return !ParameterProperties(parameter.properties1, parameter.properties2).isReadOnly()
        && !readBackMayDiffer(parameter);
}

} // namespace DriveDesk
