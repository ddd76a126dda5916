#pragma once

#include <QCoreApplication>
#include <QString>

namespace DriveDesk {

// How the parameter sets a set mask (service 0: bit 0 = set 0 ... bit 7 = set 7) selects read:
// "set 0", "sets 0, 2, 5", "all sets"; and the two sets of standard set addressing (service 1).
class SetList
{
    Q_DECLARE_TR_FUNCTIONS(SetList)
public:
    static QString text(quint8 mask);
    // Service 1: 0 = the active set, 1 = the set the set pointer (Fr.09) chooses.
    static QString standardSetText(quint8 set);
};

} // namespace DriveDesk
