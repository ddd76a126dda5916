#include "ScopeSpectrumView.h"

#include "QCustomPlotInclude.h"
#include "ScopeChart.h"
#include "ScopeDock.h"
#include "ScopeMathChannels.h"
#include "ScopeSpectrumPlot.h"

#include "client/WhenFinished.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeSnapshot.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QSplitter>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <utility>

namespace DriveDesk {

namespace {

constexpr int kPeaks = 5;

} // namespace

struct ScopeSpectrumView::Request
{
    ScopeSnapshot snapshot;
    int channel = -1; // a recorded channel of the snapshot, or -1 for `series`
    std::shared_ptr<const ScopeSeries> series;
    ScopeSpectrumOptions options;
    qint64 originMs = 0; // the recording's first sample: the times shown are from it
    quint64 generation = 0;
};

struct ScopeSpectrumView::Result
{
    std::optional<ScopeSpectrum> spectrum;
    QString error;
    QVector<QCPGraphData> points; // amplitude over Hz, made in the worker too
    qint64 originMs = 0;
};

ScopeSpectrumView::ScopeSpectrumView(ScopeChart *chart, ScopeMathChannels *math, QWidget *parent)
    : QWidget(parent, Qt::Window)
    , m_chart(chart)
    , m_math(math)
{
    setObjectName(QStringLiteral("scopeSpectrum"));
    setWindowTitle(tr("Spectrum"));
    resize(760, 480);
    auto *layout = new QVBoxLayout(this);

    auto *controls = new QHBoxLayout;
    auto *channelLabel = new QLabel(tr("&Channel"), this);
    m_channel = new QComboBox(this);
    m_channel->setObjectName(QStringLiteral("spectrumChannel"));
    m_channel->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    channelLabel->setBuddy(m_channel);
    auto *rangeLabel = new QLabel(tr("&Range"), this);
    m_range = new QComboBox(this);
    m_range->setObjectName(QStringLiteral("spectrumRange"));
    m_range->addItem(tr("the view"), int(Range::View));
    m_range->addItem(tr("between the cursors"), int(Range::Cursors));
    rangeLabel->setBuddy(m_range);
    m_logarithmic = new QCheckBox(tr("&Logarithmic amplitude"), this);
    m_logarithmic->setObjectName(QStringLiteral("spectrumLogarithmic"));
    controls->addWidget(channelLabel);
    controls->addWidget(m_channel);
    controls->addSpacing(12);
    controls->addWidget(rangeLabel);
    controls->addWidget(m_range);
    controls->addSpacing(12);
    controls->addWidget(m_logarithmic);
    controls->addStretch(1);
    layout->addLayout(controls);

    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setChildrenCollapsible(false);
    m_spectrumPlot = std::make_unique<ScopeSpectrumPlot>(splitter);
    splitter->addWidget(m_spectrumPlot->plot());
    splitter->addWidget(m_spectrumPlot->peakTable());
    splitter->setStretchFactor(0, 1);
    layout->addWidget(splitter, 1);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("spectrumMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_message);

    m_followTimer.setSingleShot(true);
    m_followTimer.setInterval(kFollowMs);
    connect(&m_followTimer, &QTimer::timeout, this, &ScopeSpectrumView::refresh);
    connect(m_chart->plot()->xAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
            &ScopeSpectrumView::follow);
    connect(m_chart, &ScopeChart::cursorsChanged, this, &ScopeSpectrumView::follow);
    connect(m_math, &ScopeMathChannels::seriesChanged, this, &ScopeSpectrumView::follow);
    connect(m_channel, &QComboBox::activated, this, &ScopeSpectrumView::refresh);
    connect(m_range, &QComboBox::currentIndexChanged, this, &ScopeSpectrumView::refresh);
    connect(m_logarithmic, &QCheckBox::toggled, this,
            [this](bool on) { m_spectrumPlot->setLogarithmic(on); });
    updateChannels();
}

ScopeSpectrumView::~ScopeSpectrumView() = default;

QCustomPlot *ScopeSpectrumView::plot() const
{
    return m_spectrumPlot->plot();
}

QTableWidget *ScopeSpectrumView::peakTable() const
{
    return m_spectrumPlot->peakTable();
}

QAction *ScopeSpectrumView::addOpenAction(QMenu *menu, ScopeDock *dock)
{
    QAction *action = menu->addAction(tr("Spectrum..."));
    action->setObjectName(QStringLiteral("scopeSpectrumAction"));
    action->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    action->setToolTip(tr("The amplitude spectrum of a channel over the view or between the "
                          "cursors (Ctrl+Shift+F)"));
    // The menu is a tool button's: its shortcut works where the dock is.
    dock->addAction(action);
    connect(action, &QAction::triggered, dock, [dock] {
        auto *view = dock->findChild<ScopeSpectrumView *>(QString(), Qt::FindDirectChildrenOnly);
        if (!view)
            view = new ScopeSpectrumView(dock->chart(), dock->mathChannels(), dock);
        view->show();
        view->raise();
        view->activateWindow();
    });
    return action;
}

void ScopeSpectrumView::setRange(Range range)
{
    m_range->setCurrentIndex(m_range->findData(int(range)));
}

ScopeSpectrumView::Range ScopeSpectrumView::range() const
{
    return Range(m_range->currentData().toInt());
}

void ScopeSpectrumView::setLogarithmic(bool on)
{
    m_logarithmic->setChecked(on);
}

QString ScopeSpectrumView::message() const
{
    return m_message->text();
}

void ScopeSpectrumView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    refresh();
}

void ScopeSpectrumView::follow()
{
    if (isVisible() && !m_followTimer.isActive())
        m_followTimer.start();
}

void ScopeSpectrumView::updateChannels()
{
    // Item data: a recorded channel's index, or -1 - i for math channel i.
    QStringList titles;
    QList<int> keys;
    if (const ScopeRecording *recording = m_chart->recording()) {
        for (const int channel : recording->recordedChannels()) {
            titles << recording->channels.at(channel).title(channel);
            keys << channel;
        }
    }
    const auto &math = m_math->series();
    for (qsizetype i = 0; i < math.size(); ++i) {
        titles << math.at(i)->title;
        keys << int(-1 - i);
    }
    bool same = titles.size() == m_channel->count();
    for (int i = 0; same && i < m_channel->count(); ++i)
        same = m_channel->itemText(i) == titles.at(i) && m_channel->itemData(i).toInt() == keys.at(i);
    if (same)
        return;
    const QString chosen = m_channel->currentText();
    m_channel->clear();
    for (qsizetype i = 0; i < titles.size(); ++i)
        m_channel->addItem(titles.at(i), keys.at(i));
    m_channel->setCurrentIndex(std::max(0, m_channel->findText(chosen)));
}

void ScopeSpectrumView::refresh()
{
    m_followTimer.stop();
    updateChannels();
    const ScopeRecording *recording = m_chart->recording();
    const auto nothing = [this](const QString &text) {
        ++m_generation;
        m_waiting.reset();
        m_lastKey.clear();
        m_spectrum.reset();
        m_spectrumPlot->clear();
        showMessage(text, false);
        emit computed();
    };
    if (!recording || m_channel->count() == 0 || m_chart->shownSampleCount() == 0)
        return nothing(tr("No samples: record or open a recording."));

    auto request = std::make_shared<Request>();
    if (range() == Range::Cursors) {
        const std::optional<double> first = m_chart->cursorTime(0);
        const std::optional<double> second = m_chart->cursorTime(1);
        if (!first || !second)
            return nothing(tr("Place both cursors on the chart for the range between them."));
        request->options.fromMs = std::min(*first, *second);
        request->options.toMs = std::max(*first, *second);
    } else {
        const ScopeTimeRange view = m_chart->visibleTimeRange();
        request->options.fromMs = double(view.fromMs);
        request->options.toMs = double(view.toMs);
    }
    request->options.peaks = kPeaks;
    const int key = m_channel->currentData().toInt();
    const qsizetype count = m_chart->shownSampleCount();
    if (key >= 0) {
        request->channel = key;
    } else {
        request->series = m_math->series().value(-1 - key);
        if (!request->series)
            return nothing(tr("No samples: record or open a recording."));
    }
    request->originMs = recording->firstTime();

    // The recording (replaced when another is opened), its start, the channel, the range and
    // the samples shown: what the spectrum is made of.
    const QString requestKey
        = QStringList { QString::number(quintptr(recording)),
                        QString::number(recording->firstTime()), QString::number(key),
                        m_channel->currentText(), QString::number(request->options.fromMs),
                        QString::number(request->options.toMs), QString::number(count),
                        QString::number(quintptr(request->series.get())) }
              .join(QLatin1Char(' '));
    if (requestKey == m_lastKey)
        return; // what is shown, or on its way
    m_lastKey = requestKey;
    if (key >= 0)
        request->snapshot = scopeSnapshot(*recording, count);
    request->generation = ++m_generation;
    if (m_running)
        m_waiting = std::move(request);
    else
        start(std::move(request));
}

void ScopeSpectrumView::start(std::shared_ptr<const Request> request)
{
    m_running = true;
    const auto work = [request] {
        Result result;
        result.originMs = request->originMs;
        result.spectrum = request->channel >= 0
            ? computeScopeSpectrum(request->snapshot, request->channel, request->options,
                                   &result.error)
            : computeScopeSpectrum(*request->series, request->options, &result.error);
        if (result.spectrum) {
            const std::vector<double> &amplitude = result.spectrum->amplitude;
            result.points.reserve(qsizetype(amplitude.size()));
            for (std::size_t k = 0; k < amplitude.size(); ++k)
                result.points.append(QCPGraphData(double(k) * result.spectrum->binHz, amplitude[k]));
        }
        return result;
    };
    const quint64 generation = request->generation;
    const auto done = [this, generation](const Result &result) {
        m_running = false;
        if (generation == m_generation)
            showResult(result);
        if (m_waiting)
            start(std::exchange(m_waiting, nullptr));
        else if (generation == m_generation)
            emit computed();
    };
    whenFinished(QtConcurrent::run(work), this, done, [done] { done({}); });
}

void ScopeSpectrumView::showResult(const Result &result)
{
    m_spectrum = result.spectrum;
    if (!m_spectrum) {
        m_spectrumPlot->clear();
        showMessage(tr("No spectrum: %1").arg(result.error), true);
        return;
    }
    const ScopeSpectrum &spectrum = *m_spectrum;
    const QLocale locale;
    const auto seconds = [&](double ms) {
        return locale.toString((ms - double(result.originMs)) / 1000, 'f', 3);
    };
    QString text = tr("%1: %Ln sample(s) from %2 s to %3 s, %4 points at %5 Hz, bins of %6 Hz",
                      nullptr, int(spectrum.samples))
                       .arg(spectrum.title, seconds(spectrum.fromMs), seconds(spectrum.toMs),
                            locale.toString(spectrum.points),
                            locale.toString(spectrum.sampleRateHz, 'g', 6),
                            locale.toString(spectrum.binHz, 'f',
                                            ScopeSpectrumPlot::frequencyDecimals(spectrum.binHz)));
    if (spectrum.resampled)
        text += tr(" (resampled to even spacing: the samples came unevenly)");
    showMessage(text, false);
    m_spectrumPlot->show(spectrum, result.points);
}

void ScopeSpectrumView::showMessage(const QString &text, bool problem)
{
    m_message->setText(text);
    m_message->setStyleSheet(problem ? QStringLiteral("color: #b00020;") : QString());
}

} // namespace DriveDesk
