#pragma once

#include "frame/WindowFeature.h"

#include <QStringList>

class QMenu;

namespace DriveDesk {

class PlantDock;

// Plants in the window: File > New Plant, Open Plant and Open Recent Plant (the plant files
// used lately, in QSettings "plants/recent"), and the plant view (PlantDock) they show, with
// View > Plant View and View > Plant History (the dock's History). The plant shown when the
// window closed shows again when it opens.
class PlantFeature : public WindowFeature
{
    Q_OBJECT
public:
    static constexpr int kMaximumRecent = 10;

    explicit PlantFeature(WindowFrame &frame, QObject *parent = nullptr);

    PlantDock *dock() const { return m_dock; }
    // Shows the plant file at `path`; a file that cannot be read is named, with the place, line
    // and column, in a message box (opened without waiting), and nothing changes.
    bool openPlant(const QString &path);
    // Asks for the machine's name and a first link, then where to save the new plant file.
    void newPlant();
    static QStringList recentPlants();

    void saveSettings() override;

signals:
    // Two drives of the plant, each read into a parameter file, to be compared side by side.
    void compareRequested(const QString &fileA, const QString &nameA, const QString &fileB,
                          const QString &nameB);

private:
    void remember(const QString &path);
    void fillRecentMenu();

    PlantDock *m_dock = nullptr;
    QMenu *m_recentMenu = nullptr;
};

} // namespace DriveDesk
