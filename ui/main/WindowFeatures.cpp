#include "WindowFeatures.h"

#include "compare/CompareFeature.h"
#include "edit/AccessFeature.h"
#include "edit/EditingFeature.h"
#include "edit/PollingFeature.h"
#include "monitor/MonitorFeature.h"
#include "scope/ScopeFeature.h"
#include "transfer/DownloadFeature.h"
#include "transfer/ExportFeature.h"

namespace DriveDesk {

QList<WindowFeature *> makeWindowFeatures(WindowFrame &frame)
{
    auto *download = new DownloadFeature(frame);
    auto *compare = new CompareFeature(frame);
    // Values chosen in the compare view reach the drive through the download's checks, its last
    // look and its report.
    QObject::connect(compare, &CompareFeature::writeToDriveRequested, download,
                     [download](const DriveDescription &selection) {
                         download->downloadSelection(selection);
                     });
    return {
        new PollingFeature(frame),
        new EditingFeature(frame),
        new AccessFeature(frame),
        new MonitorFeature(frame),
        new ScopeFeature(frame),
        download,
        compare,
        new ExportFeature(frame),
    };
}

} // namespace DriveDesk
