#include "PlantDock.h"

#include "PlantHistoryWindow.h"
#include "PlantLinkDialog.h"
#include "PlantModel.h"
#include "PlantReportDialog.h"

#include "frame/FrameSupport.h"
#include "frame/WindowFeature.h"

#include <QAction>
#include <QApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QSettings>
#include <QStyledItemDelegate>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>

namespace DriveDesk {

namespace {

const QString kFoldersGroup = QStringLiteral("plants/backupFolders");

// The progress column: a bar with what the job does, while a job works on the row.
class ProgressDelegate : public QStyledItemDelegate
{
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override
    {
        const QVariant percent = index.data(PlantModel::ProgressRole);
        if (!percent.isValid() || percent.toInt() < 0)
            return QStyledItemDelegate::paint(painter, option, index);
        QStyleOptionProgressBar bar;
        bar.rect = option.rect.adjusted(1, 1, -1, -1);
        bar.minimum = 0;
        bar.maximum = 100;
        bar.progress = percent.toInt();
        bar.text = QStringLiteral("%1% %2").arg(percent.toInt()).arg(index.data().toString());
        bar.textVisible = true;
        bar.state = option.state | QStyle::State_Horizontal;
        const QWidget *widget = option.widget;
        QStyle *style = widget ? widget->style() : QApplication::style();
        style->drawControl(QStyle::CE_ProgressBar, &bar, painter, widget);
    }
};

QString folderKey(const QString &plantPath)
{
    return kFoldersGroup + QLatin1Char('/')
        + QString::fromLatin1(
               QCryptographicHash::hash(QFileInfo(plantPath).absoluteFilePath().toUtf8(),
                                        QCryptographicHash::Sha1)
                   .toHex()
                   .left(16));
}

} // namespace

PlantDock::PlantDock(WindowFrame &frame, QWidget *parent)
    : QDockWidget(tr("Plant"), parent)
    , m_frame(frame)
{
    setObjectName(QStringLiteral("plantDock"));
    m_state = new PlantState(this);
    m_model = new PlantModel(m_state, this);
    auto *content = new QWidget;
    auto *layout = new QVBoxLayout(content);
    layout->setContentsMargins(2, 2, 2, 2);
    m_title = new QLabel(tr("No plant open. File > New Plant or Open Plant."));
    m_title->setObjectName(QStringLiteral("plantTitle"));
    m_title->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_toolBar = new QToolBar;
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_view = new QTreeView;
    m_view->setObjectName(QStringLiteral("plantView"));
    m_view->setModel(m_model);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setItemDelegateForColumn(PlantModel::ProgressColumn, new ProgressDelegate(m_view));
    m_view->header()->setStretchLastSection(true);
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("plantStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_title);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_status);
    setWidget(content);
    createActions();

    connect(m_view, &QTreeView::doubleClicked, this, &PlantDock::openDrive);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &PlantDock::updateActions);
    // A drive found by a search appears under its link: its longer name must fit at once.
    connect(m_model, &QAbstractItemModel::rowsInserted, this, [this](const QModelIndex &parent) {
        m_view->expand(parent);
        m_view->resizeColumnToContents(PlantModel::NameColumn);
    });
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        m_view->expandAll();
        fitColumns();
    });
    updateActions();
}

PlantDock::~PlantDock()
{
    if (m_run) {
        m_run->disconnect(this);
        m_run->stop();
    }
}

