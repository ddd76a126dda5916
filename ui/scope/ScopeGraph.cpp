#include "ScopeGraph.h"

#include "ScopeLegendItem.h"

#include <QPaintEngine>

#include <algorithm>
#include <cmath>
#include <limits>

namespace DriveDesk {

namespace {

// The image is written eight columns at a time: a loop of a fixed count the compiler turns
// into vector instructions.
constexpr int kLanes = 8;

// A stroke costs the raster engine about four times what a pixel of the image costs
// (bench_scope_view): the image pays when the strokes cover a quarter of it.
constexpr qint64 kStrokeCost = 4;

// One column in this many may stay out of the block that drawColumns() fills as rectangles.
constexpr std::size_t kExceptions = 50;

// One row of the image: the colour where row y lies within a column's `count` rows from its
// `top`, transparent elsewhere. Out of line, with pointers that share no memory, so that the
// compiler can write it with vector instructions. `width` is a multiple of kLanes.
void fillRow(quint32 *__restrict line, const qint32 *__restrict tops,
             const quint32 *__restrict counts, int width, qint32 y, quint32 paint)
{
    for (int x = 0; x < width; x += kLanes) {
        for (int lane = 0; lane < kLanes; ++lane) {
            const quint32 covered = quint32(y) - quint32(tops[x + lane]) < counts[x + lane];
            line[x + lane] = paint & (0u - covered);
        }
    }
}

// The pixel a coordinate falls on: an aliased line through x = 2.5 or x = 2 lights pixel 2.
// (std::floor is a library call per point.) Valid within int's range.
int pixelOf(double coordinate)
{
    const int truncated = int(coordinate);
    return truncated - (coordinate < double(truncated) ? 1 : 0);
}

} // namespace

ScopeGraph::ScopeGraph(QCPAxis *keyAxis, QCPAxis *valueAxis)
    : QCPGraph(keyAxis, valueAxis)
{
    setAdaptiveSampling(false);
    setAntialiased(false);
}

ScopeGraph *ScopeGraph::add(QCustomPlot *plot, QCPAxis *keyAxis, QCPAxis *valueAxis)
{
    // The plot takes the graph in QCPGraph's constructor; addGraph() would make a plain one.
    auto *graph = new ScopeGraph(keyAxis, valueAxis);
    graph->setName(QStringLiteral("Graph %1").arg(plot->graphCount()));
    // The plot gave it a plain entry in the legend if it adds its plottables there.
    if (plot->legend->hasItemWithPlottable(graph))
        showInLegend(graph, true);
    return graph;
}

bool ScopeGraph::coverColumns(const QRect &clip)
{
    const QVector<QPointF> &lines = m_pixels;
    // The strokes' heights first, which is all a light trace costs here (a gap adds none).
    double strokes = 0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const double height = std::abs(lines.at(i).y() - lines.at(i - 1).y());
        if (std::isfinite(height))
            strokes += height;
    }
    const qint64 area = qint64(clip.width()) * clip.height();
    if (!(strokes * kStrokeCost >= double(area)))
        return false;

    const int width = (clip.width() + kLanes - 1) / kLanes * kLanes;
    // An empty column: its top below its bottom.
    m_tops.assign(std::size_t(width), std::numeric_limits<qint32>::max());
    m_bottoms.assign(std::size_t(width), std::numeric_limits<qint32>::min());
    const double top = clip.top();
    const double bottom = clip.bottom();
    const double left = clip.left();
    const double right = clip.right();
    const auto cover = [&](int column, double y0, double y1) {
        if (column < clip.left() || column > clip.right())
            return;
        // Clamped: far-off values (a zoomed value axis) stay inside int, and the image short.
        const auto row = [&](double y) { return qint32(pixelOf(std::clamp(y, top, bottom))); };
        const std::size_t at = std::size_t(column - clip.left());
        m_tops[at] = std::min(m_tops[at], row(std::min(y0, y1)));
        m_bottoms[at] = std::max(m_bottoms[at], row(std::max(y0, y1)));
    };
    for (qsizetype i = 1; i < lines.size(); ++i) {
        QPointF a = lines.at(i - 1);
        QPointF b = lines.at(i);
        // QCustomPlot marks a gap in the data with a NaN point.
        if (!std::isfinite(a.x()) || !std::isfinite(a.y()) || !std::isfinite(b.x())
            || !std::isfinite(b.y()))
            continue;
        if (a.x() > b.x())
            std::swap(a, b);
        if (b.x() < left || a.x() >= right + 1)
            continue;
        const int firstColumn = pixelOf(std::max(a.x(), left));
        const int lastColumn = pixelOf(std::min(b.x(), right));
        if (firstColumn == lastColumn || a.x() == b.x()) {
            cover(firstColumn, a.y(), b.y());
            continue;
        }
        // The rows the segment crosses within each pixel column it passes.
        const double slope = (b.y() - a.y()) / (b.x() - a.x());
        const auto yAt
            = [&](double x) { return a.y() + (std::clamp(x, a.x(), b.x()) - a.x()) * slope; };
        for (int column = firstColumn; column <= lastColumn; ++column)
            cover(column, yAt(column), yAt(column + 1.0));
    }
    // The rows each column covers, from its top (none for an empty column).
    m_counts.resize(std::size_t(width));
    qint64 pixels = 0;
    for (std::size_t x = 0; x < std::size_t(width); ++x) {
        const bool empty = m_tops[x] > m_bottoms[x];
        m_counts[x] = empty ? 0 : quint32(m_bottoms[x] - m_tops[x] + 1);
        if (empty)
            m_tops[x] = 0;
        pixels += m_counts[x];
    }
    return pixels * kStrokeCost >= area;
}

