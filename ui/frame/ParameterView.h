#pragma once

#include <QTreeView>

namespace DriveDesk {

// The parameter table: a tree view over the filtered ParameterModel in which a click on the
// star in front of a parameter's id makes it a favourite (or no longer one). An attempt to edit
// a value that cannot be changed says why instead of doing nothing (or, for a typed key,
// jumping to another row); the password parameter asks for its dialog.
class ParameterView : public QTreeView
{
    Q_OBJECT
public:
    explicit ParameterView(QWidget *parent = nullptr);

    // Where the star of a parameter row is drawn, in viewport coordinates; empty for groups.
    QRect starRect(const QModelIndex &index) const;
    // Closes an open editor without writing what it holds.
    void cancelEditing();
    using QTreeView::edit;

signals:
    // The user tried to edit a value he may not change; `reason` says why (also shown at the
    // cell).
    void editRefused(const QString &reason);
    // The user tried to edit the password parameter: a password is entered in its dialog.
    void passwordRequested();

protected:
    void mousePressEvent(QMouseEvent *event) override;
    bool edit(const QModelIndex &index, EditTrigger trigger, QEvent *event) override;
};

} // namespace DriveDesk
