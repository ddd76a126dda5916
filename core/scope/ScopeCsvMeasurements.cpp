// The CSV export's measurements section and its column headers (ScopeCsv.h).
#include "ScopeCsv.h"

#include "ScopeMeasurements.h"
#include "ScopeRecording.h"
#include "ScopeSeries.h"
#include "parameters/ParameterCsv.h"

#include <QStringList>

#include <array>
#include <charconv>
#include <functional>

namespace DriveDesk {

namespace {

// The shortest text that reads back as the same double, '.' as separator.
QString exact(double value)
{
    std::array<char, 32> text {};
    const std::to_chars_result result = std::to_chars(text.data(), text.data() + text.size(), value);
    return QString::fromLatin1(text.data(), result.ptr - text.data());
}

QString exact(std::optional<double> value)
{
    return value ? exact(*value) : QString();
}

} // namespace

QString scopeCsvColumnHeader(const ScopeChannel &channel, int index)
{
    const QString unit = channel.unit();
    return unit.isEmpty() ? channel.title(index)
                          : QStringLiteral("%1 [%2]").arg(channel.title(index), unit);
}

QByteArray scopeCsvMeasurements(const ScopeRecording &recording, const QList<int> &channels,
                                double fromMs, double toMs,
                                const QList<const ScopeSeries *> &math)
{
    if (toMs < fromMs)
        std::swap(fromMs, toMs);
    QList<ScopeMeasurements> measured;
    for (const int channel : channels)
        measured << measureScope(recording, channel, fromMs, toMs);
    for (const ScopeSeries *series : math)
        measured << measureScope(*series, fromMs, toMs);
    const double origin = double(recording.firstTime());

    using Quantity = std::function<std::optional<double>(const ScopeMeasurements &)>;
    const auto always = [](double (*get)(const ScopeMeasurements &)) {
        return Quantity([get](const ScopeMeasurements &m) -> std::optional<double> {
            return m.samples > 0 ? std::optional(get(m)) : std::nullopt;
        });
    };
    const auto duration = [](std::optional<ScopeTransition> ScopeMeasurements::*which) {
        return Quantity([which](const ScopeMeasurements &m) -> std::optional<double> {
            const std::optional<ScopeTransition> &t = m.*which;
            return t ? std::optional(t->durationMs()) : std::nullopt;
        });
    };
    const auto rate = [](std::optional<ScopeTransition> ScopeMeasurements::*which) {
        return Quantity([which](const ScopeMeasurements &m) -> std::optional<double> {
            const std::optional<ScopeTransition> &t = m.*which;
            return t ? t->ratePerSecond : std::nullopt;
        });
    };
    // Not translated: tools find the rows by name, as the samples' header.
    const std::array<std::pair<const char *, Quantity>, 10> rows { {
        { "Samples",
          [](const ScopeMeasurements &m) { return std::optional(double(m.samples)); } },
        { "Minimum", always([](const ScopeMeasurements &m) { return m.minimum; }) },
        { "Maximum", always([](const ScopeMeasurements &m) { return m.maximum; }) },
        { "Peak to peak", always([](const ScopeMeasurements &m) { return m.peakToPeak(); }) },
        { "Mean", always([](const ScopeMeasurements &m) { return m.mean; }) },
        { "RMS", always([](const ScopeMeasurements &m) { return m.rms; }) },
        { "Rise time [ms]", duration(&ScopeMeasurements::rise) },
        { "Rise rate [unit/s]", rate(&ScopeMeasurements::rise) },
        { "Fall time [ms]", duration(&ScopeMeasurements::fall) },
        { "Fall rate [unit/s]", rate(&ScopeMeasurements::fall) },
    } };

    QStringList header { QStringLiteral("Measurement") };
    for (const int channel : channels)
        header << scopeCsvColumnHeader(recording.channels.at(channel), channel);
    for (const ScopeSeries *series : math)
        header << series->label();
    QString text = csvRecord(header) + QStringLiteral("\r\n");
    const auto timeRow = [&](const char *name, double ms) {
        QStringList fields { QLatin1String(name) };
        for (qsizetype i = 0; i < measured.size(); ++i)
            fields << exact(ms - origin);
        text += csvRecord(fields) + QStringLiteral("\r\n");
    };
    // In the file's time: ms since the recording's first sample.
    timeRow("From [ms]", fromMs);
    timeRow("To [ms]", toMs);
    for (const auto &[name, quantity] : rows) {
        QStringList fields { QLatin1String(name) };
        for (const ScopeMeasurements &m : measured)
            fields << exact(quantity(m));
        text += csvRecord(fields) + QStringLiteral("\r\n");
    }
    return text.toUtf8();
}

} // namespace DriveDesk
