#pragma once

#include "ScopeCursorReadout.h"

#include "scope/ScopeOverlay.h"

#include <QColor>
#include <QTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>

class QCPAxis;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemText;
class QCustomPlot;
class QMouseEvent;
class QWheelEvent;

namespace DriveDesk {

class ScopeCursorTable;
class ScopeCursors;
class ScopeMathTraces;
class ScopeOverlayTraces;
struct ScopeSeries;
class ScopeSeriesLevels;
class ScopeTraces;

// A span of recording time in ms, both ends included.
struct ScopeTimeRange
{
    qint64 fromMs = 0;
    qint64 toMs = 0;
    bool operator==(const ScopeTimeRange &) const = default;
};

// The scope's chart: a recording's four channels over time (seconds from its first sample),
// zoomable and pannable on both axes, with two cursors and their read-out.
//
// It never hands QCustomPlot the samples. Each redraw asks the recording's min/max levels for
// about one column per pixel of the visible time and draws each column's min and max, so a
// redraw costs the same for a thousand samples or a hundred million, and every peak shows.
// New samples only mark the chart stale (samplesAppended()); a timer redraws at most
// refreshRate() times a second.
//
// The view rolls (follows the newest samples, the last rollSeconds()), shows the whole
// recording as it grows (showAll()), or stays where it was put: a zoom or pan on the time axis
// with the mouse or keys leaves the first two (followChanged(false)). A zoom or pan on the
// values only stops fitting the value axes (autoScaleChanged(false)) and keeps the time view.
// Keys and mouse: helpText().
//
// The recording is owned elsewhere and lives in this thread; its owner tells the chart when
// it changed. Times in this API are recording ms (ScopeRecording's), unless named seconds.
class ScopeChart : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kChannels = 4;
    static constexpr int kDefaultRefreshHz = 30;
    static constexpr int kMinRefreshHz = 25;
    static constexpr int kMaxRefreshHz = 60;
    static constexpr double kDefaultRollSeconds = 10.0;

    explicit ScopeChart(QWidget *parent = nullptr);
    ~ScopeChart() override;

    // The recording shown (null: none). Not owned; it must outlive the chart or be replaced.
    void setRecording(const ScopeRecording *recording);
    const ScopeRecording *recording() const { return m_recording; }
    // The recording changed beyond new samples: channels, or cleared and started again. A
    // recording that starts again is shown whole unless the view rolls.
    void recordingChanged();
    // Samples were appended: drawn on the next tick of the refresh timer (not while frozen).
    void samplesAppended();

    // Redraws a second at most, clamped to 25..60.
    void setRefreshRate(int hz);
    int refreshRate() const { return m_refreshHz; }
    // What the timer does: brings the data up to date and replots now.
    void redrawNow();

    void setFollow(bool follow);
    bool follows() const { return m_view == View::Roll; }
    void setRollSeconds(double seconds);
    double rollSeconds() const { return m_rollSeconds; }
    // The whole recording, and it stays whole as samples come.
    void showAll();
    bool showsAll() const { return m_view == View::All; }
    // A fixed span, e.g. around a trigger (leaves roll mode).
    void showTimeRange(qint64 fromMs, qint64 toMs);
    // The recording ms of the samples inside the visible time span.
    ScopeTimeRange visibleTimeRange() const;
    // factor < 1 zooms in, about the middle of the view; a pan moves by a part of the view
    // (positive: later times, higher values). The time ones leave roll mode and the whole
    // view, the value ones stop the value axes' fitting.
    void zoomTime(double factor);
    void panTime(double fraction);
    void zoomValues(double factor);
    void panValues(double fraction);

    // Fits the value axes to the visible data on every redraw (on by default).
    void setAutoScale(bool on);
    bool autoScales() const { return m_autoScale; }
    // Fits the value axes now and keeps fitting them.
    void autoScaleValues();

    // A frozen view shows the samples there were when it froze; the recording goes on.
    void setFrozen(bool frozen);
    bool isFrozen() const { return m_frozenCount.has_value(); }

    void setChannelVisible(int channel, bool visible);
    bool isChannelVisible(int channel) const;
    void setChannelColor(int channel, const QColor &color);
    QColor channelColor(int channel) const;
    // An own value axis on the right (true) or the shared one on the left.
    void setChannelOwnAxis(int channel, bool own);
    bool hasChannelOwnAxis(int channel) const;

    // The math channels' traces (computed elsewhere from the recording), each drawn on a value
    // axis of its own; none: no math channels. With their min/max levels a redraw reads
    // O(columns) of each, not every value in view.
    void setMathSeries(const QList<std::shared_ptr<const ScopeSeries>> &series,
                       const QList<std::shared_ptr<const ScopeSeriesLevels>> &levels = {});
    QList<std::shared_ptr<const ScopeSeries>> mathSeries() const;
    ScopeMathTraces *mathTraces() const { return m_math.get(); }

