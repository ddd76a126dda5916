#include "WindowFeatures.h"

#include "compare/CompareFeature.h"
#include "edit/AccessFeature.h"
#include "edit/EditingFeature.h"
#include "edit/PollingFeature.h"
#include "monitor/MonitorFeature.h"
#include "plant/PlantFeature.h"
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
    QList<WindowFeature *> features{
        new PollingFeature(frame),
        new EditingFeature(frame),
        new AccessFeature(frame),
        new MonitorFeature(frame),
        new ScopeFeature(frame),
        download,
        compare,
        new ExportFeature(frame),
    };
    auto *plant = new PlantFeature(frame);
    // Two drives of the plant, each read into a file, side by side in the compare window.
    QObject::connect(plant, &PlantFeature::compareRequested, compare,
                     [compare](const QString &fileA, const QString &fileB) {
                         CompareWindow *window = compare->showCompareWindow();
                         window->setSide(true, CompareWindow::Source::File, fileA);
                         window->setSide(false, CompareWindow::Source::File, fileB);
                         window->compare();
                     });
    features << plant;
    return features;
}

} // namespace DriveDesk
