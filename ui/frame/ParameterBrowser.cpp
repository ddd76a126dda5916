#include "ParameterBrowser.h"

#include "FilterBar.h"
#include "GroupListModel.h"
#include "ParameterView.h"

#include "delegate/ParameterDelegate.h"
#include "model/ParameterFilterModel.h"
#include "model/ParameterModel.h"

#include <QAction>
#include <QDataStream>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QScopedValueRollback>
#include <QSplitter>
#include <QStackedWidget>
#include <QTreeView>
#include <QVBoxLayout>

namespace DriveDesk {

namespace {

constexpr quint32 kStateVersion = 1;

} // namespace

ParameterBrowser::ParameterBrowser(ParameterModel *model, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
{
    m_filter = new ParameterFilterModel(this);
    m_filter->setSourceModel(m_model);
    m_delegate = new ParameterDelegate(this);

    m_groupList = new GroupListModel(m_model, this);
    m_groups = new QTreeView;
    m_groups->setObjectName(QStringLiteral("groupTree"));
    m_groups->setModel(m_groupList);
    m_groups->setRootIsDecorated(false);
    m_groups->setItemsExpandable(false);
    m_groups->setUniformRowHeights(true);
    m_groups->setAllColumnsShowFocus(true);
    m_groups->setSelectionMode(QAbstractItemView::SingleSelection);
    m_groups->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_groups->header()->setStretchLastSection(false);
    m_groups->header()->setSectionResizeMode(GroupListModel::GroupColumn, QHeaderView::Stretch);
    m_groups->header()->setSectionResizeMode(GroupListModel::CountColumn,
                                             QHeaderView::ResizeToContents);

    m_view = new ParameterView;
    m_view->setModel(m_filter);
    m_view->setItemDelegate(m_delegate);
    m_view->setSortingEnabled(false);
    m_view->header()->setSectionsMovable(true);
    m_view->setIndentation(m_view->fontMetrics().averageCharWidth() * 2);
    const auto characters = [this](int n) { return m_view->fontMetrics().averageCharWidth() * n; };
    m_view->header()->resizeSection(ParameterModel::IdColumn, characters(19));
    m_view->header()->resizeSection(ParameterModel::NameColumn, characters(30));
    for (int column = ParameterModel::FirstSetColumn; column < ParameterModel::ColumnCount;
         ++column)
        m_view->header()->resizeSection(column, characters(16));
    m_view->header()->resizeSection(ParameterModel::FirstSetColumn, characters(24));
    m_view->header()->resizeSection(ParameterModel::UnitColumn, characters(8));
    m_view->header()->resizeSection(ParameterModel::AccessColumn, characters(30));

    m_empty = new QLabel;
    m_empty->setObjectName(QStringLiteral("emptyNotice"));
    m_empty->setAlignment(Qt::AlignCenter);
    m_empty->setWordWrap(true);
    m_stack = new QStackedWidget;
    m_stack->addWidget(m_view);
    m_stack->addWidget(m_empty);

    m_scope = new QLabel;
    m_scope->setObjectName(QStringLiteral("scopeLabel"));
    m_scope->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *right = new QWidget;
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    m_filterBar = new FilterBar;
    rightLayout->addWidget(m_filterBar);
    rightLayout->addWidget(m_scope);
    rightLayout->addWidget(m_stack, 1);

    m_splitter = new QSplitter;
    m_splitter->setObjectName(QStringLiteral("browserSplitter"));
    m_splitter->addWidget(m_groups);
    m_splitter->addWidget(right);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setSizes({ 280, 1000 });
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);

    connect(m_model, &QAbstractItemModel::modelReset, this, &ParameterBrowser::rebuildGroups);
    connect(m_groups->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &ParameterBrowser::onGroupSelected);
    connect(searchField(), &QLineEdit::textChanged, this, [this](const QString &text) {
        m_filter->setFilterText(text);
        applyScope();
    });
    connect(differsAction(), &QAction::toggled, this, [this](bool on) {
        m_filter->setDiffersFromDefaultOnly(on);
        applyScope();
    });
    connect(favouritesAction(), &QAction::toggled, this, [this](bool on) {
        m_filter->setFavouritesOnly(on);
        applyScope();
    });
    connect(hideAboveLevelAction(), &QAction::toggled, this, [this](bool on) {
        m_filter->setHideAboveLevel(on);
        applyScope();
    });
    connect(rawValuesAction(), &QAction::toggled, m_model, &ParameterModel::setShowRawValues);
    connect(m_filter, &QAbstractItemModel::rowsInserted, this,
            [this](const QModelIndex &parent, int first, int last) {
                if (parent.isValid() || m_root.isValid())
                    return followFilter();
                // A group came back into an all-groups view: open it like the others.
                for (int row = first; row <= last; ++row) {
                    m_view->setFirstColumnSpanned(row, {}, true);
                    m_view->expand(m_filter->index(row, 0));
                }
                followFilter();
            });
    connect(m_filter, &QAbstractItemModel::rowsRemoved, this, &ParameterBrowser::followFilter);
    connect(m_filter, &QAbstractItemModel::layoutChanged, this, &ParameterBrowser::followFilter);
    connect(m_view, &QWidget::customContextMenuRequested, this, &ParameterBrowser::showContextMenu);
    rebuildGroups();
}

QLineEdit *ParameterBrowser::searchField() const
{
    return m_filterBar->searchField();
}

QAction *ParameterBrowser::findAction() const
{
    return m_filterBar->findAction();
}

QAction *ParameterBrowser::differsAction() const
{
    return m_filterBar->differsAction();
}

QAction *ParameterBrowser::favouritesAction() const
{
    return m_filterBar->favouritesAction();
}

QAction *ParameterBrowser::hideAboveLevelAction() const
{
    return m_filterBar->hideAboveLevelAction();
}

QAction *ParameterBrowser::rawValuesAction() const
{
    return m_filterBar->rawValuesAction();
}

void ParameterBrowser::rebuildGroups()
{
    m_groupAddresses.clear();
    const DriveDescription drive = m_model->state()->description();
    for (const GroupDescription &group : drive.groups)
        m_groupAddresses.insert(group.id, group.address);
    // The group shown before, or the one asked for before the drive was read.
    const QString wanted = m_pendingGroup.isEmpty() ? m_groupId : m_pendingGroup;
    const QModelIndex current = m_groupList->rowOf(sourceGroupOf(wanted));
    {
        const QScopedValueRollback rebuilding(m_rebuilding, true);
        m_groups->setCurrentIndex(current);
    }
    m_groupId = groupIdOf(m_groupList->sourceGroup(current));
    // Cleared for a new scan: the same group comes back once the drive has been read again.
    m_pendingGroup = m_model->rowCount() > 0 ? QString() : wanted;
    applyScope();
}

QString ParameterBrowser::groupIdOf(const QModelIndex &group) const
{
    if (!group.isValid() || !group.data(ParameterModel::IsGroupRole).toBool())
        return {};
    return m_groupAddresses.key(group.data(ParameterModel::AddressRole).value<quint16>());
}

QModelIndex ParameterBrowser::sourceGroupOf(const QString &groupId) const
{
    const auto address = m_groupAddresses.constFind(groupId);
    if (groupId.isEmpty() || address == m_groupAddresses.constEnd())
        return {};
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const QModelIndex group = m_model->index(row, 0);
        if (group.data(ParameterModel::AddressRole).value<quint16>() == *address)
            return group;
    }
    return {};
}

