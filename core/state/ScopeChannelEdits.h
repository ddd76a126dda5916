#pragma once

#include "session/ScopeChannelsJob.h"

#include <functional>

namespace DriveDesk {

class ValueEdits;

// Puts the sources chosen on the scope channels through the drive's edit path (ValueEdits:
// ordered with the other edits of those parameters, journaled, shown in its DriveState), then
// reads every channel's assignment back (ScopeChannelsJob), so that a recording shows what the
// drive delivers. A choice planScopeChannels() refuses ends at once, nothing sent
// (refusedChoice). `done` runs once in the thread of `edits`; nothing runs once `edits` is gone.
void assignScopeChannels(ValueEdits &edits, const DriveDescription &drive,
                         const ScopeAssignment &choices,
                         std::function<void(const ScopeChannelsOutcome &)> done);

} // namespace DriveDesk
