#include "PlantHistoryWindow.h"

#include "PlantHistoryReading.h"

#include <QtConcurrent/QtConcurrentRun>

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

const QString kSettingsGroup = QStringLiteral("plantHistory");
const QString kTimeFormat = QStringLiteral("yyyy-MM-dd HH:mm:ss"); // as `plant history` prints
enum Column { IdColumn, TimeColumn, AuthorColumn, MessageColumn, ChangesColumn };

} // namespace

PlantHistoryWindow::PlantHistoryWindow(QWidget *parent)
    : QWidget(parent, Qt::Window)
{
    setObjectName(QStringLiteral("plantHistoryWindow"));
    setWindowTitle(tr("Plant History - DriveDesk"));
    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("historyTitle"));
    m_title->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *filters = new QHBoxLayout;
    m_driveFilter = new QComboBox(this);
    m_driveFilter->setObjectName(QStringLiteral("historyDriveFilter"));
    m_driveFilter->setEditable(true);
    m_driveFilter->setInsertPolicy(QComboBox::NoInsert);
    m_driveFilter->lineEdit()->setPlaceholderText(tr("every drive"));
    m_driveFilter->setToolTip(tr("Only the revisions that changed this drive (cabinet-5)"));
    m_driveFilter->setMinimumContentsLength(14);
    auto *driveLabel = new QLabel(tr("&Drive:"), this);
    driveLabel->setBuddy(m_driveFilter);
    m_parameterFilter = new QLineEdit(this);
    m_parameterFilter->setObjectName(QStringLiteral("historyParameterFilter"));
    m_parameterFilter->setPlaceholderText(tr("every parameter"));
    m_parameterFilter->setToolTip(tr("Only the revisions that changed this parameter (op.28)"));
    m_parameterFilter->setClearButtonEnabled(true);
    auto *parameterLabel = new QLabel(tr("&Parameter:"), this);
    parameterLabel->setBuddy(m_parameterFilter);
    auto *refresh = new QPushButton(tr("Re&fresh"), this);
    refresh->setObjectName(QStringLiteral("historyRefresh"));
    refresh->setToolTip(tr("Read the backup folder's revisions again"));
    filters->addWidget(driveLabel);
    filters->addWidget(m_driveFilter);
    filters->addWidget(parameterLabel);
    filters->addWidget(m_parameterFilter);
    filters->addWidget(refresh);
    filters->addStretch(1);

    m_revisions = new QTreeWidget(this);
    m_revisions->setObjectName(QStringLiteral("historyRevisions"));
    m_revisions->setHeaderLabels({tr("Revision"), tr("Time"), tr("Author"), tr("Message"),
                                  tr("Changes")});
    m_revisions->setRootIsDecorated(false);
    m_revisions->setUniformRowHeights(true);
    m_revisions->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_revisions->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_revisions->header()->setStretchLastSection(false);
    m_revisions->header()->setSectionResizeMode(MessageColumn, QHeaderView::Stretch);
    m_changes = new QListWidget(this);
    m_changes->setObjectName(QStringLiteral("historyChanges"));
    m_changes->setToolTip(tr("What the revision selected changed against the one before"));
    m_splitter = new QSplitter(Qt::Vertical, this);
    m_splitter->addWidget(m_revisions);
    m_splitter->addWidget(m_changes);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);

    auto *actions = new QHBoxLayout;
    m_compareDrive = new QComboBox(this);
    m_compareDrive->setObjectName(QStringLiteral("historyCompareDrive"));
    m_compareDrive->setMinimumContentsLength(14);
    auto *compareLabel = new QLabel(tr("Drive to co&mpare:"), this);
    compareLabel->setBuddy(m_compareDrive);
    m_compareButton = new QPushButton(tr("&Side by Side"), this);
    m_compareButton->setObjectName(QStringLiteral("historyCompare"));
    m_compareButton->setToolTip(
        tr("The drive's file at the two revisions selected, or at the one selected and in the "
           "backup folder now, side by side in the compare window"));
    m_driveButton = new QPushButton(tr("Against the Dri&ve"), this);
    m_driveButton->setObjectName(QStringLiteral("historyAgainstDrive"));
    m_driveButton->setToolTip(tr("The drive's file at the revision selected against the drive "
                                 "itself, read afresh, side by side in the compare window"));
    m_restoreButton = new QPushButton(tr("&Restore to This Revision..."), this);
    m_restoreButton->setObjectName(QStringLiteral("historyRestore"));
    m_restoreButton->setToolTip(
        tr("Download the revision's files to the drives, after Download All's last look at "
           "what each would get"));
    actions->addWidget(compareLabel);
    actions->addWidget(m_compareDrive);
    actions->addWidget(m_compareButton);
    actions->addWidget(m_driveButton);
    actions->addStretch(1);
    actions->addWidget(m_restoreButton);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("historyMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addLayout(filters);
    layout->addWidget(m_splitter, 1);
    layout->addLayout(actions);
    layout->addWidget(m_message);

    connect(refresh, &QPushButton::clicked, this, &PlantHistoryWindow::refresh);
    connect(m_driveFilter, &QComboBox::activated, this, &PlantHistoryWindow::refresh);
    connect(m_driveFilter->lineEdit(), &QLineEdit::returnPressed, this,
            &PlantHistoryWindow::refresh);
    connect(m_parameterFilter, &QLineEdit::returnPressed, this, &PlantHistoryWindow::refresh);
    connect(m_revisions, &QTreeWidget::itemSelectionChanged, this, [this] {
        showChanges();
        updateButtons();
    });
    connect(m_compareButton, &QPushButton::clicked, this, &PlantHistoryWindow::compareSelected);
    connect(m_driveButton, &QPushButton::clicked, this, &PlantHistoryWindow::compareWithDrive);
    connect(m_restoreButton, &QPushButton::clicked, this, &PlantHistoryWindow::restoreSelected);
    connect(&m_reading, &QFutureWatcherBase::finished, this, &PlantHistoryWindow::onRead);
    connect(&m_extracting, &QFutureWatcherBase::finished, this, &PlantHistoryWindow::onExtracted);

    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    if (!restoreGeometry(settings.value(QStringLiteral("geometry")).toByteArray()))
        resize(900, 560);
    m_fitColumns = !m_revisions->header()->restoreState(
        settings.value(QStringLiteral("columns")).toByteArray());
    m_splitter->restoreState(settings.value(QStringLiteral("splitter")).toByteArray());
    updateButtons();
}

