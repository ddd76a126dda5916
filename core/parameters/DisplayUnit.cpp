#include "DisplayUnit.h"

#include <array>

namespace DriveDesk {

namespace {

constexpr std::array<const char *, kDisplayUnitCount> kSymbols { {
    "",   "mm",  "cm",  "m",    "km",   "g",    "kg",    "µs",  "ms",  "s",  "h",
    "Nm", "kNm", "m/s", "m/s²", "m/s³", "km/h", "1/min", "Hz",  "kHz", "mV", "V",
    "kV", "mW",  "W",   "kW",   "VA",   "kVA",  "mA",    "A",   "kA",  "°C", "K",
    "mΩ", "Ω",   "kΩ",  "INC",  "%",    "kWh",  "mH",    "s/h",
} };

struct Alias
{
    const char *spelling;
    int code;
};

// ASCII spellings of the symbols, and the seed's own "us" and "KWh".
constexpr std::array<Alias, 14> kAliases { {
    { "us", 7 },
    { "m/s2", 14 },
    { "m/s^2", 14 },
    { "m/s3", 15 },
    { "m/s^3", 15 },
    { "rpm", 17 },
    { "degC", 31 },
    { "mOhm", 33 },
    { "Ohm", 34 },
    { "kOhm", 35 },
    { "KWh", 38 },
    { "µs", 7 },
    { "μs", 7 },
    { "1/min", 17 },
} };

} // namespace

QString displayUnitSymbol(int code)
{
    if (code < 0 || code >= kDisplayUnitCount)
        return {};
    return QString::fromUtf8(kSymbols[std::size_t(code)]);
}

std::optional<int> displayUnitFromSymbol(const QString &symbol)
{
    const QString wanted = symbol.trimmed();
    if (wanted.isEmpty())
        return std::nullopt;
    for (int code = 1; code < kDisplayUnitCount; ++code) {
        if (wanted == displayUnitSymbol(code))
            return code;
    }
    for (const Alias &alias : kAliases) {
        if (wanted.compare(QString::fromUtf8(alias.spelling), Qt::CaseInsensitive) == 0)
            return alias.code;
    }
    std::optional<int> found;
    for (int code = 1; code < kDisplayUnitCount; ++code) {
        if (wanted.compare(displayUnitSymbol(code), Qt::CaseInsensitive) == 0) {
            if (found)
                return std::nullopt; // two units differ only in case: the user must say which
            found = code;
        }
    }
    return found;
}

QString withUnit(const QString &number, const QString &unit)
{
    return unit.isEmpty() ? number : number + QLatin1Char(' ') + unit;
}

} // namespace DriveDesk
