#include "WindowFeatures.h"

#include "compare/CompareFeature.h"
#include "edit/AccessFeature.h"
#include "edit/EditingFeature.h"
#include "edit/PollingFeature.h"
#include "edit/SetsFeature.h"
#include "files/ParameterFileFeature.h"
#include "journal/JournalFeature.h"
#include "monitor/MonitorFeature.h"
#include "plant/PlantDock.h"
#include "plant/PlantFeature.h"
#include "scope/ScopeDock.h"
#include "scope/ScopeFeature.h"
#include "transfer/DownloadFeature.h"
#include "transfer/ExportFeature.h"
#include "transfer/SaveDriveFeature.h"

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
    // The others add their actions and status fields in this order.
    QList<WindowFeature *> features{
        new ParameterFileFeature(frame), // first: the File menu and the toolbar begin with it
        new SaveDriveFeature(frame),
        new SetsFeature(frame),
        new PollingFeature(frame),
    };
    auto *editing = new EditingFeature(frame);
    auto *access = new AccessFeature(frame);
    // A higher password level reads at once what it opened, not at the next refresh.
    QObject::connect(access, &AccessFeature::levelRaised, editing,
                     &EditingFeature::readOpenedValues);
    features << editing << access;
    // The download journals its writes as the edits do, by the one setting.
    download->setJournaled([editing] { return editing->journalsWrites(); });
    auto *monitor = new MonitorFeature(frame);
    auto *scope = new ScopeFeature(frame);
    features << QList<WindowFeature *>{
        monitor,
        scope,
        download,
        compare,
        new ExportFeature(frame),
    };
    auto *plant = new PlantFeature(frame);
    // Two drives of the plant, each read into a file, side by side in the compare window.
    QObject::connect(plant, &PlantFeature::compareRequested, compare,
                     [compare](const QString &fileA, const QString &nameA,
                               const QString &fileB, const QString &nameB) {
                         CompareWindow *window = compare->showCompareWindow();
                         window->setReading(true, fileA, nameA);
                         window->setReading(false, fileB, nameB);
                         window->compare();
                     });
    plant->dock()->setJournaled([editing] { return editing->journalsWrites(); });
    // A plant's scope presets are kept beside its file, and listed first.
    scope->dock()->setPlantFile(plant->dock()->plantPath());
    QObject::connect(plant->dock(), &PlantDock::plantOpened, scope->dock(),
                     &ScopeDock::setPlantFile);
    features << plant;
    auto *journal = new JournalFeature(frame);
    // Journal entries reverted reach the drive as the compare window's chosen values do.
    QObject::connect(journal, &JournalFeature::revertRequested, download,
                     [download](const DriveDescription &selection, const QString &what,
                                const QString &job) {
                         download->downloadSelection(selection, what, job);
                     });
    features << journal;
    return features;
}

} // namespace DriveDesk
