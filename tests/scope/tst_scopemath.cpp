// Math channels: each kind against values the test works out itself, with its unit and title;
// the definition as JSON and back, and its faults named.
#include "ScopeTestRecording.h"
#include "scope/ScopeMath.h"

#include <QJsonDocument>
#include <QTest>

#include <cmath>

using namespace DriveDesk;
using namespace DriveDesk::ScopeTest;

namespace {

using Kind = ScopeMathDefinition::Kind;

ScopeMathDefinition definition(Kind kind, QList<int> sources)
{
    ScopeMathDefinition made;
    made.kind = kind;
    made.sources = std::move(sources);
    return made;
}

// Steps of 1, 2 and 3 ms in turn, and two samples in one ms every tenth sample.
std::vector<qint64> unevenTimes(int count)
{
    std::vector<qint64> times;
    qint64 t = 1000;
    for (int i = 0; i < count; ++i) {
        times.push_back(t);
        t += i % 10 == 9 ? 0 : 1 + i % 3;
    }
    return times;
}

// Channel 0: ru.03 in Hz (raw tenths), 0.5 Hz a ms from 0 at the first sample; channel 1:
// ru.18 in Hz (raw tenths), 2 * sin(2 pi t / 200 ms); channel 2: ru.09 in V (raw volts), 400.
ScopeRecording &fill(ScopeRecording &recording, const std::vector<qint64> &times)
{
    recording.channels[0] = scaledChannel(0x0203, QStringLiteral("ru.03"),
                                          QStringLiteral("Actual frequency"), 10, kHz);
    recording.channels[1]
        = scaledChannel(0x0212, QStringLiteral("ru.18"), QStringLiteral("Set value"), 10000, kHz);
    recording.channels[2] = scaledChannel(0x0209, QStringLiteral("ru.09"),
                                          QStringLiteral("Output voltage"), 1, kVolt);
    for (const qint64 t : times) {
        const double sine = 2 * std::sin(2 * M_PI * double(t - times.front()) / 200);
        append(recording, t, qint32(5 * (t - times.front())), qint32(std::lround(sine * 10000)),
               400);
    }
    return recording;
}

double sineAt(double t, double t0)
{
    return 2 * std::sin(2 * M_PI * (t - t0) / 200);
}

} // namespace

class TestScopeMath : public QObject
{
    Q_OBJECT
private slots:
    void derivative()
    {
        const std::vector<qint64> times = unevenTimes(3000);
        ScopeRecording recording;
        fill(recording, times);
        const ScopeMathResult ramp
            = computeScopeMath(definition(Kind::Derivative, { 0 }), recording);
        QVERIFY2(ramp.ok(), qPrintable(ramp.error));
        QCOMPARE(ramp.series.unit, QStringLiteral("Hz/s"));
        QCOMPARE(ramp.series.title, QStringLiteral("d/dt ru.03 Actual frequency"));
        QCOMPARE(ramp.series.count(), qsizetype(times.size()));
        // 0.5 Hz a ms is 500 Hz/s at every sample, the ends and the shared ms included.
        for (const double value : ramp.series.values)
            QVERIFY2(std::abs(value - 500) < 1e-9, qPrintable(QString::number(value)));

        // The sine's slope, 2 * 2 pi / 0.2 s * cos: within 0.2 % of its peak (steps of 1 to 3 ms
        // against a 200 ms period).
        const ScopeMathResult sine
            = computeScopeMath(definition(Kind::Derivative, { 1 }), recording);
        const double peak = 2 * 2 * M_PI / 0.2;
        for (std::size_t i = 0; i < times.size(); i += 7) {
            const double expected
                = peak * std::cos(2 * M_PI * double(times[i] - times.front()) / 200);
            QVERIFY2(std::abs(sine.series.values[i] - expected) < 0.002 * peak,
                     qPrintable(QStringLiteral("%1 at %2: %3")
                                    .arg(sine.series.values[i])
                                    .arg(times[i])
                                    .arg(expected)));
        }

        ScopeSeries oneTime;
        oneTime.timeMs = { 5, 5 };
        oneTime.values = { 1, 2 };
        QVERIFY(!computeScopeMath(definition(Kind::Derivative, { 0 }), oneTime).ok());
    }

    void integral()
    {
        const std::vector<qint64> times = unevenTimes(2000);
        ScopeRecording recording;
        fill(recording, times);
        const ScopeMathResult ramp = computeScopeMath(definition(Kind::Integral, { 0 }), recording);
        QVERIFY2(ramp.ok(), qPrintable(ramp.error));
        QCOMPARE(ramp.series.unit, QStringLiteral("Hz·s"));
        QCOMPARE(ramp.series.title, QStringLiteral("∫ ru.03 Actual frequency dt"));
        // The area under 0.5 Hz/ms * t: 0.25 * t² Hz·ms, exact for trapezoids.
        for (std::size_t i = 0; i < times.size(); ++i) {
            const double t = double(times[i] - times.front());
            QVERIFY(std::abs(ramp.series.values[i] - 0.25 * t * t / 1000) < 1e-9);
        }
        // 400 V for the whole recording.
        const ScopeMathResult constant
            = computeScopeMath(definition(Kind::Integral, { 2 }), recording);
        QCOMPARE(constant.series.unit, QStringLiteral("V·s"));
        QCOMPARE(constant.series.values.front(), 0.0);
        const double seconds = double(times.back() - times.front()) / 1000;
        QVERIFY(std::abs(constant.series.values.back() - 400 * seconds) < 1e-9);
    }

