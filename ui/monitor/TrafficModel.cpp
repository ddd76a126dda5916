#include "TrafficModel.h"

#include <QApplication>
#include <QFontDatabase>
#include <QIcon>
#include <QPalette>
#include <QStyle>

#include <algorithm>

namespace DriveDesk {

namespace {

// A hint of red over the palette's base colour: keeps the base's lightness, so the text stays
// readable in light and dark themes alike.
QColor errorBackground()
{
    const QColor base = QGuiApplication::palette().color(QPalette::Base);
    const QColor tint(230, 0, 0);
    constexpr float amount = 0.3F;
    return QColor::fromRgbF(base.redF() * (1 - amount) + tint.redF() * amount,
                            base.greenF() * (1 - amount) + tint.greenF() * amount,
                            base.blueF() * (1 - amount) + tint.blueF() * amount);
}

bool isError(const TrafficEntry &entry)
{
    return entry.record.kind == TrafficRecord::Kind::Error;
}

} // namespace

TrafficModel::TrafficModel(QObject *parent)
    : QAbstractTableModel(parent)
{
    m_batchTimer.setSingleShot(true);
    m_batchTimer.setInterval(kBatchIntervalMs);
    connect(&m_batchTimer, &QTimer::timeout, this, &TrafficModel::onTick);
}

void TrafficModel::setCapacity(int capacity)
{
    m_capacity = std::max(capacity, 1);
    if (m_rows.size() > std::size_t(m_capacity))
        dropOldestRows(m_rows.size() - std::size_t(m_capacity));
    while (m_waiting.size() > std::size_t(m_capacity)) {
        m_waiting.pop_front();
        ++m_dropped;
    }
    emit countsChanged();
}

void TrafficModel::setDrive(std::shared_ptr<const DriveDescription> drive)
{
    m_drive = std::move(drive);
}

const QString &TrafficModel::meaning(int row) const
{
    TrafficEntry &item = m_rows[std::size_t(row)];
    if (!item.described) {
        item.meaning = TrafficFormat::meaning(item, item.drive.get());
        item.described = true;
    }
    return item.meaning;
}

void TrafficModel::append(const TrafficRecord &record)
{
    append(record, m_protocol);
}

void TrafficModel::append(const TrafficRecord &record, Protocol protocol)
{
    m_waiting.push_back({ record, protocol, m_drive, {}, false });
    ++m_received;
    // More waiting than the rows can hold: the oldest would be pushed out on arrival anyway.
    if (m_waiting.size() > std::size_t(m_capacity)) {
        m_waiting.pop_front();
        ++m_dropped;
    }
    if (!m_batchTimer.isActive())
        m_batchTimer.start();
}

void TrafficModel::onTick()
{
    if (m_paused)
        emit countsChanged();
    else
        flush();
}

void TrafficModel::flush()
{
    if (m_paused || m_waiting.empty())
        return;
    m_batchTimer.stop();
    emit batchAboutToBeShown();

    // m_waiting never holds more than the capacity, so the oldest rows make room for it all.
    const std::size_t room
        = std::size_t(m_capacity) - std::min(m_rows.size(), std::size_t(m_capacity));
    if (m_waiting.size() > room)
        dropOldestRows(m_waiting.size() - room);

    const int first = int(m_rows.size());
    beginInsertRows({}, first, first + int(m_waiting.size()) - 1);
    std::move(m_waiting.begin(), m_waiting.end(), std::back_inserter(m_rows));
    m_waiting.clear();
    endInsertRows();

    emit batchShown();
    emit countsChanged();
}

void TrafficModel::dropOldestRows(std::size_t count)
{
    if (count == 0)
        return;
    beginRemoveRows({}, 0, int(count) - 1);
    m_rows.erase(m_rows.begin(), m_rows.begin() + qsizetype(count));
    m_dropped += qint64(count);
    endRemoveRows();
}

void TrafficModel::setPaused(bool paused)
{
    if (m_paused == paused)
        return;
    if (paused)
        flush();
    m_paused = paused;
    if (!paused)
        flush();
    emit countsChanged();
}

void TrafficModel::clear()
{
    beginResetModel();
    m_rows.clear();
    m_waiting.clear();
    m_dropped = 0;
    m_received = 0;
    m_batchTimer.stop();
    endResetModel();
    emit countsChanged();
}

int TrafficModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int TrafficModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TrafficModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const TrafficEntry &item = entry(index.row());
    const TrafficRecord &record = item.record;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case TimeColumn:
            return TrafficFormat::time(record.msecsSinceEpoch);
        case DirectionColumn:
            return TrafficFormat::direction(record.kind);
        case BytesColumn:
            return TrafficFormat::hex(record.bytes);
        case CharactersColumn:
            return TrafficFormat::characters(item);
        case MeaningColumn:
            return meaning(index.row());
        }
        break;
    case Qt::ToolTipRole:
        if (index.column() == MeaningColumn)
            meaning(index.row()); // made where it was not yet
        return toolTip(item, index.column());
    case Qt::BackgroundRole:
        if (isError(item))
            return errorBackground();
        break;
    case Qt::DecorationRole:
        if (isError(item) && index.column() == DirectionColumn && QApplication::style())
            return QApplication::style()->standardIcon(QStyle::SP_MessageBoxWarning);
        break;
    case Qt::FontRole:
        if (index.column() == BytesColumn || index.column() == CharactersColumn)
            return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        break;
    case KindRole:
        return int(record.kind);
    case TimestampRole:
        return record.msecsSinceEpoch;
    case BytesRole:
        return record.bytes;
    default:
        break;
    }
    return {};
}

QVariant TrafficModel::toolTip(const TrafficEntry &entry, int column) const
{
    const TrafficRecord &record = entry.record;
    switch (column) {
    case TimeColumn:
        return TrafficFormat::time(record.msecsSinceEpoch, TrafficFormat::Clock::DateAndTime);
    case BytesColumn:
    case CharactersColumn: {
        if (record.bytes.isEmpty())
            return {};
        // The whole telegram, however narrow the column.
        QStringList lines { TrafficFormat::hex(record.bytes) };
        const QString characters = TrafficFormat::characters(entry);
        if (!characters.isEmpty())
            lines << characters;
        lines << tr("%n byte(s)", nullptr, int(record.bytes.size()));
        return lines.join(QLatin1Char('\n'));
    }
    case MeaningColumn: {
        return entry.meaning.isEmpty() ? QVariant() : QVariant(entry.meaning);
    }
    default:
        break;
    }
    return {};
}

QVariant TrafficModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole || section < 0
        || section >= ColumnCount)
        return {};
    return TrafficFormat::fieldName(TrafficFormat::Field(section));
}

} // namespace DriveDesk
