#include "WindowFeatures.h"

#include "edit/AccessFeature.h"
#include "edit/EditingFeature.h"
#include "edit/PollingFeature.h"
#include "monitor/MonitorFeature.h"
#include "transfer/DownloadFeature.h"

namespace DriveDesk {

QList<WindowFeature *> makeWindowFeatures(WindowFrame &frame)
{
    return {
        new PollingFeature(frame),
        new EditingFeature(frame),
        new AccessFeature(frame),
        new MonitorFeature(frame),
        new DownloadFeature(frame),
    };
}

} // namespace DriveDesk
