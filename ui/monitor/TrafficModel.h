#pragma once

#include "TrafficFormat.h"

#include <QAbstractTableModel>
#include <QTimer>

#include <deque>
#include <memory>

namespace DriveDesk {

// The telegrams of the monitor, oldest first, at most capacity() of them: beyond that the
// oldest are dropped and counted. Records arrive one by one (append) but are shown in batches
// on a coalescing timer, so a fast scan costs the view at most one insertion per tick. While
// paused, records wait (up to the capacity, the oldest beyond it dropped and counted) and are
// shown on resume. Lives in the GUI thread.
class TrafficModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        TimeColumn = TrafficFormat::Time,
        DirectionColumn = TrafficFormat::Direction,
        BytesColumn = TrafficFormat::Bytes,
        CharactersColumn = TrafficFormat::Characters,
        MeaningColumn = TrafficFormat::Meaning,
        ColumnCount = TrafficFormat::FieldCount
    };
    enum Role {
        KindRole = Qt::UserRole + 1, // int: TrafficRecord::Kind
        TimestampRole, // qint64: milliseconds since the epoch
        BytesRole, // QByteArray: the telegram as on the wire
    };

    static constexpr int kDefaultCapacity = 20000;
    static constexpr int kBatchIntervalMs = 33; // about 30 batches a second at most

    explicit TrafficModel(QObject *parent = nullptr);

    // At least 1. Shrinking drops the oldest rows (counted).
    void setCapacity(int capacity);
    int capacity() const { return m_capacity; }
    // The protocol of the records appended from now on (how their characters read).
    void setProtocol(Protocol protocol) { m_protocol = protocol; }
    Protocol protocol() const { return m_protocol; }

    // Takes a record; it is shown with the next batch, or on resume while paused.
    void append(const DriveDesk::TrafficRecord &record);
    // A record of another protocol than setProtocol()'s (a client besides the session's).
    void append(const DriveDesk::TrafficRecord &record, Protocol protocol);
    // Shows what is waiting now instead of on the next tick (nothing while paused).
    void flush();
    // Pausing first shows what arrived before it; resuming shows what arrived during it.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Forgets every row, every waiting record and the counts.
    void clear();

    // The drive whose parameters the meanings of the telegrams captured from now on name (by id,
    // name and value as shown); null before a scan: ids from the address and raw values. Rows
    // already captured keep the drive of their time.
    void setDrive(std::shared_ptr<const DriveDescription> drive);
    const DriveDescription *drive() const { return m_drive.get(); }

    const TrafficEntry &entry(int row) const { return m_rows[std::size_t(row)]; }
    // What the meaning column shows, made on the row's first use and kept.
    const QString &meaning(int row) const;
    // Records waiting to be shown: arrived while paused, or since the last batch.
    int waitingCount() const { return int(m_waiting.size()); }
    // Records dropped because more arrived than the capacity holds, since the last clear.
    qint64 droppedCount() const { return m_dropped; }
    // Records appended since the last clear, dropped ones included.
    qint64 receivedCount() const { return m_received; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    // Around the row changes of a batch, for views that follow the newest row.
    void batchAboutToBeShown();
    void batchShown();
    // The counts changed: at most once a batch interval while records arrive.
    void countsChanged();

private:
    void onTick();
    void dropOldestRows(std::size_t count);
    QVariant toolTip(const TrafficEntry &entry, int column) const;

    // Mutable: a row's meaning is made when it is first needed (meaning()).
    mutable std::deque<TrafficEntry> m_rows;
    std::shared_ptr<const DriveDescription> m_drive;
    std::deque<TrafficEntry> m_waiting;
    QTimer m_batchTimer;
    int m_capacity = kDefaultCapacity;
    Protocol m_protocol = Protocol::Hsp5;
    bool m_paused = false;
    qint64 m_dropped = 0;
    qint64 m_received = 0;
};

} // namespace DriveDesk
