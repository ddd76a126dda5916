#pragma once

#include <QPersistentModelIndex>
#include <QWidget>

class QAction;
class QLabel;
class QLineEdit;
class QSplitter;
class QStackedWidget;
class QTreeWidget;

namespace DriveDesk {

class FilterBar;
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
    QTreeWidget *groupTree() const { return m_groups; }
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
    QTreeWidget *m_groups = nullptr;
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
};

} // namespace DriveDesk
