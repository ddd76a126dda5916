// ParameterModel: what each cell shows, and edits coming back from views.
#include "ParameterModel.h"

#include "parameters/ParameterId.h"

#include <QDateTime>
#include <QFont>

namespace DriveDesk {

QVariant ParameterModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.model() != this)
        return {};
    if (isGroup(index))
        return groupData(index.row(), index.column(), role);
    return parameterData(*rowAt(index), index.column(), role);
}

QVariant ParameterModel::groupData(int group, int column, int role) const
{
    const GroupDescription &description = m_state->group(group);
    switch (role) {
    case Qt::DisplayRole:
        if (column == IdColumn)
            return QStringLiteral("%1  %2").arg(description.id, description.name);
        return {};
    case Qt::ToolTipRole:
        if (column == IdColumn) {
            return tr("%1, %n parameter(s)", nullptr, m_state->parameterCount(group))
                .arg(ParameterId::hexAddress(description.address));
        }
        return {};
    case Qt::FontRole: {
        QFont font;
        font.setBold(true);
        return font;
    }
    case AddressRole:
        return QVariant::fromValue(description.address);
    case GroupIdRole:
        return description.id;
    case IsGroupRole:
        return true;
    case SetRole:
        return -1;
    case EditableRole:
    case FavouriteRole:
    case DiffersFromDefaultRole:
    case AboveLevelRole:
        return false;
    case RawModeRole:
        return m_raw;
    default:
        return {};
    }
}

QVariant ParameterModel::parameterData(const ParameterRow &row, int column, int role) const
{
    const int set = setOfColumn(column);
    const int cell = row.hasCell(set) ? set : -1;
    switch (role) {
    case Qt::DisplayRole:
        return displayText(row, column);
    case Qt::EditRole:
        if (cell >= 0)
            return row.shownValue(cell).value_or(row.description().defaultValue);
        return displayText(row, column);
    case Qt::ToolTipRole:
        return toolTip(row, column);
    case Qt::DecorationRole:
        if (column == IdColumn)
            return m_decoration.favouriteIcon(isFavourite(row.address()));
        if (cell >= 0 && row.editState(cell) != EditState::None)
            return m_decoration.icon(row.editState(cell));
        return {};
    case Qt::BackgroundRole:
        if (cell >= 0 && row.editState(cell) != EditState::None)
            return m_decoration.background(row.editState(cell));
        if (cell >= 0 && row.properties().isReadOnly())
            return m_decoration.readOnlyBackground();
        return {};
    case Qt::ForegroundRole:
        if (isAboveLevel(row) || (cell >= 0 && isStale(row)))
            return m_decoration.lockedText();
        return {};
    case Qt::FontRole:
        if (cell >= 0 && isStale(row)) {
            QFont font;
            font.setItalic(true);
            return font;
        }
        return {};
    case StaleRole:
        return cell >= 0 && isStale(row);
    case LastReadRole:
        return row.readAtMs() != 0 ? QDateTime::fromMSecsSinceEpoch(row.readAtMs()) : QDateTime();
    case RawValueRole:
        if (cell >= 0) {
            const std::optional<qint32> shown = row.shownValue(cell);
            return shown ? QVariant(*shown) : QVariant();
        }
        if (column == MinimumColumn)
            return row.description().minimum;
        if (column == MaximumColumn)
            return row.description().maximum;
        if (column == DefaultColumn)
            return row.description().defaultValue;
        return {};
    case AddressRole:
        return QVariant::fromValue(row.address());
    case SetRole:
        return cell;
    case EditStateRole:
        return cell >= 0 ? QVariant::fromValue(row.editState(cell)) : QVariant();
    case EditableRole:
        return isEditable(row);
    case EditRefusalRole:
        return m_state->editRefusal(row.address());
    case FavouriteRole:
        return isFavourite(row.address());
    case IsGroupRole:
        return false;
    case DiffersFromDefaultRole:
        return row.state().differsFromDefault();
    case AboveLevelRole:
        return isAboveLevel(row);
    case SearchTextRole:
        return row.searchText(m_raw);
    case DescriptionRole:
        return QVariant::fromValue(row.description());
    case RawModeRole:
        return m_raw;
    default:
        return {};
    }
}

QVariant ParameterModel::displayText(const ParameterRow &row, int column) const
{
    const int set = setOfColumn(column);
    if (set >= 0) {
        if (!row.hasCell(set))
            return {};
        const QString text = row.text(set, m_raw);
        return text.isEmpty() ? tr("?") : text;
    }
    const ParameterDescription &description = row.description();
    const ParameterFormat &format = row.format();
    switch (column) {
    case IdColumn:
        return row.id();
    case NameColumn:
        return description.name;
    case MinimumColumn:
        return m_raw ? QString::number(description.minimum) : format.number(description.minimum);
    case MaximumColumn:
        return m_raw ? QString::number(description.maximum) : format.number(description.maximum);
    case DefaultColumn:
        return m_raw ? QString::number(description.defaultValue)
                     : format.text(description.defaultValue, false);
    case UnitColumn:
        return m_raw ? QString() : format.scaling().unitSymbol();
    case AccessColumn:
        return accessText(row);
    default:
        return {};
    }
}

