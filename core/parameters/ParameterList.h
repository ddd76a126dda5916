#pragma once

#include "DriveDescription.h"
#include "ParameterAccess.h"
#include "ParameterProperties.h"

#include <QCoreApplication>
#include <QString>

namespace DriveDesk {

// What a parameter list upload (drive to file) and download (file to drive) do with a
// parameter: properties 2 bits 12, 13, 14 and 17 (seed 002 2.6.2). One rule for the command
// line, the window and every job.
class ParameterList
{
    Q_DECLARE_TR_FUNCTIONS(ParameterList)
public:
    // Part of a parameter list at all: not "excluded from the complete list" (bit 14).
    static bool holds(const ParameterDescription &parameter)
    {
        return !properties(parameter).isExcludedFromCompleteList();
    }

    // An upload reads its value: in the list and not "write only" (bit 13). A write-only
    // parameter goes into the file with its default, to be set offline.
    static bool isReadByUpload(const ParameterDescription &parameter)
    {
        return holds(parameter) && !properties(parameter).isWriteOnly();
    }

    // A download may write it: in the list, writable over the bus, not "read only for
    // up/download lists" (bit 17) and not a value the drive changes by itself.
    static bool isWrittenByDownload(const ParameterDescription &parameter)
    {
        const ParameterProperties p = properties(parameter);
        return holds(parameter) && !p.isReadOnly() && !p.isReadOnlyForTransferLists()
            && !readBackMayDiffer(parameter);
    }

    // A download writes it whatever the drive holds: "write always" (bit 12), and "write only"
    // (bit 13), whose value on the drive is never read to compare with.
    static bool isAlwaysWritten(const ParameterDescription &parameter)
    {
        const ParameterProperties p = properties(parameter);
        return isWrittenByDownload(parameter) && (p.isWriteAlways() || p.isWriteOnly());
    }

    // Why a download leaves a parameter alone, in words; empty when it may write it.
    static QString whyNotWritten(const ParameterDescription &parameter);

    // What an upload keeps of a scanned drive: every parameter the list holds, with the values
    // read, and each write-only parameter with its default in every set.
    static DriveDescription fromScan(const DriveDescription &scanned);

private:
    static ParameterProperties properties(const ParameterDescription &parameter)
    {
        return ParameterProperties(parameter.properties1, parameter.properties2);
    }
};

} // namespace DriveDesk
