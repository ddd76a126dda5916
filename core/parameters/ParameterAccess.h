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

} // namespace DriveDesk
