#include "ComparisonModel.h"

#include "model/ParameterModel.h"
#include "model/ParameterRow.h"

#include <QFont>
#include <QHash>
#include <QPalette>
#include <QGuiApplication>

namespace DriveDesk {

namespace {

// What the parameter table searches for this parameter (ParameterRow::searchText), on each side
// that has it: the id, the address, the name and every value as shown.
QString searchTextOf(const ComparisonRow &row, const DriveDescription &a,
                     const DriveDescription &b)
{
    QString text;
    for (const DriveDescription *side : { &a, &b }) {
        if (const ParameterDescription *parameter = side->find(row.address)) {
            const ParameterState state(*parameter, row.id);
            text += ParameterRow(state).searchText(false) + QLatin1Char('\n');
        }
    }
    return text;
}

} // namespace

ComparisonModel::ComparisonModel(QObject *parent)
    : GroupTreeModel(parent)
{ }

void ComparisonModel::setComparison(const ComparisonTable &table, const DriveDescription &a,
                                    const DriveDescription &b)
{
    beginResetModel();
    m_table = table;
    m_groups.clear();
    m_searchTexts.assign(std::size_t(table.rows.size()), QString());
    m_chosen.assign(std::size_t(table.rows.size()), false);
    QHash<QString, std::size_t> groupOf;
    for (const DriveDescription *side : { &a, &b }) {
        for (const GroupDescription &group : side->groups) {
            if (groupOf.contains(group.id))
                continue;
            groupOf.insert(group.id, m_groups.size());
            m_groups.push_back({ group.id, group.name, group.address, {} });
        }
    }
    QHash<quint16, QString> searchTexts; // one per parameter, for each of its sets
    for (int i = 0; i < table.rows.size(); ++i) {
        const ComparisonRow &row = table.rows[i];
        auto group = groupOf.constFind(row.groupId);
        if (group == groupOf.cend())
            continue; // every parameter is in a group of its side
        m_groups[*group].rows.append(i);
        auto text = searchTexts.find(row.address);
        if (text == searchTexts.end())
            text = searchTexts.insert(row.address, searchTextOf(row, a, b));
        m_searchTexts[std::size_t(i)] = *text;
    }
    // Groups with nothing to compare (a set against another: only set-programmable parameters)
    // are left out.
    std::erase_if(m_groups, [](const Group &group) { return group.rows.isEmpty(); });
    endResetModel();
    emit chosenChanged();
}

void ComparisonModel::setSideNames(const QString &a, const QString &b)
{
    m_nameA = a;
    m_nameB = b;
    emit headerDataChanged(Qt::Horizontal, AColumn, BColumn);
}

void ComparisonModel::setShowRawValues(bool raw)
{
    if (raw == m_raw)
        return;
    beginResetModel(); // every value text and the search text change
    m_raw = raw;
    endResetModel();
}

QList<ComparisonRow> ComparisonModel::chosenRows() const
{
    QList<ComparisonRow> rows;
    for (std::size_t i = 0; i < m_chosen.size(); ++i) {
        if (m_chosen[i])
            rows.append(m_table.rows[qsizetype(i)]);
    }
    return rows;
}

void ComparisonModel::clearChosen()
{
    std::fill(m_chosen.begin(), m_chosen.end(), false);
    for (int g = 0; g < int(m_groups.size()); ++g) {
        const QModelIndex group = index(g, 0);
        if (const int rows = rowCount(group); rows > 0)
            emit dataChanged(index(0, IdColumn, group), index(rows - 1, IdColumn, group),
                             { Qt::CheckStateRole });
    }
    emit chosenChanged();
}

bool ComparisonModel::isChoosable(const QModelIndex &index) const
{
    const ComparisonRow *row = rowAt(index);
    return row && (row->isWritableTo(true) || row->isWritableTo(false));
}

void ComparisonModel::setChosen(const QModelIndex &index, bool chosen)
{
    setData(index.siblingAtColumn(IdColumn), chosen ? Qt::Checked : Qt::Unchecked,
            Qt::CheckStateRole);
}

const ComparisonRow *ComparisonModel::rowAt(const QModelIndex &index) const
{
    const int row = tableRowAt(index);
    return row < 0 ? nullptr : &m_table.rows[row];
}

int ComparisonModel::tableRowAt(const QModelIndex &index) const
{
    const int group = groupOf(index);
    return group < 0 ? -1 : m_groups[std::size_t(group)].rows[index.row()];
}

int ComparisonModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

QVariant ComparisonModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid())
        return {};
    if (isGroup(index))
        return groupData(m_groups[std::size_t(index.row())], index.column(), role);
    return rowData(tableRowAt(index), index.column(), role);
}

QVariant ComparisonModel::groupData(const Group &group, int column, int role) const
{
    switch (role) {
    case Qt::DisplayRole:
        if (column == IdColumn)
            return tr("%1 - %2").arg(group.id, group.name);
        return {};
    case ParameterModel::IsGroupRole:
        return true;
    case ParameterModel::GroupIdRole:
        return group.id;
    case ParameterModel::AddressRole:
        return QVariant::fromValue(group.address);
    case Qt::FontRole: {
        QFont font;
        font.setBold(true);
        return font;
    }
    default:
        return {};
    }
}

