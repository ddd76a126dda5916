#include "scope/QCustomPlotInclude.h"
#include "scope/ScopeGraph.h"
#include "scope/ScopeLegendItem.h"

#include <QApplication>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QRandomGenerator>
#include <QTest>

#include <cmath>
#include <limits>

using namespace DriveDesk;

namespace {

constexpr QSize kSize(640, 360);
const QColor kPen(0x00, 0x72, 0xB2);

// A bare plot (no axes, grid or legend drawn) of one graph, a ScopeGraph or QCustomPlot's own.
struct Plot
{
    QCustomPlot plot;
    QCPGraph *graph = nullptr;

    Plot(bool scope, const QVector<double> &keys, const QVector<double> &values,
         QCPRange valueRange)
    {
        plot.resize(kSize);
        plot.setNotAntialiasedElements(QCP::aeAll);
        graph = scope ? ScopeGraph::add(&plot, plot.xAxis, plot.yAxis)
                      : plot.addGraph(plot.xAxis, plot.yAxis);
        graph->setAdaptiveSampling(false);
        graph->setAntialiased(false);
        graph->setPen(QPen(kPen, 1));
        graph->setData(keys, values, true);
        plot.xAxis->setRange(0, 1);
        plot.yAxis->setRange(valueRange);
        for (QCPAxis *axis : plot.axisRect()->axes()) {
            axis->setVisible(false);
            axis->grid()->setVisible(false);
        }
        plot.legend->setVisible(false);
        // The axis rect fills the plot: a column of the data is a pixel column, as the chart
        // decimates to one column a pixel.
        plot.axisRect()->setAutoMargins(QCP::msNone);
        plot.axisRect()->setMargins(QMargins());
    }

    QImage image()
    {
        plot.replot(QCustomPlot::rpImmediateRefresh);
        return plot.toPixmap(kSize.width(), kSize.height()).toImage().convertToFormat(
            QImage::Format_RGB32);
    }
};

// The rows painted in the pen's colour, per column: first and last (-1: none), and in all.
struct Painted
{
    QVector<int> first;
    QVector<int> last;
    qint64 pixels = 0;
    qint64 otherColours = 0; // neither the pen's colour nor the background

    explicit Painted(const QImage &image)
        : first(image.width(), -1)
        , last(image.width(), -1)
    {
        const QRgb pen = kPen.rgb();
        const QRgb background = image.pixel(0, 0);
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QRgb pixel = image.pixel(x, y);
                if (pixel == background)
                    continue;
                if (pixel != pen) {
                    ++otherColours;
                    continue;
                }
                ++pixels;
                if (first[x] < 0)
                    first[x] = y;
                last[x] = y;
            }
        }
    }
};

// A column's min and max, as ScopeTraces hands them over: two points a pixel column, each of
// two random values within `spread` of `offset`.
void columns(int count, double spread, double offset, QVector<double> &keys,
             QVector<double> &values, QRandomGenerator &random)
{
    for (int column = 0; column < count; ++column) {
        const double key = (column + 0.5) / count;
        const double a = offset + spread * (random.generateDouble() * 2 - 1);
        const double b = offset + spread * (random.generateDouble() * 2 - 1);
        keys << key << key;
        values << std::min(a, b) << std::max(a, b);
    }
}

// As columns(), each column reaching from below the middle to above it, as a derivative's
// noise does.
void throughTheMiddle(QVector<double> &keys, QVector<double> &values, QRandomGenerator &random)
{
    columns(kSize.width(), 0.4, 0, keys, values, random);
    for (qsizetype i = 0; i < values.size(); i += 2) {
        values[i] -= 0.6;
        values[i + 1] += 0.6;
    }
}

enum class Trace { Noise, Wider, ThroughTheMiddle, QuietColumns, Small, GapAndFarOff };

// The points of `trace`, and the value axis's range to draw them in.
QCPRange make(Trace trace, QVector<double> &keys, QVector<double> &values)
{
    QRandomGenerator random(quint32(trace) + 7);
    switch (trace) {
    case Trace::Noise:
        columns(kSize.width(), 1.0, 0, keys, values, random);
        break;
    case Trace::Wider:
        columns(kSize.width() * 3 / 2, 1.0, 0, keys, values, random);
        break;
    case Trace::ThroughTheMiddle:
        throughTheMiddle(keys, values, random);
        break;
    case Trace::QuietColumns:
        throughTheMiddle(keys, values, random);
        for (const qsizetype column : { 100, 101, 102, 300, 301 }) {
            values[2 * column] = 0.5;
            values[2 * column + 1] = 0.51;
        }
        values[2 * 400] = -0.01;
        values[2 * 400 + 1] = 0.01;
        break;
    case Trace::Small:
        columns(kSize.width(), 0.002, 0.3, keys, values, random);
        return QCPRange(-1, 1);
    case Trace::GapAndFarOff:
        columns(kSize.width(), 1.0, 0, keys, values, random);
        for (int i = 100; i < 140; ++i)
            values[i] = std::numeric_limits<double>::quiet_NaN();
        values[300] = 1e12;
        values[301] = -1e12;
        break;
    }
    return QCPRange(-1.1, 1.1);
}

} // namespace