PlantHistoryWindow::~PlantHistoryWindow()
{
    // A reading under way ends on its own in the pool; its answer goes nowhere.
    m_reading.disconnect(this);
    m_extracting.disconnect(this);
}

void PlantHistoryWindow::showFolder(const QString &plantName, const QString &directory,
                                    const QStringList &drives)
{
    m_directory = directory;
    m_title->setText(tr("<b>%1</b> &mdash; revisions of the backups in %2")
                         .arg(plantName.toHtmlEscaped(),
                              QDir::toNativeSeparators(directory).toHtmlEscaped()));
    const QString filtered = m_driveFilter->currentText();
    const QString compared = m_compareDrive->currentText();
    m_driveFilter->clear();
    m_driveFilter->addItems(drives);
    m_driveFilter->setCurrentText(filtered);
    m_compareDrive->clear();
    m_compareDrive->addItems(drives);
    if (drives.contains(compared))
        m_compareDrive->setCurrentText(compared);
    refresh();
}

void PlantHistoryWindow::refresh()
{
    if (m_directory.isEmpty())
        return;
    if (m_readPending) {
        m_readAgain = true; // the filters changed while reading: read again once it is done
        return;
    }
    HistoryFilter filter;
    filter.drive = m_driveFilter->currentText().trimmed();
    filter.parameter = m_parameterFilter->text().trimmed();
    showMessage(tr("Reading the revisions..."));
    m_readPending = true;
    m_reading.setFuture(QtConcurrent::run(readHistory, m_directory, filter));
    updateButtons();
}