void ScopeGraph::drawColumns(QCPPainter *painter, const QRect &clip, QRgb color)
{
    const int width = int(m_tops.size());
    std::vector<qint32> tops;
    std::vector<qint32> bottoms;
    tops.reserve(std::size_t(width));
    bottoms.reserve(std::size_t(width));
    for (std::size_t x = 0; x < std::size_t(width); ++x) {
        if (m_counts[x] > 0) {
            tops.push_back(m_tops[x]);
            bottoms.push_back(m_tops[x] + qint32(m_counts[x]) - 1);
        }
    }
    if (tops.empty())
        return;
    const qint32 first = *std::min_element(tops.begin(), tops.end());
    const qint32 last = *std::max_element(bottoms.begin(), bottoms.end());
    // The block of rows that nearly every column covers (a noisy trace's middle) is filled as
    // rectangles, not written into the image: those between the columns that do not cover it
    // (an edge, a quiet stretch) and for each of those what it covers of it.
    const std::size_t exceptions = tops.size() / kExceptions;
    std::nth_element(tops.begin(), tops.end() - 1 - qsizetype(exceptions), tops.end());
    std::nth_element(bottoms.begin(), bottoms.begin() + qsizetype(exceptions), bottoms.end());
    qint32 blockTop = *(tops.end() - 1 - qsizetype(exceptions));
    qint32 blockBottom = bottoms[exceptions];
    if (blockTop > blockBottom) {
        blockTop = last + 1;
        blockBottom = last;
    }
    const QColor solid = QColor::fromRgba(color);
    int run = -1; // the first column of the run of columns that cover the block
    const auto endRun = [&](int x) {
        if (run >= 0) {
            painter->fillRect(QRect(clip.left() + run, blockTop, x - run,
                                    blockBottom - blockTop + 1),
                              solid);
        }
        run = -1;
    };
    for (int x = 0; x < width && blockTop <= blockBottom; ++x) {
        const std::size_t at = std::size_t(x);
        const qint32 top = m_tops[at];
        const qint32 bottom = top + qint32(m_counts[at]) - 1;
        if (m_counts[at] > 0 && top <= blockTop && bottom >= blockBottom) {
            if (run < 0)
                run = x;
            continue;
        }
        endRun(x);
        const qint32 from = std::max(top, blockTop);
        const qint32 to = std::min(bottom, blockBottom);
        if (m_counts[at] > 0 && from <= to)
            painter->fillRect(QRect(clip.left() + x, from, 1, to - from + 1), solid);
    }
    endRun(width);

    // The rows above the block, then those below it, one after the other in the image.
    const int above = blockTop - first;
    const int below = last - blockBottom;
    if (m_columns.width() != width || m_columns.height() < above + below)
        m_columns = QImage(width, clip.height() + 2, QImage::Format_ARGB32_Premultiplied);
    const quint32 paint = qPremultiply(color);
    for (int row = 0; row < above; ++row) {
        fillRow(reinterpret_cast<quint32 *>(m_columns.scanLine(row)), m_tops.data(),
                m_counts.data(), width, first + row, paint);
    }
    for (int row = 0; row < below; ++row) {
        fillRow(reinterpret_cast<quint32 *>(m_columns.scanLine(above + row)), m_tops.data(),
                m_counts.data(), width, blockBottom + 1 + row, paint);
    }
    if (above > 0)
        painter->drawImage(QPoint(clip.left(), first), m_columns, QRect(0, 0, width, above));
    if (below > 0) {
        painter->drawImage(QPoint(clip.left(), blockBottom + 1), m_columns,
                           QRect(0, above, width, below));
    }
}