bool ParameterBrowser::showGroup(const QString &groupId)
{
    const QModelIndex group = sourceGroupOf(groupId);
    if (!groupId.isEmpty() && !group.isValid())
        return false;
    m_groups->setCurrentIndex(m_groupList->rowOf(group));
    onGroupSelected();
    return true;
}

void ParameterBrowser::onGroupSelected()
{
    const QModelIndex current = m_groups->currentIndex();
    // While rebuilding, or while the list is reset, the current row says nothing.
    if (m_rebuilding || !current.isValid())
        return;
    m_groupId = groupIdOf(m_groupList->sourceGroup(current));
    m_pendingGroup.clear();
    applyScope();
}

void ParameterBrowser::applyScope()
{
    const bool searching = !m_filter->filterText().trimmed().isEmpty();
    QModelIndex sourceGroup;
    if (!searching)
        sourceGroup = sourceGroupOf(m_groupId);
    QString title;
    if (sourceGroup.isValid()) {
        m_root = m_filter->mapFromSource(sourceGroup);
        m_view->setRootIndex(m_root);
        m_view->setRootIsDecorated(false);
        title = sourceGroup.data(Qt::DisplayRole).toString();
    } else {
        m_root = QPersistentModelIndex();
        m_view->setRootIndex({});
        m_view->setRootIsDecorated(true);
        for (int row = 0; row < m_filter->rowCount(); ++row)
            m_view->setFirstColumnSpanned(row, {}, true);
        m_view->expandAll();
        title = searching
            ? tr("Search results for \u201c%1\u201d").arg(m_filter->filterText().trimmed())
            : tr("All parameters");
    }
    updateSetColumns(sourceGroup);
    m_title = title;
    followFilter();
}

