#pragma once

#include "client/RequestJob.h"
#include "parameters/DriveDescription.h"
#include "parameters/PasswordLevel.h"
#include "session/WriteChangesJob.h"

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

// Writes a plan's items to the target set, each read back; result i is the outcome of
// items[i] (WriteChangesJob: requestStop() and a lost connection leave every item without a
// result unwritten).
class CopySetJob : public WriteChangesJob
{
public:
    CopySetJob(Protocol protocol, const CopySetPlan &plan);
};

} // namespace DriveDesk
