#pragma once

#include <QTreeView>

namespace DriveDesk {

// The parameter table: a tree view over the filtered ParameterModel in which a click on the
// star in front of a parameter's id makes it a favourite (or no longer one).
class ParameterView : public QTreeView
{
    Q_OBJECT
public:
    explicit ParameterView(QWidget *parent = nullptr);

    // Where the star of a parameter row is drawn, in viewport coordinates; empty for groups.
    QRect starRect(const QModelIndex &index) const;
    // Closes an open editor without writing what it holds.
    void cancelEditing();

protected:
    void mousePressEvent(QMouseEvent *event) override;
};

} // namespace DriveDesk