QVariant ParameterModel::toolTip(const ParameterRow &row, int column) const
{
    const ParameterDescription &description = row.description();
    const int set = setOfColumn(column);
    if (set >= 0 && row.hasCell(set)) {
        const QString shown = row.text(set, m_raw);
        // An entry of a parameter without sets names no set.
        const JournalEntry *change = m_state->journalChanges().last(
            row.address(), description.isSetProgrammable() ? set : -1);
        switch (row.editState(set)) {
        case EditState::Pending:
            return tr("Writing %1 ...").arg(shown);
        case EditState::Written:
            if (change)
                return tr("Written: %1").arg(shown) + QLatin1Char('\n') + change->changeText();
            return tr("Written: %1").arg(shown);
        case EditState::Failed:
            return tr("Writing %1 failed: %2")
                .arg(valueText(row, *row.requestedValue(set)), row.failure(set));
        case EditState::Unknown:
            return tr("Whether the drive took %1 is unknown: %2")
                .arg(valueText(row, *row.requestedValue(set)), row.failure(set));
        case EditState::Changed:
            return tr("Changed in the file: %1; save to keep it").arg(shown);
        case EditState::None:
            break;
        }
        const std::optional<qint32> raw = row.value(set);
        QString text;
        if (!raw) {
            text = description.error.isEmpty() ? tr("Not read")
                                               : tr("Not read: %1").arg(description.error);
        } else {
            text = tr("raw %1 = %2h").arg(*raw).arg(QString::number(quint32(*raw), 16).toUpper());
        }
        if (change)
            text += QLatin1Char('\n') + change->changeText();
        if (isStale(row)) {
            const QString time = QDateTime::fromMSecsSinceEpoch(row.readAtMs())
                                     .toString(QStringLiteral("HH:mm:ss"));
            text = tr("Last read %1; the drive is not answering").arg(time) + QLatin1Char('\n')
                   + text;
        }
        if (const QString refusal = m_state->editRefusal(row.address()); !refusal.isEmpty())
            text += QLatin1Char('\n') + refusal;
        return text;
    }
    switch (column) {
    case IdColumn:
    case NameColumn:
        if (!description.error.isEmpty())
            return tr("%1: %2").arg(ParameterId::hexAddress(row.address()), description.error);
        return ParameterId::hexAddress(row.address());
    case AccessColumn:
        return row.properties().describe().join(QLatin1Char('\n'));
    default:
        return {};
    }
}

QString ParameterModel::valueText(const ParameterRow &row, qint32 raw) const
{
    return m_raw ? QString::number(raw) : row.format().text(raw);
}

QString ParameterModel::accessText(const ParameterRow &row) const
{
    const ParameterProperties &properties = row.properties();
    const QString read = passwordLevelName(properties.readLevel());
    if (properties.isReadOnly())
        return tr("read-only (read: %1)").arg(read);
    return tr("read: %1, write: %2").arg(read, passwordLevelName(properties.writeLevel()));
}

bool ParameterModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const ParameterRow *row = index.model() == this ? rowAt(index) : nullptr;
    if (!row)
        return false;
    if (role == FavouriteRole) {
        setFavourite(row->address(), value.toBool());
        return true;
    }
    const int set = setOfColumn(index.column());
    if (role != Qt::EditRole || !row->hasCell(set))
        return false;

    std::optional<qint32> raw;
    if (value.typeId() == QMetaType::QString) {
        raw = (m_raw ? row->format().rawFormat() : row->format()).parse(value.toString());
    } else {
        bool ok = false;
        const qlonglong number = value.toLongLong(&ok);
        if (ok && number == qint32(number))
            raw = qint32(number);
    }
    if (!raw)
        return false;
    // A value the drive already holds is not written again.
    if (row->editState(set) == EditState::None && row->value(set) == raw)
        return true;
    return requestWrite(row->address(), quint8(1u << set), *raw);
}

Qt::ItemFlags ParameterModel::flags(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return Qt::NoItemFlags;
    const ParameterRow *row = rowAt(index);
    if (!row)
        return Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemNeverHasChildren;
    if (row->hasCell(setOfColumn(index.column())) && isEditable(*row))
        flags |= Qt::ItemIsEditable;
    return flags;
}

QVariant ParameterModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || section < 0 || section >= ColumnCount)
        return {};
    const int set = setOfColumn(section);
    const bool active = set >= 0 && set == m_state->activeSet();
    if (role == Qt::ToolTipRole && set >= 0) {
        QString text = set == 0
            ? tr("Set 0, or the one value of a parameter that is not set-programmable")
            : tr("Set %1").arg(set);
        if (active)
            text += QLatin1Char('\n') + tr("The drive runs with this set (active set, Fr.02)");
        return text;
    }
    if (role == Qt::FontRole && active) {
        QFont font;
        font.setBold(true);
        return font;
    }
    if (role != Qt::DisplayRole)
        return {};
    if (set == 0)
        return active ? tr("Value / set 0 (active)") : tr("Value / set 0");
    if (set > 0)
        return active ? tr("Set %1 (active)").arg(set) : tr("Set %1").arg(set);
    switch (section) {
    case IdColumn:
        return tr("Parameter");
    case NameColumn:
        return tr("Name");
    case MinimumColumn:
        return tr("Minimum");
    case MaximumColumn:
        return tr("Maximum");
    case DefaultColumn:
        return tr("Default");
    case UnitColumn:
        return tr("Unit");
    case AccessColumn:
        return tr("Access");
    default:
        return {};
    }
}

} // namespace DriveDesk
