// ParameterBrowser: the cells the user selected, whether they may be edited, and their context
// menu.
#include "ParameterBrowser.h"

#include "ParameterView.h"

#include "model/ParameterFilterModel.h"
#include "model/ParameterModel.h"

#include <QHash>
#include <QMap>
#include <QMenu>

#include <algorithm>

namespace DriveDesk {

void ParameterBrowser::setEditingEnabled(bool enabled)
{
    if (!enabled)
        m_view->cancelEditing();
    m_view->setEditTriggers(enabled ? QAbstractItemView::DoubleClicked
                                    | QAbstractItemView::EditKeyPressed
                                    | QAbstractItemView::AnyKeyPressed
                                    : QAbstractItemView::NoEditTriggers);
}

QModelIndexList ParameterBrowser::selectedCells() const
{
    QModelIndexList indexes = m_view->selectionModel()->selectedIndexes();
    if (indexes.isEmpty() && m_view->currentIndex().isValid())
        indexes << m_view->currentIndex();
    return indexes;
}

bool ParameterBrowser::hasSelectedParameter() const
{
    const QModelIndexList indexes = selectedCells();
    return std::any_of(indexes.cbegin(), indexes.cend(), [](const QModelIndex &index) {
        return !index.data(ParameterModel::IsGroupRole).toBool();
    });
}

QList<QPair<quint16, quint8>> ParameterBrowser::selectedParameters() const
{
    QMap<quint16, quint8> masks; // in address order
    QHash<quint16, bool> setProgrammable;
    const QModelIndexList indexes = selectedCells();
    for (const QModelIndex &index : indexes) {
        if (index.data(ParameterModel::IsGroupRole).toBool())
            continue;
        const auto address = index.data(ParameterModel::AddressRole).value<quint16>();
        auto known = setProgrammable.constFind(address);
        if (known == setProgrammable.constEnd()) {
            known = setProgrammable.insert(address,
                                           m_model->state()->parameter(address)
                                               && m_model->state()->parameter(address)->isSetProgrammable());
        }
        const int set = ParameterModel::setOfColumn(index.column());
        masks[address] |= set >= 0 ? quint8(1u << set) : *known ? quint8(0xFF) : quint8(0x01);
    }
    QList<QPair<quint16, quint8>> result;
    for (auto it = masks.cbegin(); it != masks.cend(); ++it)
        result.append({ it.key(), it.value() });
    return result;
}

void ParameterBrowser::showContextMenu(const QPoint &position)
{
    const QModelIndex index = m_view->indexAt(position);
    QMenu menu(this);
    if (index.isValid() && !index.data(ParameterModel::IsGroupRole).toBool()) {
        QAction *favourite = menu.addAction(tr("Favourite"));
        favourite->setCheckable(true);
        favourite->setChecked(index.data(ParameterModel::FavouriteRole).toBool());
        const QPersistentModelIndex target(index);
        connect(favourite, &QAction::toggled, this, [this, target](bool on) {
            if (target.isValid())
                m_filter->setData(target, on, ParameterModel::FavouriteRole);
        });
        menu.addSeparator();
    }
    menu.addActions(m_contextActions);
    if (!menu.isEmpty())
        menu.exec(m_view->viewport()->mapToGlobal(position));
}

} // namespace DriveDesk
