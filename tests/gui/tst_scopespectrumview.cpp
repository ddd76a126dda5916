// The spectrum window of the scope, offscreen: beside a chart of a recording of a 50 Hz sine
// at 1 kHz, its highest peak at 50 Hz within a bin over the view, between the cursors (their
// samples counted), the last of quick cursor moves shown, too few samples said so, another
// channel, and a math channel's spectrum.
#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeChart.h"
#include "scope/ScopeMathChannels.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeSpectrumView.h"

#include "Translations.h"

#include <QComboBox>
#include <QLocale>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

#include <cmath>

using namespace DriveDesk;

namespace {

constexpr int kWaitMs = 20000;
constexpr quint16 kHz = 18;
constexpr qint64 kStartMs = 5000;
constexpr int kSamples = 2000;

// ru.03 in 0.01 Hz: 20 Hz + 10 Hz sin(2 pi 50 Hz t), one sample a ms for 2 s from 5000 ms.
// Channel 2 (raw) a slower sine, 7 Hz, so that the channels differ.
ScopeRecording sineRecording()
{
    ScopeRecording recording;
    ScopeChannel frequency;
    frequency.source = 0x0203;
    frequency.id = QStringLiteral("ru.03");
    frequency.name = QStringLiteral("Actual frequency");
    frequency.scaling
        = DisplayScaling(DisplayScalingData { 0x0203, 100, 1, 0, quint16(kHz | (2 << 8)) });
    recording.channels[0] = frequency;
    recording.channels[2].enabled = false;
    recording.channels[3].enabled = false;
    for (int i = 0; i < kSamples; ++i) {
        const double s = double(i) / 1000;
        ScopeSample sample;
        sample.time = kStartMs + i;
        sample.wide = { qint32(std::lround((20 + 10 * std::sin(2 * M_PI * 50 * s)) * 100)),
                        qint32(std::lround(1000 * std::sin(2 * M_PI * 7 * s))) };
        recording.buffer.append(sample);
    }
    return recording;
}

// Waits until the window shows the newest request's spectrum (or its message).
bool settled(ScopeSpectrumView *view)
{
    return QTest::qWaitFor([view] { return !view->isComputing(); }, kWaitMs);
}

QString describe(const ScopeSpectrumView *view)
{
    QString text = view->message();
    if (view->spectrum()) {
        for (const ScopeSpectrumPeak &peak : view->spectrum()->peaks)
            text += QStringLiteral("; %1 Hz: %2").arg(peak.frequencyHz).arg(peak.amplitude);
    }
    return text;
}

} // namespace

// A chart of the recording, its math channels, and the spectrum window beside them, shown.
struct Scope
{
    explicit Scope(ScopeRecording &recording)
    {
        chart.resize(900, 500);
        chart.setRecording(&recording);
        chart.show();
        chart.showAll();
        QObject::connect(&math, &ScopeMathChannels::seriesChanged, &chart,
                         [this] { chart.setMathSeries(math.series(), math.levels()); });
        view.show();
    }
    ScopeChart chart;
    ScopeMathChannels math;
    ScopeSpectrumView view { &chart, &math };
};

class TestScopeSpectrumView : public QObject
{
    Q_OBJECT
private slots:
    // The English catalogue holds the plural forms ("2,000 samples") the window shows.
    void initTestCase() { QVERIFY(installTranslations(QStringLiteral("en"))); }

