#include "ScopeMathDefinition.h"

#include "ScopeSample.h"
#include "parameters/JsonObjectReader.h"

#include <QJsonArray>

#include <array>
#include <cmath>

namespace DriveDesk {

namespace {

using Kind = ScopeMathDefinition::Kind;

struct KindName
{
    Kind kind;
    const char *key;
};

// The names in the file: not translated.
constexpr std::array<KindName, 5> kKinds { {
    { Kind::Derivative, "derivative" },
    { Kind::Integral, "integral" },
    { Kind::Difference, "difference" },
    { Kind::Sum, "sum" },
    { Kind::MovingAverage, "movingAverage" },
} };

QString kindKey(Kind kind)
{
    for (const KindName &name : kKinds) {
        if (name.kind == kind)
            return QLatin1String(name.key);
    }
    return {};
}

QString windowUnitKey(ScopeMathDefinition::WindowUnit unit)
{
    return unit == ScopeMathDefinition::WindowUnit::Samples ? QStringLiteral("samples")
                                                            : QStringLiteral("ms");
}

// "m/s" over time: a trailing /s gains a power, a trailing ·s goes.
QString perSecond(const QString &unit)
{
    if (unit.isEmpty())
        return QStringLiteral("1/s");
    if (unit.endsWith(QStringLiteral("·s")))
        return unit.chopped(2);
    if (unit.endsWith(QStringLiteral("/s")))
        return unit + QStringLiteral("²");
    if (unit.endsWith(QStringLiteral("/s²")))
        return unit.chopped(1) + QStringLiteral("³");
    if (unit.contains(QLatin1Char('/')))
        return QStringLiteral("(%1)/s").arg(unit);
    return unit + QStringLiteral("/s");
}

// "A" times time: the inverse of perSecond().
QString timesSecond(const QString &unit)
{
    if (unit.isEmpty())
        return QStringLiteral("s");
    if (unit == QLatin1String("1/s"))
        return {};
    if (unit.endsWith(QStringLiteral("/s")))
        return unit.chopped(2);
    if (unit.endsWith(QStringLiteral("/s²")))
        return unit.chopped(1);
    if (unit.endsWith(QStringLiteral("/s³")))
        return unit.chopped(1) + QStringLiteral("²");
    if (unit.contains(QLatin1Char('/')))
        return QStringLiteral("(%1)·s").arg(unit);
    return unit + QStringLiteral("·s");
}

} // namespace

int ScopeMathDefinition::sourceCount(Kind kind)
{
    return kind == Kind::Difference || kind == Kind::Sum ? 2 : 1;
}

QString ScopeMathDefinition::check(int channelCount) const
{
    if (sources.size() != sourceCount(kind)) {
        return sourceCount(kind) == 2
            ? tr("a difference or a sum reads two channels")
            : tr("a derivative, an integral or a moving average reads one channel");
    }
    for (const int source : sources) {
        if (source < 0 || source >= channelCount)
            return tr("there is no channel %1 (1..%2)").arg(source + 1).arg(channelCount);
    }
    return checkWindow();
}

QString ScopeMathDefinition::checkWindow() const
{
    if (kind != Kind::MovingAverage)
        return {};
    const bool samples = windowUnit == WindowUnit::Samples;
    // Beyond a billion (samples or ms) a window is a mistake; below it, it fits a size_t.
    if (!std::isfinite(window) || window > 1e9
        || (samples ? window < 1 || std::trunc(window) != window : window <= 0)) {
        return samples ? tr("the window is a whole number of samples, at least 1")
                       : tr("the window is a time in ms, more than 0");
    }
    return {};
}

QJsonObject ScopeMathDefinition::toJson() const
{
    QJsonArray channels;
    for (const int source : sources)
        channels.append(source);
    QJsonObject json { { QStringLiteral("kind"), kindKey(kind) },
                       { QStringLiteral("sources"), channels } };
    if (kind == Kind::MovingAverage) {
        json.insert(QStringLiteral("window"), window);
        json.insert(QStringLiteral("windowUnit"), windowUnitKey(windowUnit));
    }
    return json;
}

std::optional<ScopeMathDefinition> ScopeMathDefinition::fromJson(const QJsonObject &json,
                                                                 QString *error)
{
    ScopeMathDefinition definition;
    JsonFault fault;
    JsonObjectReader reader(json, QString(), &fault);
    const QString kindName = reader.string(QStringLiteral("kind"));
    bool known = false;
    for (const KindName &name : kKinds) {
        if (kindName == QLatin1String(name.key)) {
            definition.kind = name.kind;
            known = true;
        }
    }
    if (reader.ok() && !known)
        reader.fail(QStringLiteral("kind"), tr("unknown kind \"%1\"").arg(kindName));

    const QString sourcesKey = QStringLiteral("sources");
    const QJsonArray sources = reader.array(sourcesKey);
    definition.sources.clear();
    for (qsizetype i = 0; reader.ok() && i < sources.size(); ++i) {
        const auto source
            = reader.checkedInteger(sources.at(i), JsonObjectReader::indexed(sourcesKey, i), 0,
                                    ScopeSample::kChannelCount - 1);
        definition.sources << int(source.value_or(0));
    }
    if (definition.kind == Kind::MovingAverage) {
        const QString windowKey = QStringLiteral("window");
        const QJsonValue window = reader.value(windowKey);
        if (reader.ok() && !window.isDouble())
            reader.fail(windowKey, tr("expected a number"));
        definition.window = window.toDouble();
        const QString unitKey = QStringLiteral("windowUnit");
        const QString unit = reader.string(unitKey);
        if (unit == windowUnitKey(WindowUnit::Milliseconds))
            definition.windowUnit = WindowUnit::Milliseconds;
        else if (reader.ok() && unit != windowUnitKey(WindowUnit::Samples))
            reader.fail(unitKey, tr("expected samples or ms"));
    }
    reader.finish();
    if (fault.isEmpty()) {
        const QString wrong = definition.check(ScopeSample::kChannelCount);
        if (!wrong.isEmpty()) {
            const bool aboutWindow = definition.sources.size() == sourceCount(definition.kind);
            reader.fail(aboutWindow ? QStringLiteral("window") : sourcesKey, wrong);
        }
    }
    if (!fault.isEmpty()) {
        if (error)
            *error = fault.text();
        return std::nullopt;
    }
    return definition;
}

ScopeMathUnit scopeMathUnit(ScopeMathDefinition::Kind kind, const QString &first,
                            const QString &second)
{
    const auto unit = [](const QString &symbol) { return ScopeMathUnit { symbol, false, symbol }; };
    switch (kind) {
    case Kind::Derivative:
        return unit(perSecond(first));
    case Kind::Integral:
        return unit(timesSecond(first));
    case Kind::Difference:
    case Kind::Sum:
        if (first == second)
            return unit(first);
        return { QString(), true,
                 ScopeMathDefinition::tr("the units differ: %1, %2")
                     .arg(first.isEmpty() ? ScopeMathDefinition::tr("none") : first,
                          second.isEmpty() ? ScopeMathDefinition::tr("none") : second) };
    case Kind::MovingAverage:
        break;
    }
    return unit(first);
}

QString scopeMathTitle(const ScopeMathDefinition &definition, const QString &first,
                       const QString &second)
{
    switch (definition.kind) {
    case Kind::Derivative:
        return ScopeMathDefinition::tr("d/dt %1").arg(first);
    case Kind::Integral:
        return ScopeMathDefinition::tr("∫ %1 dt").arg(first);
    case Kind::Difference:
        return ScopeMathDefinition::tr("%1 − %2").arg(first, second);
    case Kind::Sum:
        return ScopeMathDefinition::tr("%1 + %2").arg(first, second);
    case Kind::MovingAverage:
        break;
    }
    if (definition.windowUnit == ScopeMathDefinition::WindowUnit::Samples)
        return ScopeMathDefinition::tr("%1, mean of %n sample(s)", nullptr, int(definition.window))
            .arg(first);
    return ScopeMathDefinition::tr("%1, mean over %2 ms").arg(first).arg(definition.window);
}

} // namespace DriveDesk
