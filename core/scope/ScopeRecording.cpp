#include "ScopeRecording.h"

namespace DriveDesk {

ScopeRecording::ScopeRecording()
    : channels(ScopeSample::kChannelCount)
{
}

qint64 ScopeRecording::firstTime() const
{
    return buffer.count() == 0 ? 0 : buffer.samples().time(0);
}

qint64 ScopeRecording::lastTime() const
{
    return buffer.count() == 0 ? 0 : buffer.samples().time(buffer.count() - 1);
}

} // namespace DriveDesk
