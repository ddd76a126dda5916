#include "ParameterView.h"

#include "model/ParameterModel.h"
#include "parameters/PasswordLevel.h"

#include <QMouseEvent>
#include <QToolTip>

namespace DriveDesk {

ParameterView::ParameterView(QWidget *parent)
    : QTreeView(parent)
{
    setObjectName(QStringLiteral("parameterView"));
    setUniformRowHeights(true); // 5,000 rows scroll without measuring each one
    setAlternatingRowColors(true);
    setSelectionBehavior(QAbstractItemView::SelectItems);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                    | QAbstractItemView::AnyKeyPressed);
    setAllColumnsShowFocus(false);
    setContextMenuPolicy(Qt::CustomContextMenu);
}

QRect ParameterView::starRect(const QModelIndex &index) const
{
    const QModelIndex id = index.siblingAtColumn(ParameterModel::IdColumn);
    if (!id.isValid() || id.data(ParameterModel::IsGroupRole).toBool())
        return {};
    QStyleOptionViewItem option;
    initViewItemOption(&option);
    option.rect = visualRect(id);
    option.features |= QStyleOptionViewItem::HasDecoration | QStyleOptionViewItem::HasDisplay;
    option.icon = id.data(Qt::DecorationRole).value<QIcon>();
    option.text = id.data(Qt::DisplayRole).toString();
    return style()->subElementRect(QStyle::SE_ItemViewItemDecoration, &option, this);
}

void ParameterView::cancelEditing()
{
    if (state() != EditingState)
        return;
    if (QWidget *editor = indexWidget(currentIndex()))
        closeEditor(editor, QAbstractItemDelegate::NoHint);
}

void ParameterView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton) {
        const QModelIndex index = indexAt(event->position().toPoint());
        if (index.column() == ParameterModel::IdColumn
            && starRect(index).contains(event->position().toPoint())) {
            const bool favourite = index.data(ParameterModel::FavouriteRole).toBool();
            model()->setData(index, !favourite, ParameterModel::FavouriteRole);
            event->accept();
            return;
        }
    }
    QTreeView::mousePressEvent(event);
}

bool ParameterView::edit(const QModelIndex &index, EditTrigger trigger, QEvent *event)
{
    const bool byUser = trigger & (DoubleClicked | EditKeyPressed | AnyKeyPressed);
    if (!byUser || !index.isValid() || index.data(ParameterModel::SetRole).toInt() < 0)
        return QTreeView::edit(index, trigger, event);
    // Returning true tells the view the attempt was handled: no double-click signal, and no
    // keyboard search moving the cursor to a row that happens to start with the typed key.
    if (index.data(ParameterModel::AddressRole).toUInt() == kPasswordParameterAddress) {
        emit passwordRequested();
        return true;
    }
    const QString refusal = index.data(ParameterModel::EditRefusalRole).toString();
    if (!refusal.isEmpty()) {
        const QRect cell = visualRect(index);
        QToolTip::showText(viewport()->mapToGlobal(cell.bottomLeft()), refusal, viewport(), cell);
        emit editRefused(refusal);
        return true;
    }
    return QTreeView::edit(index, trigger, event);
}

} // namespace DriveDesk
