#include "ScopeMeasurementTable.h"

#include "client/WhenFinished.h"
#include "parameters/DisplayUnit.h"
#include "scope/ScopeMathDefinition.h"
#include "scope/ScopeSnapshot.h"

#include <QHeaderView>
#include <QLocale>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>
#include <utility>

namespace DriveDesk {

struct ScopeMeasurementTable::Request
{
    ScopeSnapshot snapshot;
    QList<int> channels;
    QList<ScopeMeasuredSeries> extra;
    double fromMs = 0;
    double toMs = 0;
    quint64 generation = 0;
};

namespace {

// Digits enough to tell values apart where no scaling says how many decimals: a math channel's.
constexpr int kSignificantDigits = 5;

// decimals < 0: none said, significant digits instead.
QString number(double value, int decimals)
{
    if (decimals < 0)
        return QLocale().toString(value, 'g', kSignificantDigits);
    return QLocale().toString(value, 'f', decimals);
}

} // namespace

ScopeMeasurementTable::ScopeMeasurementTable(QWidget *parent)
    : QTableWidget(RowCount, 0, parent)
{
    setVerticalHeaderLabels({ tr("Minimum"), tr("Maximum"), tr("Peak to peak"), tr("Mean"),
                              tr("RMS"), tr("Rise time"), tr("Rise rate"), tr("Fall time"),
                              tr("Fall rate") });
    verticalHeader()->setToolTip(tr("Between the cursors, both included. Mean and RMS of the "
                                    "line through the samples; rise and fall between 10 % and "
                                    "90 % of the span from minimum to maximum."));
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::ContiguousSelection);
    setFocusPolicy(Qt::NoFocus);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setSizeAdjustPolicy(QAbstractScrollArea::AdjustIgnored);
    fitHeight();
    setVisible(false);
}

void ScopeMeasurementTable::measure(const ScopeRecording &recording, qsizetype sampleCount,
                                    const ScopeCursorReadout &readout,
                                    const QList<ScopeMeasuredSeries> &extra)
{
    ++m_generation;
    if (!readout.timeMs[0] || !readout.timeMs[1]) {
        m_waiting.reset();
        setColumnCount(0);
        setVisible(false);
        return;
    }
    auto request = std::make_shared<Request>();
    request->snapshot = scopeSnapshot(recording, sampleCount);
    for (const ScopeCursorReadout::Channel &channel : readout.channels)
        request->channels << channel.channel;
    request->extra = extra;
    request->fromMs = *readout.timeMs[0];
    request->toMs = *readout.timeMs[1];
    request->generation = m_generation;
    if (m_running)
        m_waiting = std::move(request);
    else
        start(std::move(request));
}

void ScopeMeasurementTable::start(std::shared_ptr<const Request> request)
{
    m_running = true;
    const auto work = [request] {
        QList<Column> columns;
        const ScopeSnapshot &snapshot = request->snapshot;
        for (const int channel : request->channels) {
            const ScopeChannel &source = snapshot.channels.at(channel);
            Column column;
            column.heading = source.id.isEmpty() ? source.title(channel) : source.id;
            column.title = source.title(channel);
            column.unit = source.unit();
            if (source.scaling.isValid())
                column.decimals = source.scaling.decimals();
            column.values = measureScope(snapshot, channel, request->fromMs, request->toMs);
            columns << column;
        }
        for (const ScopeMeasuredSeries &extra : request->extra) {
            Column column;
            column.heading = extra.heading;
            column.title = extra.series->title;
            column.unit = extra.series->unit;
            column.values = measureScope(*extra.series, request->fromMs, request->toMs);
            columns << column;
        }
        return columns;
    };
    const quint64 generation = request->generation;
    const auto done = [this, generation](const QList<Column> &columns) {
        m_running = false;
        if (generation == m_generation)
            showColumns(columns);
        if (m_waiting)
            start(std::exchange(m_waiting, nullptr));
        else if (generation == m_generation)
            emit measured();
    };
    whenFinished(QtConcurrent::run(work), this, done, [done] { done({}); });
}

void ScopeMeasurementTable::showColumns(const QList<Column> &columns)
{
    setColumnCount(int(columns.size()));
    for (int c = 0; c < columns.size(); ++c) {
        const Column &column = columns.at(c);
        auto *header = new QTableWidgetItem(column.heading);
        header->setToolTip(column.unit.isEmpty()
                               ? column.title
                               : tr("%1 [%2]", "channel title and unit")
                                     .arg(column.title, column.unit));
        setHorizontalHeaderItem(c, header);
        const ScopeMeasurements &m = column.values;
        const int decimals = column.decimals.value_or(-1);
        // A mean or a rate is finer than the steps of the samples it comes from.
        const int finer = decimals < 0 ? -1 : decimals + 1;
        const QString rateUnit
            = scopeMathUnit(ScopeMathDefinition::Kind::Derivative, column.unit).symbol;
        const auto value = [&](double v, int places) {
            return m.samples > 0 ? withUnit(number(v, places), column.unit) : QString();
        };
        const auto time = [](const std::optional<ScopeTransition> &t) {
            return t ? withUnit(QLocale().toString(t->durationMs(), 'f', 1), tr("ms")) : QString();
        };
        const auto rate = [&](const std::optional<ScopeTransition> &t) {
            return t && t->ratePerSecond ? withUnit(number(*t->ratePerSecond, finer), rateUnit)
                                         : QString();
        };
        setCell(MinimumRow, c, value(m.minimum, decimals));
        setCell(MaximumRow, c, value(m.maximum, decimals));
        setCell(PeakToPeakRow, c, value(m.peakToPeak(), decimals));
        setCell(MeanRow, c, value(m.mean, finer));
        setCell(RmsRow, c, value(m.rms, finer));
        setCell(RiseTimeRow, c, time(m.rise));
        setCell(RiseRateRow, c, rate(m.rise));
        setCell(FallTimeRow, c, time(m.fall));
        setCell(FallRateRow, c, rate(m.fall));
    }
    fitHeight();
    setVisible(!columns.isEmpty());
}

QString ScopeMeasurementTable::cellText(int row, int column) const
{
    const QTableWidgetItem *cell = item(row, column);
    return cell ? cell->text() : QString();
}

void ScopeMeasurementTable::setCell(int row, int column, const QString &text)
{
    QTableWidgetItem *cell = item(row, column);
    if (!cell) {
        cell = new QTableWidgetItem;
        cell->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(row, column, cell);
    }
    if (cell->text() != text)
        cell->setText(text);
}

void ScopeMeasurementTable::fitHeight()
{
    int height = horizontalHeader()->sizeHint().height() + 2 * frameWidth();
    for (int row = 0; row < rowCount(); ++row)
        height += verticalHeader()->sectionSize(row);
    setFixedHeight(height);
}

} // namespace DriveDesk