void PlantDock::createActions()
{
    const auto add
        = [this](const QString &text, const QString &name, const QString &tip, const QIcon &icon) {
              auto *action = new QAction(icon, text, this);
              action->setObjectName(name);
              action->setToolTip(tip);
              m_toolBar->addAction(action);
              return action;
          };
    m_findAction = add(tr("Find"), QStringLiteral("plantFindAction"),
                       tr("Search every link for its drives and write the addresses found into "
                          "the plant file"),
                       themedIcon("edit-find", QStyle::SP_FileDialogContentsView));
    m_backupAction = add(tr("Back Up All"), QStringLiteral("plantBackupAction"),
                         tr("Read every drive whole and save it to its file in the backup folder"),
                         themedIcon("document-save-all", QStyle::SP_DialogSaveButton));
    createCommitAction();
    m_verifyAction = add(tr("Verify All"), QStringLiteral("plantVerifyAction"),
                         tr("Check every drive's settings against its file in the backup folder"),
                         themedIcon("dialog-ok", QStyle::SP_DialogApplyButton));
    m_downloadAction = add(tr("Download All..."), QStringLiteral("plantDownloadAction"),
                           tr("Write each drive's file to the drive, after a last look at what "
                              "each would get"),
                           themedIcon("document-send", QStyle::SP_ArrowUp));
    m_stopAction = add(tr("Stop"), QStringLiteral("plantStopAction"),
                       tr("Stop every link after the value on its way"),
                       themedIcon("process-stop", QStyle::SP_BrowserStop));
    m_toolBar->addSeparator();
    m_compareAction
        = add(tr("Compare"), QStringLiteral("plantCompareAction"),
              tr("Read the two selected drives afresh and compare them side by side"), QIcon());
    m_historyAction = add(tr("History..."), QStringLiteral("plantHistoryAction"),
                          tr("The backup folder's revisions: what changed when, two side by "
                             "side, and a revision restored"),
                          themedIcon("document-open-recent", QStyle::SP_FileDialogDetailedView));
    m_addLinkAction = add(tr("Add Link..."), QStringLiteral("plantAddLinkAction"),
                          tr("Add a link to the plant file"), QIcon());
    m_folderAction = add(tr("Backup Folder..."), QStringLiteral("plantFolderAction"),
                         tr("Choose where the drives' files are"), QIcon());

    connect(m_findAction, &QAction::triggered, this,
            [this] { startJob(Job::Find, m_state->plant(), {}); });
    connect(m_backupAction, &QAction::triggered, this, [this] {
        if (!QDir().mkpath(backupFolder()))
            return showMessage(
                tr("Cannot make the folder %1.").arg(QDir::toNativeSeparators(backupFolder())));
        startJob(Job::Backup, m_state->plant(), backupFolder());
    });
    connect(m_verifyAction, &QAction::triggered, this, [this] {
        if (!QDir(backupFolder()).exists())
            return showMessage(tr("The backup folder %1 does not exist: back the drives up "
                                  "first, or choose another folder.")
                                   .arg(QDir::toNativeSeparators(backupFolder())));
        startJob(Job::Verify, m_state->plant(), backupFolder());
    });
    connect(m_downloadAction, &QAction::triggered, this, [this] {
        if (!QDir(backupFolder()).exists())
            return showMessage(tr("The backup folder %1 does not exist.")
                                   .arg(QDir::toNativeSeparators(backupFolder())));
        m_revisionFiles.reset();
        m_revision.clear();
        startJob(Job::DownloadLook, m_state->plant(), backupFolder());
    });
    connect(m_stopAction, &QAction::triggered, this, [this] {
        if (m_run)
            m_run->stop();
    });
    connect(m_compareAction, &QAction::triggered, this, &PlantDock::compareSelected);
    connect(m_historyAction, &QAction::triggered, this, &PlantDock::showHistory);
    connect(m_addLinkAction, &QAction::triggered, this, &PlantDock::addLink);
    connect(m_folderAction, &QAction::triggered, this, &PlantDock::chooseBackupFolder);
}

bool PlantDock::openPlant(const QString &path, QString *error)
{
    if (m_run) {
        *error = tr("A job is running on the plant shown; stop it first.");
        return false;
    }
    const std::optional<Plant> plant = PlantFile::load(path, error);
    if (!plant)
        return false;
    m_path = QFileInfo(path).absoluteFilePath();
    m_state->openPlant(*plant, backupFolder());
    showPlantTitle();
    m_status->clear();
    updateActions();
    if (m_history && m_history->isVisible())
        showHistory();
    show();
    raise();
    emit plantOpened(m_path);
    return true;
}

bool PlantDock::showNewPlant(const Plant &plant, const QString &path, QString *error)
{
    return PlantFile::save(path, plant, error) && openPlant(path, error);
}

QString PlantDock::backupFolder() const
{
    if (m_path.isEmpty())
        return {};
    const QString chosen = QSettings().value(folderKey(m_path)).toString();
    return chosen.isEmpty() ? QFileInfo(m_path).dir().filePath(QStringLiteral("backups")) : chosen;
}

void PlantDock::setBackupFolder(const QString &directory)
{
    if (m_path.isEmpty())
        return;
    QSettings().setValue(folderKey(m_path), QDir(directory).absolutePath());
    m_state->setBackupFolder(backupFolder());
    showPlantTitle();
    if (m_history && m_history->isVisible())
        showHistory();
}

void PlantDock::chooseBackupFolder()
{
    auto *dialog = new QFileDialog(this, tr("Backup Folder"), backupFolder());
    dialog->setFileMode(QFileDialog::Directory);
    dialog->setOption(QFileDialog::ShowDirsOnly);
    connect(dialog, &QFileDialog::fileSelected, this, &PlantDock::setBackupFolder);
    openDialog(dialog);
}