// ScopeGraph draws decimated traces its own way on screen (docs/scope.md, bench_scope_view):
// what it draws is checked against QCustomPlot's own graph of the same points.
class TestScopeGraph : public QObject
{
    Q_OBJECT
private:
    // The two drawings agree column by column, to a pixel's rounding at the ends of strokes.
    static void checkSameDrawing(const QVector<double> &keys, const QVector<double> &values,
                                 QCPRange range)
    {
        Plot own(true, keys, values, range);
        Plot reference(false, keys, values, range);
        // The quick way on screen, in the plot's own buffer and in an image of it.
        own.plot.replot(QCustomPlot::rpImmediateRefresh);
        QVERIFY(qobject_cast<ScopeGraph *>(own.graph)->drewItself());
        const QImage ownImage = own.image();
        QVERIFY(qobject_cast<ScopeGraph *>(own.graph)->drewItself());
        const QImage referenceImage = reference.image();
        const Painted drawn(ownImage);
        const Painted expected(referenceImage);
        QVERIFY(expected.pixels > 0);
        QCOMPARE(drawn.otherColours, 0);
        // A column's strokes end where QCustomPlot's do, to a pixel's rounding; where a steep
        // line passes from one pixel column to the next, the rows it takes to do so may
        // divide a few rows differently. The line's first and last pixel are a matter of
        // convention (the raster engine leaves out a stroke shorter than a pixel there).
        qint64 offByMore = 0;
        for (int x = 1; x < kSize.width() - 1; ++x) {
            QVERIFY2((drawn.first[x] < 0) == (expected.first[x] < 0),
                     qPrintable(QStringLiteral("column %1 drawn in one only").arg(x)));
            const int off = std::max(std::abs(drawn.first[x] - expected.first[x]),
                                     std::abs(drawn.last[x] - expected.last[x]));
            QVERIFY2(off <= 5, qPrintable(QStringLiteral("column %1: rows %2-%3, expected %4-%5")
                                              .arg(x)
                                              .arg(drawn.first[x])
                                              .arg(drawn.last[x])
                                              .arg(expected.first[x])
                                              .arg(expected.last[x])));
            if (off > 1)
                ++offByMore;
        }
        QVERIFY2(offByMore <= kSize.width() / 7,
                 qPrintable(QStringLiteral("%1 columns off by more than a row").arg(offByMore)));
        const double ratio = double(drawn.pixels) / double(expected.pixels);
        QVERIFY2(ratio > 0.97 && ratio < 1.03,
                 qPrintable(QStringLiteral("%1 pixels drawn, %2 expected")
                                .arg(drawn.pixels)
                                .arg(expected.pixels)));
    }

private slots:
    void drawsWhatQCustomPlotDraws_data()
    {
        QTest::addColumn<int>("trace");
        // A derivative's noise: every column spans much of the plot (the image).
        QTest::newRow("noise filling the plot") << int(Trace::Noise);
        // A view decimated for a wider chart than it is drawn on (the chart resized).
        QTest::newRow("more columns than pixels") << int(Trace::Wider);
        // Every column reaching from below the middle to above it (the block filled as a
        // rectangle, the rest through the image).
        QTest::newRow("every column through the middle") << int(Trace::ThroughTheMiddle);
        // As that, but five columns nearly flat above the middle and one through it only just:
        // they stay out of the rectangle.
        QTest::newRow("a few quiet columns") << int(Trace::QuietColumns);
        // A few rows high over every column: most points add no pixel and are left out.
        QTest::newRow("small, on a shared axis") << int(Trace::Small);
        // A NaN leaves a gap; values far beyond a zoomed value axis still give the right slope
        // where their lines cross the plot.
        QTest::newRow("a gap and far-off values") << int(Trace::GapAndFarOff);
    }

    void drawsWhatQCustomPlotDraws()
    {
        QFETCH(int, trace);
        QVector<double> keys;
        QVector<double> values;
        const QCPRange range = make(Trace(trace), keys, values);
        checkSameDrawing(keys, values, range);
    }

    void aVectorExportDrawsAsQCustomPlotDoes()
    {
        QRandomGenerator random(9);
        QVector<double> keys;
        QVector<double> values;
        columns(kSize.width(), 1.0, 0, keys, values, random);
        Plot own(true, keys, values, QCPRange(-1.1, 1.1));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("chart.pdf"));
        QVERIFY(own.plot.savePdf(path));
        QVERIFY(!qobject_cast<ScopeGraph *>(own.graph)->drewItself());
        QVERIFY(QFileInfo(path).size() > 1000);
    }

    void theLegendShowsTheNameAndFollowsARename()
    {
        QRandomGenerator random(1);
        QVector<double> keys;
        QVector<double> values;
        columns(100, 1.0, 0, keys, values, random);
        Plot own(true, keys, values, QCPRange(-1.1, 1.1));
        own.plot.legend->setVisible(true);
        own.graph->setName(QStringLiteral("ru.03 Actual frequency [Hz]"));
        QCOMPARE(own.plot.legend->itemCount(), 1);
        auto *item = qobject_cast<ScopeLegendItem *>(own.plot.legend->item(0));
        QVERIFY(item);
        const int shortWidth = item->minimumOuterSizeHint().width();
        own.graph->setName(QStringLiteral("ru.03 Actual frequency (overlay: run 2) [Hz]"));
        QVERIFY(item->minimumOuterSizeHint().width() > shortWidth);
        // The same size as QCustomPlot's own entry would have, so the layout is unchanged.
        QCPPlottableLegendItem plain(own.plot.legend, own.graph);
        QCOMPARE(item->minimumOuterSizeHint(),
                 static_cast<const QCPLayoutElement &>(plain).minimumOuterSizeHint());
        showInLegend(own.graph, false);
        QCOMPARE(own.plot.legend->itemCount(), 0);
        showInLegend(own.graph, true);
        QVERIFY(qobject_cast<ScopeLegendItem *>(own.plot.legend->item(0)));
    }
};

QTEST_MAIN(TestScopeGraph)
#include "tst_scopegraph.moc"
