#pragma once

#include "QCustomPlotInclude.h"

#include <QPixmap>

namespace DriveDesk {

class ScopeGraph;

// A scope graph's entry in the legend. QCustomPlot's own measures, lays out and draws its text
// glyph by glyph on every redraw, which with nine entries was a tenth of a roll tick; this one
// keeps its size and its text drawn in a pixmap until the name, the font or the colour
// changes. A vector export (PDF) draws it as QCustomPlot does.
class ScopeLegendItem : public QCPPlottableLegendItem
{
    Q_OBJECT
public:
    ScopeLegendItem(QCPLegend *legend, ScopeGraph *graph);

    QSize minimumOuterSizeHint() const override;

protected:
    void draw(QCPPainter *painter) override;

private:
    // The name's box for the font in use, measured again when either changed.
    void measure() const;
    // The text as it is drawn at this pixel ratio.
    const QPixmap &text(qreal pixelRatio);

    ScopeGraph *m_graph;
    mutable QString m_name;
    mutable QFont m_font;
    mutable QRect m_textRect;
    mutable bool m_textStale = true; // the name or the font changed since m_text was drawn
    QPixmap m_text;
    QColor m_textColor;
};

// Shows `graph` in its plot's legend (a ScopeLegendItem for a ScopeGraph), or takes it out.
void showInLegend(QCPGraph *graph, bool shown);

} // namespace DriveDesk