void PlantHistoryWindow::onRead()
{
    m_readPending = false;
    if (m_readAgain) {
        m_readAgain = false;
        return refresh();
    }
    showRevisions(m_reading.result());
    updateButtons();
}

void PlantHistoryWindow::showRevisions(const HistoryReading &reading)
{
    m_shown = reading.revisions;
    m_revisions->clear();
    m_changes->clear();
    for (const PlantRevision &revision : std::as_const(m_shown)) {
        qsizetype lines = 0;
        for (const DriveChange &change : revision.changes)
            lines += change.lines().size();
        auto *item = new QTreeWidgetItem(
            m_revisions, {PlantRevision::shortId(revision.id),
                          revision.time.toLocalTime().toString(kTimeFormat), revision.author,
                          revision.subject, QString::number(lines)});
        item->setData(IdColumn, Qt::UserRole, revision.id);
        item->setToolTip(AuthorColumn, revision.email);
        item->setToolTip(MessageColumn, revision.subject);
    }
    // Fitted to the first revisions shown, until the user sizes the columns (remembered).
    if (m_fitColumns && !m_shown.isEmpty()) {
        for (int column : {IdColumn, TimeColumn, AuthorColumn})
            m_revisions->resizeColumnToContents(column);
        m_fitColumns = false;
    }
    if (!reading.error.isEmpty())
        showMessage(tr("No history to show: %1").arg(reading.error));
    else if (!reading.hasCommits)
        showMessage(tr("%1 has no revisions yet: each backup committed with drivedesk-cli "
                       "plant backup --commit becomes one.")
                        .arg(QDir::toNativeSeparators(m_directory)));
    else if (m_shown.isEmpty())
        showMessage(tr("No revision changed the drive or parameter the filter names."));
    else
        showMessage(tr("Revisions: %1, newest first.").arg(m_shown.size()));
    if (!m_shown.isEmpty())
        m_revisions->setCurrentItem(m_revisions->topLevelItem(0));
}

void PlantHistoryWindow::showChanges()
{
    m_changes->clear();
    const QTreeWidgetItem *item = m_revisions->currentItem();
    const PlantRevision *shown = item ? revision(item->data(IdColumn, Qt::UserRole).toString())
                                      : nullptr;
    if (!shown)
        return;
    for (const DriveChange &change : shown->changes)
        m_changes->addItems(change.lines());
    // The drive compared follows the revision looked at, where it changed one.
    if (!shown->changes.isEmpty() && m_compareDrive->findText(shown->changes.first().drive) >= 0)
        m_compareDrive->setCurrentText(shown->changes.first().drive);
}

QStringList PlantHistoryWindow::selectedRevisions() const
{
    QStringList ids;
    for (int row = 0; row < m_revisions->topLevelItemCount(); ++row) {
        const QTreeWidgetItem *item = m_revisions->topLevelItem(row);
        if (item->isSelected())
            ids << item->data(IdColumn, Qt::UserRole).toString();
    }
    return ids;
}

void PlantHistoryWindow::compare(Purpose purpose)
{
    const QStringList ids = selectedRevisions();
    const QString drive = m_compareDrive->currentText();
    if (ids.isEmpty() || ids.size() > (purpose == Purpose::Compare ? 2 : 1) || drive.isEmpty())
        return showMessage(tr("Select one or two revisions and a drive to compare."));
    m_extractedDrive = drive;
    // The older as A: a change reads from A to B, as in the list of changes.
    extract({ids.constLast(), ids.constFirst()}, purpose);
}

void PlantHistoryWindow::restoreSelected()
{
    const QStringList ids = selectedRevisions();
    if (ids.size() != 1 || !m_restoreAllowed)
        return showMessage(tr("Select one revision to restore."));
    extract(ids, Purpose::Restore);
}

