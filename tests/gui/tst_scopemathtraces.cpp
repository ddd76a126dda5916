// A math channel's trace drawn from its min/max levels: the same points as a scan of every
// value in view, at several zooms, on even and uneven times (offscreen).
#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeMathTraces.h"

#include <QRandomGenerator>
#include <QTest>

#include <cmath>
#include <memory>

using namespace DriveDesk;

namespace {

// A noisy sine with rare spikes; steps of 1 ms, or of 0 to 3 ms (several values a ms).
std::shared_ptr<const ScopeSeries> trace(qsizetype count, bool uneven)
{
    auto series = std::make_shared<ScopeSeries>();
    series->title = QStringLiteral("d/dt ru.03 Actual frequency");
    series->unit = QStringLiteral("Hz/s");
    QRandomGenerator random(7);
    double t = 1000;
    for (qsizetype i = 0; i < count; ++i) {
        double value = 100 * std::sin(double(i) / 500) + random.generateDouble();
        if (random.bounded(5000) == 0)
            value += 1000;
        series->timeMs.push_back(t);
        series->values.push_back(value);
        t += uneven ? double(random.bounded(4)) : 1.0;
    }
    return series;
}

QString points(const QCPGraph *graph)
{
    QStringList texts;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        texts << QStringLiteral("%1:%2").arg(it->key, 0, 'g', 17).arg(it->value, 0, 'g', 17);
    return texts.join(QLatin1Char(' '));
}

} // namespace

class TestScopeMathTraces : public QObject
{
    Q_OBJECT
private slots:
    void levelsDrawWhatAScanDraws_data()
    {
        QTest::addColumn<bool>("uneven");
        QTest::newRow("1 ms steps") << false;
        QTest::newRow("0 to 3 ms steps") << true;
    }

    void levelsDrawWhatAScanDraws()
    {
        QFETCH(bool, uneven);
        const auto series = trace(200000, uneven);
        const auto levels = std::make_shared<const ScopeSeriesLevels>(*series);
        QCustomPlot withPlot;
        QCustomPlot scanPlot;
        ScopeMathTraces withLevels(&withPlot);
        ScopeMathTraces scanned(&scanPlot);
        withLevels.setSeries({ series }, { levels });
        scanned.setSeries({ series });
        const qint64 first = qint64(series->timeMs.front());
        const qint64 last = qint64(series->timeMs.back());
        const QList<std::pair<qint64, qint64>> views
            = { { first, last }, { first + 1000, first + 41000 }, { first + 5000, first + 5300 },
                { first - 100, first + 20 }, { last - 777, last + 100 } };
        for (const auto &[from, to] : views) {
            for (const int columns : { 1, 300, 1505 }) {
                ScopeTraceWindow window;
                window.fromMs = from;
                window.toMs = to;
                window.columns = columns;
                window.originMs = first;
                withLevels.fill(window);
                scanned.fill(window);
                QVERIFY(!withLevels.graph(0)->data()->isEmpty());
                QCOMPARE(points(withLevels.graph(0)), points(scanned.graph(0)));
            }
        }
    }
};

QTEST_MAIN(TestScopeMathTraces)
#include "tst_scopemathtraces.moc"
