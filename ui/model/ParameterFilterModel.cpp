#include "ParameterFilterModel.h"

#include "ParameterModel.h"

#include "parameters/ParameterId.h"

namespace DriveDesk {

ParameterFilterModel::ParameterFilterModel(QObject *parent)
    : QSortFilterProxyModel(parent)
{
    setRecursiveFilteringEnabled(true);
    setDynamicSortFilter(true);
    setSortRole(ParameterModel::RawValueRole);
}

void ParameterFilterModel::setFilterText(const QString &text)
{
    if (text == m_text)
        return;
    m_text = text;
    const QString needle = text.trimmed().toLower();
    if (needle == m_needle)
        return;
    m_needle = needle;
    updateNamedAddress();
    invalidateRowsFilter();
}

void ParameterFilterModel::setSourceModel(QAbstractItemModel *model)
{
    disconnect(m_resetConnection);
    QSortFilterProxyModel::setSourceModel(model);
    if (model) {
        // Another drive has other groups: "op28" may name another address, or none.
        m_resetConnection = connect(model, &QAbstractItemModel::modelReset, this, [this] {
            updateNamedAddress();
            invalidateRowsFilter();
        });
    }
    updateNamedAddress();
}

void ParameterFilterModel::updateNamedAddress()
{
    m_namedAddress.reset();
    if (m_needle.isEmpty() || !sourceModel())
        return;
    QList<GroupAddress> groups;
    for (int row = 0; row < sourceModel()->rowCount(); ++row) {
        const QModelIndex group = sourceModel()->index(row, 0);
        groups << GroupAddress{group.data(ParameterModel::GroupIdRole).toString(),
                               group.data(ParameterModel::AddressRole).value<quint16>()};
    }
    m_namedAddress = ParameterId::parse(m_needle, groups);
}

void ParameterFilterModel::setFlag(bool &flag, bool on)
{
    if (flag == on)
        return;
    flag = on;
    invalidateRowsFilter();
}

void ParameterFilterModel::setDiffersFromDefaultOnly(bool on)
{
    setFlag(m_differsOnly, on);
}

void ParameterFilterModel::setFavouritesOnly(bool on)
{
    setFlag(m_favouritesOnly, on);
}

void ParameterFilterModel::setHideAboveLevel(bool on)
{
    setFlag(m_hideAboveLevel, on);
}

bool ParameterFilterModel::isFiltering() const
{
    return !m_needle.isEmpty() || m_differsOnly || m_favouritesOnly || m_hideAboveLevel;
}

bool ParameterFilterModel::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (!isFiltering())
        return true;
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    // A group is accepted through its parameters (recursive filtering).
    if (index.data(ParameterModel::IsGroupRole).toBool())
        return false;
    if (m_hideAboveLevel && index.data(ParameterModel::AboveLevelRole).toBool())
        return false;
    if (m_favouritesOnly && !index.data(ParameterModel::FavouriteRole).toBool())
        return false;
    if (m_differsOnly && !index.data(ParameterModel::DiffersFromDefaultRole).toBool())
        return false;
    if (!m_needle.isEmpty()) {
        const QString text = index.data(ParameterModel::SearchTextRole).toString();
        if (!text.contains(m_needle)
            && index.data(ParameterModel::AddressRole).value<quint16>() != m_namedAddress) {
            return false;
        }
    }
    return true;
}

bool ParameterFilterModel::lessThan(const QModelIndex &left, const QModelIndex &right) const
{
    if (left.data(ParameterModel::IsGroupRole).toBool())
        return left.row() < right.row(); // the drive's order
    if (left.column() == ParameterModel::IdColumn) {
        return left.data(ParameterModel::AddressRole).toUInt()
            < right.data(ParameterModel::AddressRole).toUInt();
    }
    const QVariant leftRaw = left.data(ParameterModel::RawValueRole);
    const QVariant rightRaw = right.data(ParameterModel::RawValueRole);
    if (leftRaw.isValid() && rightRaw.isValid())
        return leftRaw.toInt() < rightRaw.toInt();
    if (leftRaw.isValid() != rightRaw.isValid())
        return rightRaw.isValid(); // unknown values first
    return QString::localeAwareCompare(left.data().toString(), right.data().toString()) < 0;
}

} // namespace DriveDesk
