#include "ScopeCursors.h"

#include "QCustomPlotInclude.h"

#include <cmath>

namespace DriveDesk {

ScopeCursors::ScopeCursors(QCustomPlot *plot)
    : QObject(plot)
    , m_plot(plot)
{
    for (int which = 0; which < kCount; ++which) {
        auto *line = new QCPItemStraightLine(m_plot);
        line->setPen(
            QPen(QColor(0x40, 0x40, 0x40), 1, which == 0 ? Qt::DashLine : Qt::DashDotLine));
        line->setSelectable(false);
        // From the top of the axis rect to its bottom, whatever the value range.
        line->point1->setTypeY(QCPItemPosition::ptAxisRectRatio);
        line->point2->setTypeY(QCPItemPosition::ptAxisRectRatio);
        line->setVisible(false);
        m_lines[which] = line;

        auto *label = new QCPItemText(m_plot);
        label->setText(QString::number(which + 1));
        label->position->setTypeX(QCPItemPosition::ptPlotCoords);
        label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        label->setPositionAlignment(Qt::AlignHCenter | Qt::AlignTop);
        label->setBrush(Qt::white);
        label->setPen(QPen(QColor(0x40, 0x40, 0x40)));
        label->setPadding(QMargins(3, 1, 3, 1));
        label->setSelectable(false);
        label->setVisible(false);
        m_labels[which] = label;
    }
    connect(m_plot, &QCustomPlot::mousePress, this, &ScopeCursors::mousePressed);
    connect(m_plot, &QCustomPlot::mouseMove, this, &ScopeCursors::mouseMoved);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &ScopeCursors::mouseReleased);
}

void ScopeCursors::setOriginMs(qint64 originMs)
{
    m_originMs = originMs;
    for (int which = 0; which < kCount; ++which)
        updateItems(which);
}

void ScopeCursors::setTime(int which, std::optional<double> timeMs)
{
    m_timeMs[which] = timeMs;
    updateItems(which);
}

void ScopeCursors::mousePressed(QMouseEvent *event)
{
    std::optional<int> which;
    if (event->modifiers() & Qt::ShiftModifier) {
        if (event->button() == Qt::LeftButton)
            which = 0;
        else if (event->button() == Qt::RightButton)
            which = 1;
    } else if (event->button() == Qt::LeftButton) {
        which = cursorNear(event->position().x());
    }
    if (!which || !m_plot->axisRect()->rect().contains(event->position().toPoint()))
        return;
    // The press moves a cursor, not the view: the axis rect must not start a range drag.
    m_rangeDragWas = m_plot->interactions().testFlag(QCP::iRangeDrag);
    m_plot->setInteraction(QCP::iRangeDrag, false);
    m_dragged = which;
    placeAt(*which, event->position().x());
}

void ScopeCursors::mouseMoved(QMouseEvent *event)
{
    if (m_dragged) {
        placeAt(*m_dragged, event->position().x());
        return;
    }
    const bool over = event->buttons() == Qt::NoButton && cursorNear(event->position().x())
        && m_plot->axisRect()->rect().contains(event->position().toPoint());
    if (over)
        m_plot->setCursor(Qt::SizeHorCursor);
    else
        m_plot->unsetCursor();
}

void ScopeCursors::mouseReleased(QMouseEvent *)
{
    if (!m_dragged)
        return;
    m_dragged.reset();
    m_plot->setInteraction(QCP::iRangeDrag, m_rangeDragWas);
}

void ScopeCursors::placeAt(int which, double pixelX)
{
    const double seconds = m_plot->xAxis->pixelToCoord(pixelX);
    setTime(which, std::round(double(m_originMs) + seconds * 1000.0));
    emit moved(which);
}

std::optional<int> ScopeCursors::cursorNear(double pixelX) const
{
    std::optional<int> nearest;
    double nearestDistance = kGrabPixels + 1;
    for (int which = 0; which < kCount; ++which) {
        if (!m_timeMs[which])
            continue;
        const double x
            = m_plot->xAxis->coordToPixel((*m_timeMs[which] - double(m_originMs)) / 1000.0);
        const double distance = std::abs(x - pixelX);
        if (distance <= kGrabPixels && distance < nearestDistance) {
            nearest = which;
            nearestDistance = distance;
        }
    }
    return nearest;
}

void ScopeCursors::updateItems(int which)
{
    const bool shown = m_timeMs[which].has_value();
    m_lines[which]->setVisible(shown);
    m_labels[which]->setVisible(shown);
    if (!shown)
        return;
    const double seconds = (*m_timeMs[which] - double(m_originMs)) / 1000.0;
    m_lines[which]->point1->setCoords(seconds, 0);
    m_lines[which]->point2->setCoords(seconds, 1);
    m_labels[which]->position->setCoords(seconds, 0);
}

} // namespace DriveDesk
