#include "ScopeLegendItem.h"

#include "ScopeGraph.h"

#include <QFontMetrics>
#include <QPainter>

namespace DriveDesk {

ScopeLegendItem::ScopeLegendItem(QCPLegend *legend, ScopeGraph *graph)
    : QCPPlottableLegendItem(legend, graph)
    , m_graph(graph)
{ }

void ScopeLegendItem::measure() const
{
    const QFont font = getFont();
    if (m_graph->name() == m_name && font == m_font && !m_textRect.isNull())
        return;
    m_name = m_graph->name();
    m_font = font;
    // As QCPPlottableLegendItem measures it, so that the layout is the same.
    m_textRect = QFontMetrics(font).boundingRect(0, 0, 0, mParentLegend->iconSize().height(),
                                                 Qt::TextDontClip, m_name);
    m_textStale = true;
}

const QPixmap &ScopeLegendItem::text(qreal pixelRatio)
{
    measure();
    const QColor color = getTextColor();
    const QSize size(m_textRect.width(),
                     qMax(m_textRect.height(), mParentLegend->iconSize().height()));
    if (!m_textStale && m_text.devicePixelRatio() == pixelRatio && color == m_textColor)
        return m_text;
    m_textStale = false;
    m_textColor = color;
    m_text = QPixmap(size * pixelRatio);
    m_text.setDevicePixelRatio(pixelRatio);
    m_text.fill(Qt::transparent);
    QPainter painter(&m_text);
    painter.setFont(m_font);
    painter.setPen(color);
    painter.drawText(QRect(QPoint(0, 0), size), Qt::TextDontClip, m_name);
    return m_text;
}

QSize ScopeLegendItem::minimumOuterSizeHint() const
{
    measure();
    const QSize icon = mParentLegend->iconSize();
    return QSize(icon.width() + mParentLegend->iconTextPadding() + m_textRect.width()
                     + mMargins.left() + mMargins.right(),
                 qMax(m_textRect.height(), icon.height()) + mMargins.top() + mMargins.bottom());
}

void ScopeLegendItem::draw(QCPPainter *painter)
{
    if (painter->modes().testFlag(QCPPainter::pmVectorized)) {
        QCPPlottableLegendItem::draw(painter);
        return;
    }
    const QSize icon = mParentLegend->iconSize();
    const qreal pixelRatio = painter->device() ? painter->device()->devicePixelRatioF() : 1.0;
    // QCustomPlot draws the text from the top of the entry, as does this.
    painter->drawPixmap(QPoint(mRect.x() + icon.width() + mParentLegend->iconTextPadding(),
                               mRect.y()),
                        text(pixelRatio));
    const QRect iconRect(mRect.topLeft(), icon);
    painter->save();
    painter->setClipRect(iconRect, Qt::IntersectClip);
    m_graph->drawIcon(painter, iconRect);
    painter->restore();
    const QPen border = getIconBorderPen();
    if (border.style() != Qt::NoPen) {
        painter->setPen(border);
        painter->setBrush(Qt::NoBrush);
        painter->drawRect(iconRect);
    }
}

void showInLegend(QCPGraph *graph, bool shown)
{
    QCPLegend *legend = graph->parentPlot()->legend;
    QCPPlottableLegendItem *item = legend->itemWithPlottable(graph);
    auto *scopeGraph = qobject_cast<ScopeGraph *>(graph);
    // The plot puts a plain entry in for every new graph.
    const bool right = item && (!scopeGraph || qobject_cast<ScopeLegendItem *>(item));
    if (shown && right)
        return;
    if (item)
        legend->removeItem(item);
    if (!shown)
        return;
    if (scopeGraph)
        legend->addItem(new ScopeLegendItem(legend, scopeGraph));
    else
        graph->addToLegend();
}

} // namespace DriveDesk
