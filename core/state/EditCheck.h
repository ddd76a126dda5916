#pragma once

#include "ParameterState.h"

#include "parameters/PasswordLevel.h"

#include <QCoreApplication>
#include <QString>

namespace DriveDesk {

// The one rule for whether a value may be written, to a drive or into a parameter file, for the
// window and the command line alike. Each refusal is a sentence that names the parameter by its
// id ("ru.03 is read-only"), so any caller can show it as it is.
class EditCheck
{
    Q_DECLARE_TR_FUNCTIONS(EditCheck)
public:
    // Why the parameter cannot be changed at all: read-only, or it needs a higher password
    // level than the one in force. Empty when it can.
    static QString refusal(const ParameterState &parameter, PasswordLevel level);
    // Why `raw` cannot be written: the refusal above, or a value outside the parameter's
    // limits. Empty when it can.
    static QString valueRefusal(const ParameterState &parameter, qint32 raw, PasswordLevel level);
    // Why `raw` cannot go into the sets of the mask: valueRefusal(), or no set chosen. Empty
    // when it can.
    static QString writeRefusal(const ParameterState &parameter, quint8 setMask, qint32 raw,
                                PasswordLevel level);
    // The parameter needs a higher level to be read, or (unless read-only) to be written.
    static bool isAboveLevel(const ParameterProperties &properties, PasswordLevel level);
};

} // namespace DriveDesk