void PlantDock::addLink()
{
    auto *dialog = new PlantLinkDialog(m_state->plant(), false, this);
    connect(dialog, &PlantLinkDialog::accepted, this, [this, dialog] {
        QString error;
        const Plant plant = dialog->plant();
        if (!PlantFile::save(m_path, plant, &error))
            return showMessage(error);
        m_state->setPlant(plant);
        showMessage(tr("Link %1 added to %2.")
                        .arg(plant.links.constLast().name, QDir::toNativeSeparators(m_path)));
    });
    openDialog(dialog);
}

void PlantDock::showPlantTitle()
{
    m_title->setText(tr("<b>%1</b> &mdash; %2 &mdash; backups in %3")
                         .arg(m_state->plant().name.toHtmlEscaped(),
                              QDir::toNativeSeparators(m_path).toHtmlEscaped(),
                              QDir::toNativeSeparators(backupFolder()).toHtmlEscaped()));
    setWindowTitle(tr("Plant: %1").arg(m_state->plant().name));
}

QList<QModelIndex> PlantDock::selectedDrives() const
{
    QList<QModelIndex> drives;
    const QModelIndexList rows = m_view->selectionModel()->selectedRows();
    for (const QModelIndex &row : rows) {
        if (m_model->isDrive(row))
            drives << row;
    }
    return drives;
}

void PlantDock::openDrive(const QModelIndex &index)
{
    const QModelIndex drive = index.siblingAtColumn(0);
    const PlantLink *link = m_model->linkOf(drive);
    if (!m_model->isDrive(drive) || !link)
        return;
    const int address = drive.data(PlantModel::AddressRole).toInt();
    m_frame.connectTo(link->settings(std::max(address, 0)));
    showMessage(tr("%1 opens in the editor.").arg(drive.data().toString()));
}

void PlantDock::showHistory()
{
    if (m_path.isEmpty())
        return;
    if (!m_history) {
        m_history = new PlantHistoryWindow(this);
        connect(m_history, &PlantHistoryWindow::compareRequested, this,
                &PlantDock::compareRequested);
        connect(m_history, &PlantHistoryWindow::compareWithDriveRequested, this,
                &PlantDock::compareWithDrive);
        connect(m_history, &PlantHistoryWindow::restoreRequested, this,
                &PlantDock::restoreRevision);
    }
    m_history->setRestoreAllowed(m_run.isNull());
    QStringList drives;
    for (const QModelIndex &row : driveRows())
        drives << row.data().toString();
    m_history->showFolder(m_state->plant().name, backupFolder(), drives);
    m_history->show();
    m_history->raise();
    m_history->activateWindow();
}

PlantHistoryWindow *PlantDock::historyWindow() const
{
    return m_history;
}

QList<QModelIndex> PlantDock::driveRows() const
{
    QList<QModelIndex> rows;
    for (int link = 0; link < m_model->rowCount(); ++link) {
        const QModelIndex parent = m_model->index(link, PlantModel::NameColumn);
        for (int drive = 0; drive < m_model->rowCount(parent); ++drive)
            rows << m_model->index(drive, PlantModel::NameColumn, parent);
    }
    return rows;
}

void PlantDock::updateActions()
{
    const bool plant = !m_path.isEmpty() && !m_state->plant().links.isEmpty();
    const bool idle = m_run.isNull();
    m_findAction->setEnabled(plant && idle);
    m_backupAction->setEnabled(plant && idle && !m_committing);
    m_verifyAction->setEnabled(plant && idle);
    m_downloadAction->setEnabled(plant && idle);
    m_stopAction->setEnabled(!idle);
    m_compareAction->setEnabled(idle && selectedDrives().size() == 2);
    m_historyAction->setEnabled(!m_path.isEmpty());
    if (m_history)
        m_history->setRestoreAllowed(plant && idle);
    m_addLinkAction->setEnabled(!m_path.isEmpty() && idle);
    m_folderAction->setEnabled(!m_path.isEmpty() && idle);
}

void PlantDock::fitColumns()
{
    for (int column = 0; column < PlantModel::ProgressColumn; ++column)
        m_view->resizeColumnToContents(column);
    // A long result (a refusal in words) is shown elided, whole in its tooltip: at its full
    // width it would push the progress column out of sight.
    const int most = std::max(m_view->viewport()->width() / 3, 200);
    if (m_view->columnWidth(PlantModel::ResultColumn) > most)
        m_view->setColumnWidth(PlantModel::ResultColumn, most);
}

// Said once, below the plant's drives where the job was started: the window's status bar
// would repeat it beside.
void PlantDock::showMessage(const QString &text)
{
    m_status->setText(text);
}

} // namespace DriveDesk
