#pragma once

#include "ScopeCursorReadout.h"

#include "scope/ScopeSeries.h"

#include <QTableWidget>

#include <memory>

namespace DriveDesk {

// The cursors' read-out under the chart: a row for the time (seconds from the first sample)
// and one per drawn channel, math channel and overlay channel, each with its value at cursor 1,
// at cursor 2 and the difference.
// Hidden while no cursor is placed.
class ScopeCursorTable : public QTableWidget
{
    Q_OBJECT
public:
    enum Column { NameColumn, FirstColumn, SecondColumn, DifferenceColumn, ColumnCount };

    explicit ScopeCursorTable(QWidget *parent = nullptr);

    // Values shown as the channels' scalings format them; the difference with as many
    // decimals.
    // A math channel's value is its trace's at or before the cursor's time, as a channel's.
    // An overlay's channels (`overlay`, read by ScopeOverlayTraces::read(), its recording's
    // `overlayChannels`) follow, as its scalings format them.
    void showReadout(const ScopeCursorReadout &readout, const ScopeChannels &channels,
                     const QList<std::shared_ptr<const ScopeSeries>> &math = {},
                     const ScopeCursorReadout &overlay = {},
                     const ScopeChannels &overlayChannels = {});
    // The text of a cell ("" for an empty one).
    QString cellText(int row, int column) const;

private:
    void showChannels(int firstRow, const ScopeCursorReadout &readout,
                      const ScopeChannels &channels);
    void setCell(int row, int column, const QString &text);
    void fitHeight();
};

} // namespace DriveDesk
