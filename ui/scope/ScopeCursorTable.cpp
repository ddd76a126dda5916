#include "ScopeCursorTable.h"

#include <QHeaderView>
#include <QLocale>

#include <cmath>

namespace DriveDesk {

namespace {

QString number(std::optional<double> value, int decimals)
{
    return value ? QLocale().toString(*value, 'f', decimals) : QString();
}

// A math channel's value: no scaling says its decimals.
QString significant(std::optional<double> value)
{
    return value ? QLocale().toString(*value, 'g', 5) : QString();
}

} // namespace

ScopeCursorTable::ScopeCursorTable(QWidget *parent)
    : QTableWidget(0, ColumnCount, parent)
{
    setHorizontalHeaderLabels(
        { tr("Cursors"), tr("Cursor 1"), tr("Cursor 2"), tr("2 − 1", "cursor 2 minus cursor 1") });
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    for (int column = FirstColumn; column < ColumnCount; ++column)
        horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::ContiguousSelection);
    setFocusPolicy(Qt::NoFocus);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setSizeAdjustPolicy(QAbstractScrollArea::AdjustIgnored);
    setVisible(false);
}

void ScopeCursorTable::showReadout(const ScopeCursorReadout &readout, const ScopeChannels &channels,
                                   const QList<std::shared_ptr<const ScopeSeries>> &math,
                                   const ScopeCursorReadout &overlay,
                                   const ScopeChannels &overlayChannels)
{
    setVisible(readout.hasCursor());
    if (!readout.hasCursor())
        return;
    const int rows = 1 + int(readout.channels.size() + math.size() + overlay.channels.size());
    if (rowCount() != rows) {
        setRowCount(rows);
        fitHeight();
    }
    setCell(0, NameColumn, tr("Time [s]"));
    setCell(0, FirstColumn, number(readout.seconds(0), 3));
    setCell(0, SecondColumn, number(readout.seconds(1), 3));
    const std::optional<double> delta = readout.deltaMs();
    setCell(0, DifferenceColumn, number(delta ? std::optional(*delta / 1000.0) : std::nullopt, 3));
    showChannels(1, readout, channels);
    for (qsizetype m = 0; m < math.size(); ++m) {
        const ScopeSeries &series = *math.at(m);
        const int row = int(1 + readout.channels.size() + m);
        setCell(row, NameColumn, series.label());
        std::array<std::optional<double>, ScopeCursorReadout::kCursors> values;
        for (int cursor = 0; cursor < ScopeCursorReadout::kCursors; ++cursor) {
            // Whole ms, as the channels' samples are read.
            const qsizetype at = readout.timeMs[cursor]
                ? series.upperBound(std::floor(*readout.timeMs[cursor])) - 1
                : -1;
            if (at >= 0)
                values[std::size_t(cursor)] = series.values[std::size_t(at)];
            setCell(row, FirstColumn + cursor, significant(values[std::size_t(cursor)]));
        }
        setCell(row, DifferenceColumn,
                significant(values[0] && values[1] ? std::optional(*values[1] - *values[0])
                                                   : std::nullopt));
    }
    showChannels(int(1 + readout.channels.size() + math.size()), overlay, overlayChannels);
}

void ScopeCursorTable::showChannels(int firstRow, const ScopeCursorReadout &readout,
                                    const ScopeChannels &channels)
{
    for (int i = 0; i < readout.channels.size(); ++i) {
        const ScopeCursorReadout::Channel &row = readout.channels.at(i);
        const DisplayScaling &scaling = channels.at(row.channel).scaling;
        setCell(firstRow + i, NameColumn,
                row.unit.isEmpty()
                    ? row.title
                    : tr("%1 [%2]", "channel title and unit").arg(row.title, row.unit));
        for (int cursor = 0; cursor < ScopeCursorReadout::kCursors; ++cursor) {
            setCell(firstRow + i, FirstColumn + cursor,
                    row.raw[cursor] ? scaling.format(*row.raw[cursor], false) : QString());
        }
        setCell(firstRow + i, DifferenceColumn, number(row.difference(), scaling.decimals()));
    }
}

QString ScopeCursorTable::cellText(int row, int column) const
{
    const QTableWidgetItem *cell = item(row, column);
    return cell ? cell->text() : QString();
}

void ScopeCursorTable::setCell(int row, int column, const QString &text)
{
    QTableWidgetItem *cell = item(row, column);
    if (!cell) {
        cell = new QTableWidgetItem;
        if (column != NameColumn)
            cell->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(row, column, cell);
    }
    if (cell->text() != text)
        cell->setText(text);
}

void ScopeCursorTable::fitHeight()
{
    int height = horizontalHeader()->sizeHint().height() + 2 * frameWidth();
    for (int row = 0; row < rowCount(); ++row)
        height += verticalHeader()->sectionSize(row);
    setFixedHeight(height);
}

} // namespace DriveDesk
