#pragma once

#include "scope/ScopeSpectrum.h"

#include <QTimer>
#include <QWidget>

#include <memory>
#include <optional>

class QAction;
class QCheckBox;
class QComboBox;
class QCustomPlot;
class QLabel;
class QMenu;
class QTableWidget;

namespace DriveDesk {

class ScopeChart;
class ScopeDock;
class ScopeMathChannels;
class ScopeSpectrumPlot;

// The amplitude spectrum of one channel (recorded or math) over the chart's view or between
// its cursors, in a window of its own beside the scope: the amplitudes over frequency, and the
// highest peaks in a table. How it is made is core's (computeScopeSpectrum(), docs/scope.md).
//
// A million samples take tens of ms, so each spectrum is made in the thread pool from a
// snapshot of the recording (or the math channel's shared trace). While one runs only the
// newest request waits, and a result is shown only if no newer request was made since. While
// the window is shown it follows the view, the cursors and the math channels, at most every
// kFollowMs: a rolling view is followed at that pace, not at every redraw.
class ScopeSpectrumView : public QWidget
{
    Q_OBJECT
public:
    enum class Range { View, Cursors };
    static constexpr int kFollowMs = 200;

    ScopeSpectrumView(ScopeChart *chart, ScopeMathChannels *math, QWidget *parent = nullptr);
    ~ScopeSpectrumView() override;

    // "Spectrum..." in `menu` (Ctrl+Shift+F, in the whole window while the dock is shown):
    // shows the dock's spectrum window, made on first use.
    static QAction *addOpenAction(QMenu *menu, ScopeDock *dock);

    // The channels offered: the recording's recorded channels, then the math channels.
    QComboBox *channelBox() const { return m_channel; }
    QComboBox *rangeBox() const { return m_range; }
    void setRange(Range range);
    Range range() const;
    void setLogarithmic(bool on);

    // The spectrum shown, none when a message says why (message()).
    const std::optional<ScopeSpectrum> &spectrum() const { return m_spectrum; }
    // The line under the plot: what the spectrum is made of, or why there is none.
    QString message() const;
    // A spectrum is being made, waits to be, or a change waits to be followed.
    bool isComputing() const { return m_running || m_waiting || m_followTimer.isActive(); }
    QCustomPlot *plot() const;
    QTableWidget *peakTable() const;

    // Asks for the spectrum anew (at once; the followers wait kFollowMs).
    void refresh();

signals:
    // The newest request's spectrum, or its message, is shown.
    void computed();

protected:
    void showEvent(QShowEvent *event) override;

private:
    struct Request;
    struct Result;

    // Something the spectrum is made of changed: asked for anew within kFollowMs, while shown.
    void follow();
    void updateChannels();
    void start(std::shared_ptr<const Request> request);
    void showResult(const Result &result);
    void showMessage(const QString &text, bool problem);

    ScopeChart *m_chart = nullptr;
    ScopeMathChannels *m_math = nullptr;
    QComboBox *m_channel = nullptr;
    QComboBox *m_range = nullptr;
    QCheckBox *m_logarithmic = nullptr;
    std::unique_ptr<ScopeSpectrumPlot> m_spectrumPlot;
    QLabel *m_message = nullptr;
    QTimer m_followTimer;
    std::optional<ScopeSpectrum> m_spectrum;
    QString m_lastKey; // what the last request was made of: the same is not asked again

    bool m_running = false;
    std::shared_ptr<const Request> m_waiting; // the newest request, while another runs
    quint64 m_generation = 0; // requests made; a result of an older one is not shown
};

} // namespace DriveDesk