    // A second recording drawn over this one to compare them (ScopeOverlayTraces), on the
    // time axis as `alignment` puts it, at the triggers by default; nullptr removes it. It
    // stays when the recording shown is replaced.
    void setOverlay(std::shared_ptr<const ScopeOverlay> overlay);
    std::shared_ptr<const ScopeOverlay> overlay() const;
    void setOverlayAlignment(ScopeOverlayAlignment alignment);
    // Where the overlay lies on the recording shown now; none without an overlay.
    std::optional<ScopeOverlayShift> overlayShift() const;
    ScopeOverlayTraces *overlayTraces() const { return m_overlay.get(); }
    // What the cursors read of the overlay (its drawn channels); empty without one.
    ScopeCursorReadout overlayReadout() const { return m_overlayReadout; }

    // Cursor 0 or 1 at a recording time (nullopt removes it). Named so as not to hide
    // QWidget::setCursor().
    void setCursorTime(int which, std::optional<double> timeMs);
    std::optional<double> cursorTime(int which) const;
    ScopeCursorReadout cursorReadout() const { return m_readout; }
    // The samples the chart shows and its cursors read: all of the recording's, or those
    // there were when the view froze.
    qsizetype shownSampleCount() const;
    // Where a single shot fired, marked on the chart (nullopt: no mark). A new recording
    // clears it.
    void setTriggerTime(std::optional<qint64> timeMs);
    std::optional<qint64> triggerTime() const { return m_triggerMs; }

    // The chart as it is shown, as a PNG image or a PDF page. False, with a message naming
    // the file in *error, when it cannot be written.
    bool savePng(const QString &path, QString *error = nullptr);
    bool savePdf(const QString &path, QString *error = nullptr);

    // What the keys and the mouse do (the plot's tool tip).
    static QString helpText();

    QCustomPlot *plot() const { return m_plot; }
    QCPGraph *graph(int channel) const;
    QCPAxis *valueAxis(int channel) const;
    ScopeCursorTable *cursorTable() const { return m_cursorTable; }

signals:
    void followChanged(bool follow);
    void autoScaleChanged(bool on);
    void frozenChanged(bool frozen);
    // The cursors moved, or the values under them changed.
    void cursorsChanged(const ScopeCursorReadout &readout);

protected:
    void keyPressEvent(QKeyEvent *event) override;

private:
    enum class View { Roll, All, Fixed };

    // ScopeChartView.cpp: the legend in a row of its own above the traces.
    void placeLegend();

    // What recordingChanged() does; a new recording also leaves a fixed view.
    void reread(bool newRecording);
    void setView(View view);
    void setTimeRange(double fromSeconds, double toSeconds);
    void timeRangeChanged();
    void valueRangeChanged();
    void connectValueAxes();
    void wheelTurned(QWheelEvent *event);
    void mousePressed(QMouseEvent *event);
    void applyView();
    void followOrigin();
    // Rolls the view on, decimates the visible span anew if stale, fits the values.
    void refreshData();
    // After QCustomPlot's layout step, before it draws.
    void layoutDone();
    void scheduleRedraw(); // on the refresh timer
    void replotSoon(); // with the next pass of the event loop
    void fitValueAxes();
    void updateReadout();
    // What updateReadout() needs of the overlay; true if it changed.
    bool readOverlay();
    void showCursorTable();
    void placeTriggerMark();
    void fitLegend();
    bool checkWritable(const QString &path, QString *error) const;

    const ScopeRecording *m_recording = nullptr;
    QCustomPlot *m_plot = nullptr;
    std::unique_ptr<ScopeTraces> m_traces;
    std::unique_ptr<ScopeMathTraces> m_math;
    std::unique_ptr<ScopeOverlayTraces> m_overlay;
    ScopeCursors *m_cursors = nullptr;
    ScopeCursorTable *m_cursorTable = nullptr;
    QCPItemStraightLine *m_triggerLine = nullptr;
    QCPItemText *m_triggerLabel = nullptr;
    std::optional<qint64> m_triggerMs;
    int m_refreshHz = kDefaultRefreshHz;
    QTimer m_refreshTimer;
    QTimer m_soonTimer;
    View m_view = View::Roll;
    double m_rollSeconds = kDefaultRollSeconds;
    bool m_autoScale = true;
    std::optional<qsizetype> m_frozenCount; // samples shown while frozen
    bool m_dataStale = true; // the graphs need decimating again
    int m_filledColumns = 0; // the columns of the last fill
    qsizetype m_filledCount = 0; // the samples there were at the last fill
    qint64 m_originMs = 0;
    // > 0 while the chart itself sets axis ranges: their rangeChanged is then not a user's
    // zoom or pan.
    int m_settingRanges = 0;
    ScopeCursorReadout m_readout;
    ScopeCursorReadout m_overlayReadout;
};

} // namespace DriveDesk