void PlantHistoryWindow::extract(const QStringList &revisions, Purpose purpose)
{
    if (m_extractPending)
        return;
    m_purpose = purpose;
    m_extractedIds = revisions;
    m_extractedIds.removeDuplicates();
    showMessage(tr("Reading the revision's files..."));
    m_extractPending = true;
    m_extracting.setFuture(QtConcurrent::run(extractRevisions, m_directory, m_extractedIds));
    updateButtons();
}

void PlantHistoryWindow::onExtracted()
{
    m_extractPending = false;
    const RevisionFolders extracted = m_extracting.result();
    updateButtons();
    if (!extracted.error.isEmpty())
        return showMessage(tr("The revision's files could not be read: %1").arg(extracted.error));
    if (m_purpose == Purpose::Restore) {
        const QString id = PlantRevision::shortId(m_extractedIds.constFirst());
        showMessage(tr("%1 goes to Download All: look at what each drive would get, then "
                       "write.").arg(id));
        emit restoreRequested(extracted.folders.constFirst(), id);
        return;
    }
    const QString file = m_extractedDrive + QStringLiteral(".json");
    QStringList paths;
    QStringList names;
    for (qsizetype i = 0; i < extracted.folders.size(); ++i) {
        paths << QDir(extracted.folders.at(i)->path()).filePath(file);
        names << revisionName(m_extractedIds.at(i));
    }
    if (paths.size() == 1 && m_purpose == Purpose::Compare) { // against the backup folder now
        paths << QDir(m_directory).filePath(file);
        names << tr("%1 in the backup folder now").arg(m_extractedDrive);
    }
    for (qsizetype i = 0; i < paths.size(); ++i) {
        if (!QFileInfo::exists(paths.at(i)))
            return showMessage(tr("%1 has no file there: %2").arg(m_extractedDrive, names.at(i)));
    }
    m_compared = extracted.folders;
    if (m_purpose == Purpose::CompareDrive) {
        showMessage(tr("Reading %1 to compare it with %2...").arg(m_extractedDrive, names.at(0)));
        return emit compareWithDriveRequested(paths.at(0), names.at(0), m_extractedDrive);
    }
    showMessage(tr("%1 and %2 side by side in the compare window.").arg(names.at(0), names.at(1)));
    emit compareRequested(paths.at(0), names.at(0), paths.at(1), names.at(1));
}

QString PlantHistoryWindow::revisionName(const QString &id) const
{
    const PlantRevision *shown = revision(id);
    return tr("%1 at %2 (%3)")
        .arg(m_extractedDrive, PlantRevision::shortId(id),
             shown ? shown->time.toLocalTime().toString(kTimeFormat) : QString());
}

const PlantRevision *PlantHistoryWindow::revision(const QString &id) const
{
    for (const PlantRevision &shown : m_shown) {
        if (shown.id == id)
            return &shown;
    }
    return nullptr;
}

void PlantHistoryWindow::setRestoreAllowed(bool allowed)
{
    m_restoreAllowed = allowed;
    updateButtons();
}

void PlantHistoryWindow::updateButtons()
{
    const qsizetype selected = selectedRevisions().size();
    const bool idle = !m_extractPending;
    m_compareButton->setEnabled(idle && (selected == 1 || selected == 2)
                                && m_compareDrive->count() > 0);
    m_driveButton->setEnabled(idle && selected == 1 && m_restoreAllowed
                              && m_compareDrive->count() > 0);
    m_restoreButton->setEnabled(idle && selected == 1 && m_restoreAllowed);
}

QString PlantHistoryWindow::message() const
{
    return m_message->text();
}

void PlantHistoryWindow::showMessage(const QString &text)
{
    m_message->setText(text);
}

void PlantHistoryWindow::hideEvent(QHideEvent *event)
{
    saveSettings();
    QWidget::hideEvent(event);
}

void PlantHistoryWindow::saveSettings() const
{
    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    settings.setValue(QStringLiteral("geometry"), saveGeometry());
    settings.setValue(QStringLiteral("columns"), m_revisions->header()->saveState());
    settings.setValue(QStringLiteral("splitter"), m_splitter->saveState());
}

} // namespace DriveDesk