QString ComparisonModel::valueText(const ComparisonRow &row, bool a) const
{
    if (!m_raw)
        return a ? row.a : row.b;
    const std::optional<qint32> &raw = a ? row.rawA : row.rawB;
    if (raw)
        return QString::number(*raw);
    return (a ? row.a : row.b).isEmpty() ? QString() : tr("?");
}

QVariant ComparisonModel::rowData(int tableRow, int column, int role) const
{
    const ComparisonRow &row = m_table.rows[tableRow];
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case IdColumn:
            return row.id;
        case NameColumn:
            return row.name;
        case SetColumn:
            if (!row.perSet)
                return tr("all");
            if (row.setA == row.setB)
                return QString::number(row.setA);
            return tr("%1 / %2").arg(row.setA).arg(row.setB);
        case AColumn:
            return valueText(row, true);
        case BColumn:
            return valueText(row, false);
        case StateColumn:
            if (row.state == ComparisonRow::State::ReadOnly) {
                return row.differs ? tr("read-only, different") : tr("read-only, equal");
            }
            if (row.state == ComparisonRow::State::NotASetting) {
                if (row.onlyInA)
                    return tr("not a setting, only in A");
                if (row.onlyInB)
                    return tr("not a setting, only in B");
                return row.differs ? tr("not a setting, different") : tr("not a setting, equal");
            }
            return ComparisonTable::stateText(row.state);
        }
        return {};
    case Qt::ToolTipRole:
        if (column == SetColumn && !row.perSet)
            return tr("The parameter holds one value for every set.");
        if (column == StateColumn && row.state == ComparisonRow::State::ReadOnly)
            return tr("A download does not write this parameter: neither side can be changed "
                      "to the other's value here.");
        if (column == StateColumn && row.state == ComparisonRow::State::NotASetting)
            return tr("A live or read-only value, or one a parameter list leaves out: shown, "
                      "never counted as a difference.");
        return {};
    case Qt::CheckStateRole:
        if (column == IdColumn && (row.isWritableTo(true) || row.isWritableTo(false)))
            return m_chosen[std::size_t(tableRow)] ? Qt::Checked : Qt::Unchecked;
        return {};
    case Qt::FontRole:
        if (row.differs && (column == AColumn || column == BColumn || column == StateColumn)) {
            QFont font;
            font.setBold(row.state == ComparisonRow::State::Different);
            font.setItalic(row.state != ComparisonRow::State::Different);
            return font;
        }
        return {};
    case Qt::ForegroundRole:
        if (row.state == ComparisonRow::State::ReadOnly
            || row.state == ComparisonRow::State::NotASetting)
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case ParameterModel::RawValueRole:
        if (column == AColumn && row.rawA)
            return *row.rawA;
        if (column == BColumn && row.rawB)
            return *row.rawB;
        if (column == SetColumn)
            return row.setA;
        return {};
    case ParameterModel::AddressRole:
        return QVariant::fromValue(row.address);
    case ParameterModel::IsGroupRole:
        return false;
    case ParameterModel::GroupIdRole:
        return row.groupId;
    case ParameterModel::SetRole:
        return row.setA;
    case ParameterModel::SearchTextRole:
        // Values shown raw are searched raw, as in the parameter table.
        if (m_raw) {
            return m_searchTexts[std::size_t(tableRow)] + valueText(row, true) + QLatin1Char('\n')
                + valueText(row, false);
        }
        return m_searchTexts[std::size_t(tableRow)];
    case StateRole:
        return int(row.state);
    case DiffersRole:
        return row.differs;
    default:
        return {};
    }
}

bool ComparisonModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const int tableRow = tableRowAt(index);
    if (tableRow < 0 || role != Qt::CheckStateRole || index.column() != IdColumn
        || !isChoosable(index)) {
        return false;
    }
    const bool chosen = value.value<Qt::CheckState>() == Qt::Checked
        || value.toInt() == int(Qt::Checked);
    if (m_chosen[std::size_t(tableRow)] == chosen)
        return true;
    m_chosen[std::size_t(tableRow)] = chosen;
    emit dataChanged(index, index, { Qt::CheckStateRole });
    emit chosenChanged();
    return true;
}

Qt::ItemFlags ComparisonModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == IdColumn && isChoosable(index))
        flags |= Qt::ItemIsUserCheckable;
    return flags;
}

QVariant ComparisonModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case IdColumn:
        return tr("Parameter");
    case NameColumn:
        return tr("Name");
    case SetColumn:
        return tr("Set");
    case AColumn:
        return m_nameA.isEmpty() ? tr("A") : tr("A: %1").arg(m_nameA);
    case BColumn:
        return m_nameB.isEmpty() ? tr("B") : tr("B: %1").arg(m_nameB);
    case StateColumn:
        return tr("State");
    }
    return {};
}

} // namespace DriveDesk