bool ParameterBrowser::isGroupShown() const
{
    return !m_groupId.isEmpty() && m_filter->filterText().trimmed().isEmpty();
}

void ParameterBrowser::followFilter()
{
    const bool groupShown = isGroupShown();
    if (groupShown && (!m_root.isValid() || m_view->rootIndex() != QModelIndex(m_root))) {
        // The group was filtered out and perhaps came back: find it again.
        for (int row = 0; row < m_filter->rowCount(); ++row) {
            const QModelIndex group = m_filter->index(row, 0);
            if (groupIdOf(group) == m_groupId) {
                m_root = group;
                m_view->setRootIndex(group);
                break;
            }
        }
    }
    const int shown = shownParameterCount();
    const bool empty = shown == 0 || (groupShown && !m_root.isValid());
    QString text = m_title;
    if (m_model->rowCount() == 0) {
        m_empty->setText(m_emptyText.isEmpty()
                             ? tr("Not connected. Connect to a drive to see its parameters.")
                             : m_emptyText);
        text.clear();
    } else if (empty) {
        m_empty->setText(m_filter->isFiltering()
                             ? tr("No parameter here matches the search and the filters.")
                             : tr("This group holds no parameters."));
        text = tr("%1: none shown").arg(text);
    } else if (m_filter->isFiltering()) {
        text = tr("%1: %n parameter(s) (filtered)", nullptr, shown).arg(text);
    } else {
        text = tr("%1: %n parameter(s)", nullptr, shown).arg(text);
    }
    m_scope->setText(text);
    m_stack->setCurrentWidget(empty || m_model->rowCount() == 0 ? static_cast<QWidget *>(m_empty)
                                                                : m_view);
}

void ParameterBrowser::setEmptyText(const QString &text)
{
    m_emptyText = text;
    followFilter();
}

int ParameterBrowser::shownParameterCount() const
{
    if (isGroupShown())
        return m_root.isValid() ? m_filter->rowCount(m_root) : 0;
    int count = 0;
    for (int row = 0; row < m_filter->rowCount(); ++row)
        count += m_filter->rowCount(m_filter->index(row, 0));
    return count;
}

void ParameterBrowser::updateSetColumns(const QModelIndex &sourceGroup)
{
    // Sets 1..7 only where a shown parameter is set-programmable: the run display has none.
    bool anySets = !sourceGroup.isValid();
    for (int row = 0; !anySets && row < m_model->rowCount(sourceGroup); ++row) {
        anySets = m_model->index(row, ParameterModel::FirstSetColumn + 1, sourceGroup)
                      .data(Qt::DisplayRole)
                      .isValid();
    }
    for (int set = 1; set < kParameterSets; ++set)
        m_view->setColumnHidden(ParameterModel::FirstSetColumn + set, !anySets);
}

QByteArray ParameterBrowser::saveState() const
{
    QByteArray state;
    QDataStream out(&state, QIODevice::WriteOnly);
    out << kStateVersion << m_splitter->saveState() << m_view->header()->saveState()
        << (m_pendingGroup.isEmpty() ? m_groupId : m_pendingGroup) << differsAction()->isChecked()
        << favouritesAction()->isChecked() << hideAboveLevelAction()->isChecked()
        << rawValuesAction()->isChecked();
    return state;
}

void ParameterBrowser::restoreState(const QByteArray &state)
{
    QDataStream in(state);
    quint32 version = 0;
    QByteArray splitter;
    QByteArray header;
    QString group;
    bool differs = false;
    bool favourites = false;
    bool hide = false;
    bool raw = false;
    in >> version >> splitter >> header >> group >> differs >> favourites >> hide >> raw;
    if (in.status() != QDataStream::Ok || version != kStateVersion)
        return;
    m_splitter->restoreState(splitter);
    m_view->header()->restoreState(header);
    differsAction()->setChecked(differs);
    favouritesAction()->setChecked(favourites);
    hideAboveLevelAction()->setChecked(hide);
    rawValuesAction()->setChecked(raw);
    // Before the drive is read the group is not there yet: the next rebuild shows it.
    if (!showGroup(group))
        m_pendingGroup = group;
}

} // namespace DriveDesk