    void differenceAndSum()
    {
        const std::vector<qint64> times = unevenTimes(500);
        ScopeRecording recording;
        fill(recording, times);
        const ScopeMathResult difference
            = computeScopeMath(definition(Kind::Difference, { 0, 1 }), recording);
        QVERIFY2(difference.ok(), qPrintable(difference.error));
        QCOMPARE(difference.series.unit, QStringLiteral("Hz"));
        QVERIFY(!difference.unit.sourcesDiffer);
        QCOMPARE(difference.series.title,
                 QStringLiteral("ru.03 Actual frequency − ru.18 Set value"));
        const ScopeMathResult sum = computeScopeMath(definition(Kind::Sum, { 0, 1 }), recording);
        QCOMPARE(sum.series.title, QStringLiteral("ru.03 Actual frequency + ru.18 Set value"));
        for (std::size_t i = 0; i < times.size(); ++i) {
            const double ramp = 0.5 * double(times[i] - times.front());
            const double sine
                = std::lround(sineAt(double(times[i]), double(times.front())) * 10000) / 10000.0;
            QVERIFY(std::abs(difference.series.values[i] - (ramp - sine)) < 1e-9);
            QVERIFY(std::abs(sum.series.values[i] - (ramp + sine)) < 1e-9);
        }

        // Hz and V: computed, but with no unit, and the reason in words.
        const ScopeMathResult mixed = computeScopeMath(definition(Kind::Sum, { 0, 2 }), recording);
        QVERIFY(mixed.ok());
        QVERIFY(mixed.unit.sourcesDiffer);
        QCOMPARE(mixed.series.unit, QString());
        QCOMPARE(mixed.unit.text, QStringLiteral("the units differ: Hz, V"));

        // Traces at other times: the second's line between its samples.
        ScopeSeries first;
        first.unit = QStringLiteral("A");
        first.timeMs = { 0, 5, 10, 15, 20 };
        first.values = { 1, 1, 1, 1, 1 };
        ScopeSeries second;
        second.unit = QStringLiteral("A");
        second.timeMs = { 2, 12, 22 };
        second.values = { 0, 10, 30 };
        const ScopeMathResult between
            = computeScopeMath(definition(Kind::Difference, { 0, 1 }), first, &second);
        QCOMPARE(between.series.timeMs, (std::vector<double> { 5, 10, 15, 20 }));
        QCOMPARE(between.series.values,
                 (std::vector<double> { 1 - 3.0, 1 - 8.0, 1 - 16.0, 1 - 26.0 }));
    }

    void movingAverage_data()
    {
        QTest::addColumn<double>("window");
        QTest::addColumn<bool>("inMs");
        QTest::newRow("5 samples") << 5.0 << false;
        QTest::newRow("4 samples") << 4.0 << false;
        QTest::newRow("1 sample") << 1.0 << false;
        QTest::newRow("7 ms") << 7.0 << true;
        QTest::newRow("0.5 ms") << 0.5 << true;
    }

