#pragma once

#include "parameters/DriveDescription.h"
#include "parameters/PasswordLevel.h"

#include <QList>

namespace DriveDesk {

// What copying one parameter set to another writes, worked out from the values known.
struct CopySetPlan
{
    struct Item
    {
        quint16 address = 0;
        qint32 raw = 0; // the source set's value
    };

    int from = 0;
    int to = 0;
    QList<Item> items; // the set-programmable values that differ, in the drive's order
    int locked = 0;    // differ, but read-only or above the password level in force
    int unknown = 0;   // the source set's value was never read
};

CopySetPlan planCopySet(const DriveDescription &drive, int from, int to, PasswordLevel level);

} // namespace DriveDesk
