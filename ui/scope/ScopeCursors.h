#pragma once

#include <QObject>

#include <array>
#include <optional>

class QCPItemStraightLine;
class QCPItemText;
class QCustomPlot;
class QMouseEvent;

namespace DriveDesk {

// The chart's two cursors: vertical lines at a time, labelled 1 and 2 at the top. The user
// places cursor 1 with Shift+left click and cursor 2 with Shift+right click, and drags either
// by its line; a mouse-placed cursor sits on a whole ms, as the samples do. Times are
// recording ms; the plot's time axis counts seconds from the origin.
// The items belong to the plot.
class ScopeCursors : public QObject
{
    Q_OBJECT
public:
    static constexpr int kCount = 2;
    static constexpr int kGrabPixels = 5; // how near a press must be to grab a line

    explicit ScopeCursors(QCustomPlot *plot);

    // The recording's first sample, time 0 on the axis.
    void setOriginMs(qint64 originMs);
    void setTime(int which, std::optional<double> timeMs);
    std::optional<double> time(int which) const { return m_timeMs[which]; }
    const std::array<std::optional<double>, kCount> &times() const { return m_timeMs; }
    // The cursor being dragged, if any.
    std::optional<int> dragged() const { return m_dragged; }

signals:
    // The user placed or dragged a cursor (the plot is not replotted: the receiver's call).
    void moved(int which);

private:
    void mousePressed(QMouseEvent *event);
    void mouseMoved(QMouseEvent *event);
    void mouseReleased(QMouseEvent *event);
    void placeAt(int which, double pixelX);
    std::optional<int> cursorNear(double pixelX) const;
    void updateItems(int which);

    QCustomPlot *m_plot = nullptr;
    std::array<QCPItemStraightLine *, kCount> m_lines {};
    std::array<QCPItemText *, kCount> m_labels {};
    std::array<std::optional<double>, kCount> m_timeMs;
    qint64 m_originMs = 0;
    std::optional<int> m_dragged;
    bool m_rangeDragWas = false;
};

} // namespace DriveDesk