    void movingAverage()
    {
        QFETCH(double, window);
        QFETCH(bool, inMs);
        const std::vector<qint64> times = unevenTimes(300);
        ScopeRecording recording;
        fill(recording, times);
        ScopeMathDefinition average = definition(Kind::MovingAverage, { 1 });
        average.window = window;
        average.windowUnit = inMs ? ScopeMathDefinition::WindowUnit::Milliseconds
                                  : ScopeMathDefinition::WindowUnit::Samples;
        const ScopeMathResult result = computeScopeMath(average, recording);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.series.unit, QStringLiteral("Hz"));
        // (Without the English catalogue the count's plural is the source text's "sample(s)".)
        const QString title = inMs
            ? QStringLiteral("ru.18 Set value, mean over %1 ms").arg(window)
            : QStringLiteral("ru.18 Set value, mean of %1 sample").arg(window);
        QVERIFY2(result.series.title.startsWith(title), qPrintable(result.series.title));
        // Every window worked out by brute force.
        const ScopeSeries source = scopeSeries(recording, 1);
        const int n = int(times.size());
        for (int i = 0; i < n; ++i) {
            double sum = 0;
            int count = 0;
            for (int j = 0; j < n; ++j) {
                const bool inside = inMs
                    ? std::abs(double(times[j] - times[i])) <= window / 2
                    : j >= i - int(window) / 2 && j <= i + (int(window) - 1) / 2;
                if (inside) {
                    sum += source.values[std::size_t(j)];
                    ++count;
                }
            }
            QVERIFY2(std::abs(result.series.values[std::size_t(i)] - sum / count) < 1e-9,
                     qPrintable(QStringLiteral("sample %1: %2, not %3")
                                    .arg(i)
                                    .arg(result.series.values[std::size_t(i)])
                                    .arg(sum / count)));
        }
    }

    void unitsOfDerivativesAndIntegrals()
    {
        QCOMPARE(scopeMathUnit(Kind::Derivative, QStringLiteral("m/s")).symbol,
                 QStringLiteral("m/s²"));
        QCOMPARE(scopeMathUnit(Kind::Derivative, QStringLiteral("A·s")).symbol,
                 QStringLiteral("A"));
        QCOMPARE(scopeMathUnit(Kind::Derivative, QString()).symbol, QStringLiteral("1/s"));
        QCOMPARE(scopeMathUnit(Kind::Derivative, QStringLiteral("1/min")).symbol,
                 QStringLiteral("(1/min)/s"));
        QCOMPARE(scopeMathUnit(Kind::Integral, QStringLiteral("m/s")).symbol, QStringLiteral("m"));
        QCOMPARE(scopeMathUnit(Kind::Integral, QString()).symbol, QStringLiteral("s"));
        QCOMPARE(scopeMathUnit(Kind::MovingAverage, QStringLiteral("%")).symbol,
                 QStringLiteral("%"));
        QCOMPARE(scopeMathUnit(Kind::Difference, QStringLiteral("V"), QStringLiteral("V")).text,
                 QStringLiteral("V"));
        QCOMPARE(scopeMathUnit(Kind::Difference, QStringLiteral("V"), QString()).text,
                 QStringLiteral("the units differ: V, none"));
    }

    void definitionAsJson()
    {
        ScopeMathDefinition average = definition(Kind::MovingAverage, { 3 });
        average.window = 2.5;
        average.windowUnit = ScopeMathDefinition::WindowUnit::Milliseconds;
        for (const ScopeMathDefinition &original :
             { definition(Kind::Derivative, { 1 }), definition(Kind::Integral, { 0 }),
               definition(Kind::Difference, { 2, 0 }), definition(Kind::Sum, { 0, 1 }), average }) {
            const QByteArray json = QJsonDocument(original.toJson()).toJson(QJsonDocument::Compact);
            QString error;
            const auto read
                = ScopeMathDefinition::fromJson(QJsonDocument::fromJson(json).object(), &error);
            QVERIFY2(read, qPrintable(error));
            QVERIFY2(*read == original, json.constData());
        }
        QCOMPARE(
            QJsonDocument(average.toJson()).toJson(QJsonDocument::Compact),
            QByteArray(R"({"kind":"movingAverage","sources":[3],"window":2.5,"windowUnit":"ms"})"));
        QCOMPARE(QJsonDocument(definition(Kind::Difference, { 2, 0 }).toJson())
                     .toJson(QJsonDocument::Compact),
                 QByteArray(R"({"kind":"difference","sources":[2,0]})"));
    }

    void badDefinitionsAreNamed_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        QTest::newRow("unknown kind") << QByteArray(R"({"kind":"fft","sources":[0]})")
                                      << QStringLiteral("kind: unknown kind \"fft\"");
        QTest::newRow("no sources")
            << QByteArray(R"({"kind":"sum"})") << QStringLiteral("sources: missing");
        QTest::newRow("one source for a sum")
            << QByteArray(R"({"kind":"sum","sources":[0]})")
            << QStringLiteral("sources: a difference or a sum reads two channels");
        QTest::newRow("channel 5") << QByteArray(R"({"kind":"integral","sources":[4]})")
                                   << QStringLiteral("sources[0]: 4 is outside 0..3");
        QTest::newRow("half a sample")
            << QByteArray(
                   R"({"kind":"movingAverage","sources":[0],"window":2.5,"windowUnit":"samples"})")
            << QStringLiteral("window: the window is a whole number of samples, at least 1");
        QTest::newRow("no time")
            << QByteArray(R"({"kind":"movingAverage","sources":[0],"window":0,"windowUnit":"ms"})")
            << QStringLiteral("window: the window is a time in ms, more than 0");
        QTest::newRow("bad window unit")
            << QByteArray(R"({"kind":"movingAverage","sources":[0],"window":3,"windowUnit":"s"})")
            << QStringLiteral("windowUnit: expected samples or ms");
        QTest::newRow("a window for a derivative")
            << QByteArray(R"({"kind":"derivative","sources":[0],"window":3})")
            << QStringLiteral("window: unknown field");
    }

    void badDefinitionsAreNamed()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QString message;
        QVERIFY(!ScopeMathDefinition::fromJson(QJsonDocument::fromJson(json).object(), &message));
        QCOMPARE(message, error);
    }

    void badDefinitionsComputeNothing()
    {
        ScopeRecording recording;
        fill(recording, unevenTimes(10));
        QVERIFY(!computeScopeMath(definition(Kind::Sum, { 0 }), recording).ok());
        QVERIFY(!computeScopeMath(definition(Kind::Integral, { 4 }), recording).ok());
        ScopeMathDefinition average = definition(Kind::MovingAverage, { 0 });
        average.window = 0;
        QVERIFY(!computeScopeMath(average, recording).ok());
    }
};

QTEST_GUILESS_MAIN(TestScopeMath)
#include "tst_scopemath.moc"
