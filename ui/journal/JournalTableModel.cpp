#include "JournalTableModel.h"

#include <algorithm>

namespace DriveDesk {

namespace {

QList<JournalEntry> newestFirst(QList<JournalEntry> entries)
{
    std::reverse(entries.begin(), entries.end());
    return entries;
}

QString valueText(const JournalValue &value)
{
    if (!value.text.isEmpty())
        return value.text;
    return value.raw ? QString::number(*value.raw) : QString();
}

} // namespace

void JournalTableModel::setEntries(const QList<JournalEntry> &entries)
{
    beginResetModel();
    m_entries = newestFirst(entries);
    endResetModel();
}

void JournalTableModel::addNewer(const QList<JournalEntry> &entries)
{
    QList<JournalEntry> newer;
    for (const JournalEntry &entry : entries) {
        if (entry.id > newestId())
            newer << entry;
    }
    if (newer.isEmpty())
        return;
    beginInsertRows({}, 0, int(newer.size()) - 1);
    m_entries = newestFirst(newer) + m_entries;
    endInsertRows();
}

void JournalTableModel::addOlder(const QList<JournalEntry> &entries)
{
    QList<JournalEntry> older;
    for (const JournalEntry &entry : entries) {
        if (m_entries.isEmpty() || entry.id < oldestId())
            older << entry;
    }
    if (older.isEmpty())
        return;
    const int first = int(m_entries.size());
    beginInsertRows({}, first, first + int(older.size()) - 1);
    m_entries += newestFirst(older);
    endInsertRows();
}

qint64 JournalTableModel::newestId() const
{
    return m_entries.isEmpty() ? 0 : m_entries.constFirst().id;
}

qint64 JournalTableModel::oldestId() const
{
    return m_entries.isEmpty() ? 0 : m_entries.constLast().id;
}

const JournalEntry *JournalTableModel::entry(int row) const
{
    return row >= 0 && row < m_entries.size() ? &m_entries.at(row) : nullptr;
}

const JournalEntry *JournalTableModel::entryById(qint64 id) const
{
    for (const JournalEntry &entry : m_entries) {
        if (entry.id == id)
            return &entry;
    }
    return nullptr;
}

int JournalTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_entries.size());
}

int JournalTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString JournalTableModel::text(const JournalEntry &entry, int column) const
{
    switch (column) {
    case IdColumn:
        return QString::number(entry.id);
    case TimeColumn:
        return entry.time.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
    case UserColumn:
        return entry.user;
    case HostColumn:
        return entry.host;
    case ProgramColumn:
        return entry.program;
    case JobColumn:
        return entry.jobDescription;
    case DriveColumn:
        return entry.drive.name();
    case ParameterColumn:
        return entry.parameterId;
    case NameColumn:
        return entry.parameterName;
    case SetColumn:
        return entry.set ? QString::number(*entry.set) : tr("active");
    case BeforeColumn:
        return entry.password ? tr("(password)") : valueText(entry.before);
    case WrittenColumn:
        return entry.password ? tr("(password)") : valueText(entry.written);
    case ReadBackColumn:
        return valueText(entry.readBack);
    case OutcomeColumn:
        return entry.outcomeText();
    default:
        return {};
    }
}

QVariant JournalTableModel::data(const QModelIndex &index, int role) const
{
    const JournalEntry *shown = index.isValid() ? entry(index.row()) : nullptr;
    if (!shown)
        return {};
    switch (role) {
    case Qt::DisplayRole:
        return text(*shown, index.column());
    case Qt::ToolTipRole:
        if (index.column() == DriveColumn) {
            const QString link = shown->drive.address
                ? QStringLiteral("%1@%2").arg(shown->drive.link).arg(*shown->drive.address)
                : shown->drive.link;
            return tr("%1 on %2, software %3, serial number %4")
                .arg(shown->drive.kind, link, shown->drive.softwareVersion,
                     shown->drive.serialNumber);
        }
        if (index.column() == TimeColumn && shown->completedTime.isValid()) {
            return tr("Answered %1")
                .arg(shown->completedTime.toLocalTime().toString(QStringLiteral("HH:mm:ss.zzz")));
        }
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == IdColumn || index.column() == SetColumn)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case EntryIdRole:
        return shown->id;
    case SearchTextRole: {
        QStringList fields;
        for (int column = 0; column < ColumnCount; ++column)
            fields << text(*shown, column);
        return fields.join(QLatin1Char(' ')).toLower();
    }
    default:
        return {};
    }
}

QVariant JournalTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case IdColumn: return tr("Entry");
    case TimeColumn: return tr("Time");
    case UserColumn: return tr("User");
    case HostColumn: return tr("Host");
    case ProgramColumn: return tr("Program");
    case JobColumn: return tr("Job");
    case DriveColumn: return tr("Drive");
    case ParameterColumn: return tr("Parameter");
    case NameColumn: return tr("Name");
    case SetColumn: return tr("Set");
    case BeforeColumn: return tr("Before");
    case WrittenColumn: return tr("Written");
    case ReadBackColumn: return tr("Read back");
    case OutcomeColumn: return tr("Outcome");
    default: return {};
    }
}

} // namespace DriveDesk
