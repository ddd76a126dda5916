#pragma once

#include "session/ValueChange.h"

#include <QList>

#include <array>
#include <optional>

namespace DriveDesk {

// One edit of one parameter: what was sent and what became of it.
struct EditOutcome : WriteOutcome
{
    bool reset = false; // reset to the default (service 32), not a value written
    // As sent: the sets after SetList::setsWritten(), a reset's value the parameter's default.
    QList<WriteStep> steps;
    // The values held when the edit began, per set ([0] alone without sets), for undo; known
    // only where ValueEdits keeps a DriveState that holds the parameter.
    std::array<std::optional<qint32>, kParameterSets> before {};
    // Sets read back holding something else than was written (bit 0 also for the active set).
    // Never set for a parameter whose read-back may differ by its nature (readBackMayDiffer).
    quint8 differingMask = 0;
    // A later edit of the same parameter was waiting: it writes and reads these sets again, so
    // this outcome's refusals are no longer the cells' to show.
    bool superseded = false;

    // The sets the steps wrote (0: the active set alone).
    quint8 askedMask() const;
    // The value written to `set` (for a step with mask 0, to [0]: the active set).
    std::optional<qint32> asked(int set) const;
    // Written everywhere asked, read back, and the drive holds what was written.
    bool complete() const { return ok() && readBackError.isEmpty() && differingMask == 0; }
};

} // namespace DriveDesk