    void theHighestPeakOverTheViewAndBetweenTheCursors()
    {
        ScopeRecording recording = sineRecording();
        Scope scope(recording);
        ScopeChart *chart = &scope.chart;
        ScopeSpectrumView *view = &scope.view;
        QVERIFY(QTest::qWaitForWindowExposed(view));
        QCOMPARE(view->channelBox()->count(), 2); // ru.03 and channel 2
        QCOMPARE(view->channelBox()->currentText(), QStringLiteral("ru.03 Actual frequency"));
        QCOMPARE(view->range(), ScopeSpectrumView::Range::View);

        // The whole recording is in view: 2000 samples, bins of 0.5 Hz.
        QVERIFY(settled(view));
        QVERIFY2(view->spectrum(), qPrintable(view->message()));
        const ScopeSpectrum &whole = *view->spectrum();
        QCOMPARE(whole.samples, qsizetype(kSamples));
        QCOMPARE(whole.unit, QStringLiteral("Hz"));
        QVERIFY2(std::abs(whole.peaks.at(0).frequencyHz - 50) < whole.binHz,
                 qPrintable(describe(view)));
        QVERIFY2(std::abs(whole.peaks.at(0).amplitude - 10) < 0.1, qPrintable(describe(view)));
        // The table reads it, in the language's numbers and the channel's unit.
        QTableWidget *peaks = view->peakTable();
        QCOMPARE(peaks->rowCount(), int(whole.peaks.size()));
        const QLocale locale;
        QCOMPARE(peaks->item(0, 0)->text(),
                 QStringLiteral("%1 Hz").arg(locale.toString(whole.peaks.at(0).frequencyHz, 'f', 2)));
        QVERIFY2(peaks->item(0, 0)->text().startsWith(locale.toString(50.0, 'f', 2)),
                 qPrintable(peaks->item(0, 0)->text()));
        QVERIFY(peaks->item(0, 1)->text().endsWith(QStringLiteral(" Hz")));
        QVERIFY(view->message().contains(locale.toString(kSamples)));
        QVERIFY(!view->plot()->graph(0)->data()->isEmpty());
        // docs/scope-spectrum.png
        const QString screenshot = qEnvironmentVariable("DRIVEDESK_SPECTRUM_SCREENSHOT");
        if (!screenshot.isEmpty()) {
            view->resize(820, 420);
            QTest::qWait(300);
            QVERIFY(view->grab().save(screenshot));
        }

        // Between the cursors, placed in either order: 512 samples, their spectrum.
        chart->setCursorTime(0, double(kStartMs + 711));
        chart->setCursorTime(1, double(kStartMs + 200));
        view->setRange(ScopeSpectrumView::Range::Cursors);
        QVERIFY(settled(view));
        QVERIFY2(view->spectrum(), qPrintable(view->message()));
        QCOMPARE(view->spectrum()->samples, qsizetype(512));
        QCOMPARE(view->spectrum()->fromMs, double(kStartMs + 200));
        QVERIFY2(view->message().contains(locale.toString(512)), qPrintable(view->message()));
        QVERIFY2(std::abs(view->spectrum()->peaks.at(0).frequencyHz - 50) < view->spectrum()->binHz,
                 qPrintable(describe(view)));

        // The cursors moved in quick succession: the last place's spectrum is shown, and
        // stays.
        for (int end = 300; end <= 1300; end += 100)
            chart->setCursorTime(0, double(kStartMs + end));
        QVERIFY(settled(view));
        QCOMPARE(view->spectrum()->samples, qsizetype(1101)); // 200 .. 1300 ms
        QTest::qWait(2 * ScopeSpectrumView::kFollowMs);
        QCOMPARE(view->spectrum()->samples, qsizetype(1101));

        // Too few samples: no spectrum, and why.
        chart->setCursorTime(0, double(kStartMs + 300));
        chart->setCursorTime(1, double(kStartMs + 304));
        QVERIFY(settled(view));
        QVERIFY(!view->spectrum());
        QVERIFY2(view->message().contains(QStringLiteral("5 in the window, at least 16 needed")),
                 qPrintable(view->message()));
        QCOMPARE(peaks->rowCount(), 0);

        // One cursor only: the range between them cannot be had; the view's still can.
        chart->setCursorTime(1, std::nullopt);
        QVERIFY(settled(view));
        QVERIFY(!view->spectrum());
        QVERIFY2(view->message().contains(QStringLiteral("both cursors")),
                 qPrintable(view->message()));
        view->setRange(ScopeSpectrumView::Range::View);
        QVERIFY(settled(view));
        QVERIFY(view->spectrum());
        QCOMPARE(view->spectrum()->samples, qsizetype(kSamples));

        // The other channel, and a logarithmic amplitude axis.
        view->channelBox()->setCurrentIndex(1);
        emit view->channelBox()->activated(1);
        QVERIFY(settled(view));
        QVERIFY2(std::abs(view->spectrum()->peaks.at(0).frequencyHz - 7) < view->spectrum()->binHz,
                 qPrintable(describe(view)));
        view->setLogarithmic(true);
        QCOMPARE(view->plot()->yAxis->scaleType(), QCPAxis::stLogarithmic);
    }

    // A derivative of ru.03 (in Hz/s) is offered beside the channels; its spectrum peaks at
    // 50 Hz as well, at 2 pi 50 times the amplitude.
    void aMathChannelsSpectrum()
    {
        ScopeRecording recording = sineRecording();
        ScopeMathDefinition derivative;
        derivative.kind = ScopeMathDefinition::Kind::Derivative;
        derivative.sources = { 0 };
        recording.math << derivative;
        Scope scope(recording);
        ScopeSpectrumView *view = &scope.view;
        QVERIFY(settled(view));
        QCOMPARE(view->channelBox()->count(), 2);

        scope.math.compute(recording, recording.buffer.count());
        QTRY_COMPARE_WITH_TIMEOUT(view->channelBox()->count(), 3, kWaitMs);
        QVERIFY(view->channelBox()->itemText(2).startsWith(QStringLiteral("d/dt ru.03")));

        view->channelBox()->setCurrentIndex(2);
        emit view->channelBox()->activated(2);
        QVERIFY(settled(view));
        QVERIFY2(view->spectrum(), qPrintable(view->message()));
        QCOMPARE(view->spectrum()->unit, QStringLiteral("Hz/s"));
        const ScopeSpectrumPeak &peak = view->spectrum()->peaks.at(0);
        QVERIFY2(std::abs(peak.frequencyHz - 50) < view->spectrum()->binHz,
                 qPrintable(describe(view)));
        // The derivative's own amplitude (a three-point slope reads a little under 2 pi f A).
        QVERIFY2(std::abs(peak.amplitude - 2 * M_PI * 50 * 10) < 0.05 * 2 * M_PI * 50 * 10,
                 qPrintable(describe(view)));
    }
};

QTEST_MAIN(TestScopeSpectrumView)
#include "tst_scopespectrumview.moc"
