#include "ParameterList.h"

namespace DriveDesk {

QString ParameterList::whyNotWritten(const ParameterDescription &parameter)
{
    const ParameterProperties p = properties(parameter);
    if (!holds(parameter))
        return tr("not part of a parameter list");
    if (p.isReadOnly())
        return tr("read-only");
    if (p.isReadOnlyForTransferLists())
        return tr("read-only for parameter lists");
    if (readBackMayDiffer(parameter))
        return tr("the drive sets this value itself");
    return {};
}

DriveDescription ParameterList::fromScan(const DriveDescription &scanned)
{
    DriveDescription list = scanned;
    for (GroupDescription &group : list.groups) {
        group.parameters.removeIf(
            [](const ParameterDescription &parameter) { return !holds(parameter); });
        for (ParameterDescription &parameter : group.parameters) {
            if (isReadByUpload(parameter))
                continue;
            parameter.values = parameter.defaultValues();
            parameter.error.clear();
        }
    }
    return list;
}

} // namespace DriveDesk