bool ScopeGraph::drawsItself(const QCPPainter *painter) const
{
    const QCPAxis *key = mKeyAxis.data();
    const QCPAxis *value = mValueAxis.data();
    // Pixels of the device, one to one: not a high-density screen's buffer or a scaled export,
    // where a pixel of the plot is several of the device's.
    return key && value && painter->paintEngine()
        && painter->paintEngine()->type() == QPaintEngine::Raster
        && !painter->modes().testFlag(QCPPainter::pmVectorized) && !painter->antialiasing()
        && painter->device() && painter->device()->devicePixelRatioF() == 1.0
        && painter->transform().isIdentity()
        && mLineStyle == lsLine && mScatterStyle.isNone() && mBrush.style() == Qt::NoBrush
        && mSelection.isEmpty() && mPen.style() == Qt::SolidLine && mPen.widthF() <= 1.0
        && mPen.color().alpha() == 255 && key->orientation() == Qt::Horizontal
        && key->scaleType() == QCPAxis::stLinear && value->scaleType() == QCPAxis::stLinear;
}

void ScopeGraph::toPixels()
{
    m_pixels.clear();
    QCPGraphDataContainer::const_iterator begin;
    QCPGraphDataContainer::const_iterator end;
    getVisibleDataBounds(begin, end, QCPDataRange(0, dataCount()));
    // Both axes are linear: a pixel is an offset and a factor away from a coordinate.
    const QCPAxis *key = mKeyAxis.data();
    const QCPAxis *value = mValueAxis.data();
    const double keyAt0 = key->coordToPixel(0);
    const double keyPerUnit = key->coordToPixel(1) - keyAt0;
    const double valueAt0 = value->coordToPixel(0);
    const double valuePerUnit = value->coordToPixel(1) - valueAt0;
    // Whether a point adds a pixel is judged on the pixels the points fall on; the points
    // drawn keep their own coordinates, so that the lines are those QCustomPlot would draw.
    // A far-off point (a zoomed axis) is always kept.
    constexpr double kFar = 1 << 24;
    constexpr int kNone = std::numeric_limits<int>::min();
    int lastX = kNone;
    int lastY = kNone;
    bool rowRun = false; // the last two points kept lie on one pixel row
    m_pixels.reserve(dataCount() + 2);
    for (auto it = begin; it != end; ++it) {
        const double x = keyAt0 + it->key * keyPerUnit;
        const double y = valueAt0 + it->value * valuePerUnit;
        if (!(std::abs(x) < kFar) || !(std::abs(y) < kFar)) {
            // NaN (a gap, which QCustomPlot's drawPolyline() leaves open) or far off.
            m_pixels.append(std::isnan(x) || std::isnan(y) ? QPointF(x, qQNaN()) : QPointF(x, y));
            lastX = kNone;
            lastY = kNone;
            rowRun = false;
            continue;
        }
        const int pixelX = pixelOf(x);
        const int pixelY = pixelOf(y);
        if (pixelY == lastY && pixelX == lastX)
            continue;
        const bool sameRow = pixelY == lastY;
        if (sameRow && rowRun) {
            m_pixels.data()[m_pixels.size() - 1] = QPointF(x, y);
        } else {
            m_pixels.append(QPointF(x, y));
            rowRun = sameRow;
        }
        lastX = pixelX;
        lastY = pixelY;
    }
}

void ScopeGraph::draw(QCPPainter *painter)
{
    m_drewItself = drawsItself(painter);
    if (!m_drewItself) {
        QCPGraph::draw(painter);
        return;
    }
    if (mKeyAxis->range().size() <= 0 || mDataContainer->isEmpty())
        return;
    toPixels();
    const QRect clip = clipRect();
    if (!clip.isEmpty() && coverColumns(clip)) {
        drawColumns(painter, clip, mPen.color().rgba());
        return;
    }
    applyDefaultAntialiasingHint(painter);
    painter->setPen(mPen);
    painter->setBrush(Qt::NoBrush);
    drawPolyline(painter, m_pixels);
}

} // namespace DriveDesk
