#pragma once

#include "ScopeCursorReadout.h"

#include "scope/ScopeMeasurements.h"
#include "scope/ScopeSeries.h"

#include <QTableWidget>

#include <memory>
#include <optional>

namespace DriveDesk {

// A trace the measurements read besides the recording's channels (a math channel): shared,
// since the worker reads it while the window keeps it.
struct ScopeMeasuredSeries
{
    QString heading; // the column's heading
    std::shared_ptr<const ScopeSeries> series;
};

// The measurements between the two cursors (core's measureScope()) beside the chart: a column
// a drawn channel, a row a quantity, in the channel's unit and the language's number format.
// Hidden unless both cursors are placed.
//
// A window of a million samples takes tens of ms, so the measuring runs in the thread pool on
// a snapshot of the recording (ScopeSnapshot: the recording may grow or be replaced
// meanwhile). While one runs, only the newest request waits: cursors dragged across the chart
// are measured where they stop, not at every step on the way.
class ScopeMeasurementTable : public QTableWidget
{
    Q_OBJECT
public:
    enum Row {
        MinimumRow,
        MaximumRow,
        PeakToPeakRow,
        MeanRow,
        RmsRow,
        RiseTimeRow,
        RiseRateRow,
        FallTimeRow,
        FallRateRow,
        RowCount
    };

    explicit ScopeMeasurementTable(QWidget *parent = nullptr);

    // Measures the readout's channels (and `extra`) over the first `sampleCount` samples of
    // `recording` between its cursors; with fewer than two cursors clears and hides the table.
    void measure(const ScopeRecording &recording, qsizetype sampleCount,
                 const ScopeCursorReadout &readout, const QList<ScopeMeasuredSeries> &extra = {});
    // A measuring is running or waiting; measured() follows.
    bool isMeasuring() const { return m_running; }
    QString cellText(int row, int column) const;

signals:
    // The table shows the newest request's measurements.
    void measured();

private:
    struct Request;
    struct Column
    {
        QString heading;
        QString title; // with the unit, for the tool tip
        QString unit;
        std::optional<int> decimals; // the channel's scaling's; none: significant digits
        ScopeMeasurements values;
    };

    void start(std::shared_ptr<const Request> request);
    void showColumns(const QList<Column> &columns);
    void setCell(int row, int column, const QString &text);
    void fitHeight();

    bool m_running = false;
    std::shared_ptr<const Request> m_waiting; // the newest request, while another runs
    quint64 m_generation = 0; // requests made; a result of an older one is not shown
};

} // namespace DriveDesk
