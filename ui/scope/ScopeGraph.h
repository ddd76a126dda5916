#pragma once

#include "QCustomPlotInclude.h"

#include <vector>

namespace DriveDesk {

// A graph of decimated min/max columns (ScopeTraces and its kin fill it), drawn for a redraw
// a second several times over: QCustomPlot's own thinning and antialiasing are off, as the
// points are one or two a pixel already.
//
// On screen it draws its line itself, in one pass from the data to pixels, leaving out what
// adds no pixel: a point on the same pixel as the one before, and the middle of three on one
// pixel row (a trace drawn small on a shared axis is mostly such points, and the raster engine
// pays per segment).
//
// A column's min and max share a pixel column, so a noisy trace is mostly upright strokes,
// each the height of the noise; a derivative's noise fills the plot from top to bottom. The
// raster engine draws a stroke a pixel at a time. Where the strokes cover much of the plot,
// the graph works out the rows each pixel column's strokes cover, writes them into an image a
// row at a time and draws the image: the same pixels (to a pixel's rounding) in about half
// the time.
//
// Anything else (a vector export, a high-density screen or a scaled export, a fill, scatter
// points, a selection, a log axis, a pen but a thin solid opaque one) is drawn as QCustomPlot
// draws it.
class ScopeGraph : public QCPGraph
{
    Q_OBJECT
public:
    ScopeGraph(QCPAxis *keyAxis, QCPAxis *valueAxis);

    // A new graph of `plot` (which owns it) against the two axes, with a ScopeLegendItem if
    // the plot adds its plottables to the legend.
    static ScopeGraph *add(QCustomPlot *plot, QCPAxis *keyAxis, QCPAxis *valueAxis);

    // Whether the last draw() drew the line itself (tests: the quick way is taken on screen).
    bool drewItself() const { return m_drewItself; }

    // The graph's legend icon (ScopeLegendItem).
    void drawIcon(QCPPainter *painter, const QRectF &rect) const { drawLegendIcon(painter, rect); }

protected:
    void draw(QCPPainter *painter) override;

private:
    // Whether draw() may draw the line itself.
    bool drawsItself(const QCPPainter *painter) const;
    // The visible points in pixels, what adds no pixel left out, into m_pixels.
    void toPixels();
    // The rows each pixel column of `clip` is covered from and to; true if the strokes cover
    // enough of the plot for the image to pay.
    bool coverColumns(const QRect &clip);
    // Those columns drawn: the block that all of them cover as a rectangle, the rest written
    // into m_columns and drawn from there.
    void drawColumns(QCPPainter *painter, const QRect &clip, QRgb color);

    // Kept between redraws for their memory.
    QVector<QPointF> m_pixels;
    std::vector<qint32> m_tops;
    std::vector<qint32> m_bottoms;
    std::vector<quint32> m_counts;
    QImage m_columns;
    bool m_drewItself = false;
};

} // namespace DriveDesk
