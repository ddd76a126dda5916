#include "ScopeSnapshot.h"

#include "ScopeRecording.h"

namespace DriveDesk {

ScopeSnapshot scopeSnapshot(const ScopeRecording &recording, qsizetype count)
{
    ScopeSnapshot snapshot;
    snapshot.samples = recording.buffer.samples().share(count);
    snapshot.channels = recording.channels;
    snapshot.originMs = recording.firstTime();
    return snapshot;
}

} // namespace DriveDesk
