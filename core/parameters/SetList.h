#pragma once

#include <QCoreApplication>
#include <QString>

namespace DriveDesk {

struct ParameterDescription;

// How the parameter sets a set mask (service 0: bit 0 = set 0 ... bit 7 = set 7) selects read:
// "set 0", "sets 0, 2, 5", "all sets"; and the two sets of standard set addressing (service 1).
class SetList
{
    Q_DECLARE_TR_FUNCTIONS(SetList)
public:
    static QString text(quint8 mask);
    // Service 1: 0 = the active set, 1 = the set the set pointer (Fr.09) chooses.
    static QString standardSetText(quint8 set);

    // The sets a write or reset to `mask` reaches. A parameter that is not set-programmable
    // holds one value, written as set 0 (mask 01h) whatever sets were chosen; mask 0 (the active
    // set, service 1) stays as it is. Every path that writes a value asks here.
    static quint8 setsWritten(bool setProgrammable, quint8 mask);
    static quint8 setsWritten(const ParameterDescription &parameter, quint8 mask);
};

} // namespace DriveDesk
