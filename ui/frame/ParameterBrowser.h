#pragma once

#include <QHash>
#include <QPersistentModelIndex>
#include <QWidget>

class QAction;
class QLabel;
class QLineEdit;
class QSplitter;
class QStackedWidget;
class QTreeView;

namespace DriveDesk {

class FilterBar;
class GroupListModel;
class ParameterDelegate;
class ParameterFilterModel;
class ParameterModel;
class ParameterView;

// Browsing one drive's parameters: the groups on the left (in the drive's order, and "All
// parameters"), the table on the right for the chosen group, with search as you type and the
// filters. A search looks through every group. Favourites are toggled with the star or the
// context menu.
class ParameterBrowser : public QWidget
{
    Q_OBJECT
public:
    explicit ParameterBrowser(ParameterModel *model, QWidget *parent = nullptr);

    ParameterModel *model() const { return m_model; }
    ParameterFilterModel *filterModel() const { return m_filter; }
    ParameterView *view() const { return m_view; }
    ParameterDelegate *delegate() const { return m_delegate; }
    FilterBar *filterBar() const { return m_filterBar; }
    QLineEdit *searchField() const;
    QTreeView *groupTree() const { return m_groups; }
    GroupListModel *groupModel() const { return m_groupList; }
    QSplitter *splitter() const { return m_splitter; }

    // Checkable actions for the menus, in step with the check boxes above the table.
    QAction *differsAction() const;
    QAction *favouritesAction() const;
    QAction *hideAboveLevelAction() const;
    QAction *rawValuesAction() const;
    QAction *findAction() const;

    // Shows one group ("ru"), or every group for an empty id. False for an id the drive lacks.
    bool showGroup(const QString &groupId);
    QString shownGroup() const { return m_groupId; }
    // Parameter rows the table shows now.
    int shownParameterCount() const;

    // What the table area says while no drive has been read ("Not connected", "Reading ...").
    void setEmptyText(const QString &text);
    // While off (link lost, not connected) values cannot be edited; everything stays visible.
    void setEditingEnabled(bool enabled);
    // Actions offered in the table's context menu after the favourite toggle.
    void setContextActions(const QList<QAction *> &actions) { m_contextActions = actions; }
    // Source-model addresses of the parameters with a selected cell, and the set mask per
    // parameter (value cells give their set; other cells every set).
    QList<QPair<quint16, quint8>> selectedParameters() const;
    bool hasSelectedParameter() const;

    QByteArray saveState() const;
    void restoreState(const QByteArray &state);

private:
    void rebuildGroups();
    void onGroupSelected();
    // A group row of the parameter or filter model -> its id, by the group's address.
    QString groupIdOf(const QModelIndex &group) const;
    // The group's row in the parameter model; invalid for an empty or unknown id.
    QModelIndex sourceGroupOf(const QString &groupId) const;
    void applyScope();
    void followFilter();
    // One group fills the table (no search overrides it).
    bool isGroupShown() const;
    void updateSetColumns(const QModelIndex &sourceGroup);
    void showContextMenu(const QPoint &position);
    QModelIndexList selectedCells() const; // the selection, or the current cell

    ParameterModel *m_model = nullptr;
    ParameterFilterModel *m_filter = nullptr;
    ParameterDelegate *m_delegate = nullptr;
    ParameterView *m_view = nullptr;
    QTreeView *m_groups = nullptr;
    GroupListModel *m_groupList = nullptr;
    QSplitter *m_splitter = nullptr;
    FilterBar *m_filterBar = nullptr;
    QLabel *m_scope = nullptr;
    QLabel *m_empty = nullptr;
    QStackedWidget *m_stack = nullptr;
    QList<QAction *> m_contextActions;
    QString m_groupId; // empty: all parameters
    QString m_title; // of the scope: the group, "All parameters" or the search
    QString m_emptyText;
    QString m_pendingGroup; // to show once the drive has been read (restored state)
    QPersistentModelIndex m_root; // the shown group in the filter model
    QHash<QString, quint16> m_groupAddresses; // group id -> address, from the description
    bool m_rebuilding = false; // the list's current row is being set from m_groupId
};

} // namespace DriveDesk
