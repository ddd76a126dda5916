// ScopeChart: what the keys and the mouse do.
#include "ScopeChart.h"

#include "QCustomPlotInclude.h"

#include <QKeyEvent>

namespace DriveDesk {

namespace {

constexpr double kZoomStep = 0.5; // + halves the visible span, - doubles it
constexpr double kPanStep = 0.1; // an arrow moves by a tenth of the view

} // namespace

QString ScopeChart::helpText()
{
    return tr("Wheel: zoom the time; Ctrl+wheel: zoom the values\n"
              "Drag: move the time; Ctrl+drag: move the values\n"
              "Shift+click: place cursor 1; Shift+right click: place cursor 2; drag a cursor to "
              "move it\n"
              "+ and -: zoom the time (with Ctrl: the values); Left and Right: move the time; "
              "Up and Down: move the values\n"
              "Home: the whole recording; End: follow the newest samples; A: fit the values; "
              "Space: freeze or go on; Esc: remove the cursors");
}

void ScopeChart::keyPressEvent(QKeyEvent *event)
{
    const bool values = event->modifiers() & Qt::ControlModifier;
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        values ? zoomValues(kZoomStep) : zoomTime(kZoomStep);
        break;
    case Qt::Key_Minus:
        values ? zoomValues(1 / kZoomStep) : zoomTime(1 / kZoomStep);
        break;
    case Qt::Key_Left:
        panTime(-kPanStep);
        break;
    case Qt::Key_Right:
        panTime(kPanStep);
        break;
    case Qt::Key_Up:
        panValues(kPanStep);
        break;
    case Qt::Key_Down:
        panValues(-kPanStep);
        break;
    case Qt::Key_Home:
        showAll();
        break;
    case Qt::Key_End:
        setFollow(true);
        break;
    case Qt::Key_A:
        autoScaleValues();
        break;
    case Qt::Key_Space:
        setFrozen(!isFrozen());
        break;
    case Qt::Key_Escape:
        setCursorTime(0, std::nullopt);
        setCursorTime(1, std::nullopt);
        break;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
}

void ScopeChart::wheelTurned(QWheelEvent *event)
{
    // Emitted before the axis rect zooms: Ctrl picks the value axes.
    m_plot->axisRect()->setRangeZoom(event->modifiers() & Qt::ControlModifier ? Qt::Vertical
                                                                              : Qt::Horizontal);
}

void ScopeChart::mousePressed(QMouseEvent *event)
{
    // Emitted before the axis rect starts a drag: Ctrl picks the value axes.
    m_plot->axisRect()->setRangeDrag(event->modifiers() & Qt::ControlModifier ? Qt::Vertical
                                                                              : Qt::Horizontal);
}

} // namespace DriveDesk
