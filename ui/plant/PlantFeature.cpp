#include "PlantFeature.h"

#include "PlantDock.h"
#include "PlantLinkDialog.h"

#include "frame/FrameSupport.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

namespace DriveDesk {

namespace {

const QString kRecentKey = QStringLiteral("plants/recent");
const QString kShownKey = QStringLiteral("plants/shown");

QString plantFilter()
{
    return PlantFeature::tr("Plant files (*.json);;All files (*)");
}

} // namespace

PlantFeature::PlantFeature(WindowFrame &frame, QObject *parent)
    : WindowFeature(frame, parent)
{
    m_dock = new PlantDock(frame, frame.frameWidget());
    frame.addDock(m_dock);
    connect(m_dock, &PlantDock::plantOpened, this, &PlantFeature::remember);
    connect(m_dock, &PlantDock::compareRequested, this, &PlantFeature::compareRequested);

    auto *newAction = new QAction(tr("&New Plant..."), this);
    newAction->setObjectName(QStringLiteral("newPlantAction"));
    newAction->setToolTip(tr("Name a machine and its first link, and save it as a plant file"));
    connect(newAction, &QAction::triggered, this, &PlantFeature::newPlant);
    auto *openAction = new QAction(tr("Open &Plant..."), this);
    openAction->setObjectName(QStringLiteral("openPlantAction"));
    openAction->setToolTip(tr("Show a plant file's links and drives in the plant view"));
    connect(openAction, &QAction::triggered, this, [this] {
        this->frame().chooseFileToRead(tr("Open Plant"), plantFilter(),
                                       [this](const QString &path) { openPlant(path); });
    });
    QMenu *file = frame.menu(WindowFrame::Menu::File);
    file->addSeparator();
    file->addAction(newAction);
    file->addAction(openAction);
    m_recentMenu = file->addMenu(tr("Open &Recent Plant"));
    m_recentMenu->setObjectName(QStringLiteral("recentPlantsMenu"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &PlantFeature::fillRecentMenu);
    fillRecentMenu();

    QAction *view = m_dock->toggleViewAction();
    view->setObjectName(QStringLiteral("plantViewAction"));
    view->setText(tr("Pla&nt View"));
    frame.menu(WindowFrame::Menu::View)->addAction(view);
    // The dock's History, with a shortcut and a mnemonic of the menu's own: the dock's toolbar
    // buttons carry none (the window's Alt+letters are taken).
    auto *history = new QAction(tr("Plant Hist&ory..."), this);
    history->setObjectName(QStringLiteral("plantHistoryMenuAction"));
    history->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_H));
    history->setToolTip(m_dock->historyAction()->toolTip());
    history->setEnabled(m_dock->historyAction()->isEnabled());
    connect(m_dock->historyAction(), &QAction::enabledChanged, history, &QAction::setEnabled);
    connect(history, &QAction::triggered, m_dock, &PlantDock::showHistory);
    frame.menu(WindowFrame::Menu::View)->addAction(history);

    const QString shown = QSettings().value(kShownKey).toString();
    QString ignored;
    if (!shown.isEmpty() && !m_dock->openPlant(shown, &ignored))
        QSettings().remove(kShownKey); // moved or changed elsewhere: not shown again
}

bool PlantFeature::openPlant(const QString &path)
{
    QString error;
    if (m_dock->openPlant(path, &error))
        return true;
    auto *box = new QMessageBox(QMessageBox::Warning, tr("Open Plant"),
                                tr("Could not open the plant: %1").arg(error), QMessageBox::Ok,
                                frame().frameWidget());
    box->setObjectName(QStringLiteral("plantProblemBox"));
    openDialog(box);
    return false;
}

void PlantFeature::newPlant()
{
    Plant start;
    start.name = tr("Machine");
    auto *dialog = new PlantLinkDialog(start, true, frame().frameWidget());
    connect(dialog, &PlantLinkDialog::accepted, this, [this, dialog] {
        const Plant plant = dialog->plant();
        frame().chooseFileToWrite(tr("Save New Plant"), plant.name + QStringLiteral(".json"),
                                  plantFilter(), [this, plant](const QString &path) {
                                      QString error;
                                      if (m_dock->showNewPlant(plant, path, &error))
                                          return true;
                                      frame().showMessage(error);
                                      return false;
                                  });
    });
    openDialog(dialog);
}

QStringList PlantFeature::recentPlants()
{
    return QSettings().value(kRecentKey).toStringList();
}

void PlantFeature::remember(const QString &path)
{
    QStringList list = recentPlants();
    list.removeAll(path);
    list.prepend(path);
    while (list.size() > kMaximumRecent)
        list.removeLast();
    QSettings().setValue(kRecentKey, list);
    fillRecentMenu();
}

void PlantFeature::fillRecentMenu()
{
    m_recentMenu->clear();
    const QStringList list = recentPlants();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString path = list.at(i);
        // "&1 line3.json": the number is the menu's mnemonic.
        const QString number = i < 9 ? QStringLiteral("&%1").arg(i + 1) : QStringLiteral("1&0");
        QAction *action = m_recentMenu->addAction(
            QStringLiteral("%1 %2").arg(number, QFileInfo(path).fileName()));
        action->setToolTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { openPlant(path); });
    }
    m_recentMenu->setEnabled(!list.isEmpty());
}

void PlantFeature::saveSettings()
{
    QSettings settings;
    if (m_dock->plantPath().isEmpty())
        settings.remove(kShownKey);
    else
        settings.setValue(kShownKey, m_dock->plantPath());
}

} // namespace DriveDesk
