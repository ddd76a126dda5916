#include "ParameterSpec.h"

#include "DataText.h"

#include <QLatin1StringView>

namespace DriveDesk::Sim {

namespace {

struct UnitEntry
{
    const char *name;
    int code;
};

// Seed 002 2.7.1, bits 0-5 of the display flags.
constexpr UnitEntry kUnits[] = {
    { "", 0 },     { "hex", 0 },   { "mm", 1 },   { "cm", 2 },    { "m", 3 },    { "km", 4 },
    { "g", 5 },    { "kg", 6 },    { "us", 7 },   { "ms", 8 },    { "s", 9 },    { "h", 10 },
    { "Nm", 11 },  { "kNm", 12 },  { "m/s", 13 }, { "km/h", 16 }, { "rpm", 17 }, { "1/min", 17 },
    { "Hz", 18 },  { "kHz", 19 },  { "mV", 20 },  { "V", 21 },    { "kV", 22 },  { "mW", 23 },
    { "W", 24 },   { "kW", 25 },   { "VA", 26 },  { "kVA", 27 },  { "mA", 28 },  { "A", 29 },
    { "kA", 30 },  { "degC", 31 }, { "K", 32 },   { "mOhm", 33 }, { "Ohm", 34 }, { "kOhm", 35 },
    { "inc", 36 }, { "%", 37 },    { "kWh", 38 }, { "mH", 39 },   { "s/h", 40 },
};

enum class Width : quint32 { Byte = 0, Word = 1, Long = 2 };

Width widthFor(qint32 minimum, qint32 maximum)
{
    if (minimum < 0) {
        if (minimum >= -128 && maximum <= 127)
            return Width::Byte;
        if (minimum >= -32768 && maximum <= 32767)
            return Width::Word;
        return Width::Long;
    }
    if (maximum <= 0xFF)
        return Width::Byte;
    if (maximum <= 0xFFFF)
        return Width::Word;
    return Width::Long;
}

} // namespace

std::optional<ParameterFlags> parseFlags(const QString &letters, QChar *bad)
{
    ParameterFlags flags;
    for (const QChar c : letters) {
        switch (c.toLatin1()) {
        case 'r':
            flags.readOnly = true;
            break;
        case 's':
            flags.setProgrammable = true;
            break;
        case 'k':
            flags.keypadReadOnly = true;
            break;
        case 'e':
            flags.enter = true;
            break;
        case 'h':
            flags.hex = true;
            break;
        case 'n':
            flags.noProcessData = true;
            break;
        case 'x':
            flags.excluded = true;
            break;
        case 'd':
            flags.plaintextOnly = true;
            break;
        case 'a':
            flags.writeAlways = true;
            break;
        case 'o':
            flags.writeOnly = true;
            break;
        case 'l':
            flags.listReadOnly = true;
            break;
        default:
            if (bad)
                *bad = c;
            return std::nullopt;
        }
    }
    return flags;
}

std::optional<int> unitCode(const QString &unit)
{
    for (const UnitEntry &entry : kUnits) {
        if (unit == QLatin1StringView(entry.name))
            return entry.code;
    }
    return std::nullopt;
}

SimParameter buildParameter(const ParameterSpec &spec, QStringList &problems)
{
    SimParameter p;
    p.address = spec.address;
    p.name[0] = lineText(spec.nameEn, spec.id + QStringLiteral(": English name"), problems);
    p.name[1] = lineText(spec.nameDe, spec.id + QStringLiteral(": German name"), problems);
    if (spec.nameEn.isEmpty() || spec.nameDe.isEmpty())
        problems << QStringLiteral("%1: a name is missing").arg(spec.id);
    p.minimum = spec.minimum;
    p.maximum = spec.maximum;
    p.defaultValue = spec.defaultValue;
    p.enumeration = spec.enumeration;
    p.signal = spec.signal;
    if (spec.minimum > spec.maximum)
        problems << QStringLiteral("%1: lower limit %2 above upper limit %3")
                        .arg(spec.id)
                        .arg(spec.minimum)
                        .arg(spec.maximum);
    if (spec.defaultValue < spec.minimum || spec.defaultValue > spec.maximum)
        problems << QStringLiteral("%1: default %2 outside %3..%4")
                        .arg(spec.id)
                        .arg(spec.defaultValue)
                        .arg(spec.minimum)
                        .arg(spec.maximum);

    const ParameterFlags &f = spec.flags;
    const bool writable = !f.readOnly;
    const bool live = spec.signal != LiveSignal::None;
    const auto width = quint32(widthFor(spec.minimum, spec.maximum));
    quint32 p1 = quint32(spec.readLevel & 7) | quint32(spec.writeLevel & 7) << 3;
    p1 |= width << 6; // type of the parameter
    p1 |= width << 8; // type of the scaling result
    if (spec.minimum < 0)
        p1 |= 1u << 10; // signed
    if (f.setProgrammable)
        p1 |= 1u << 11;
    if (f.setProgrammable && writable)
        p1 |= 1u << 16; // writable while the active set is shown
    p1 |= 0xFu << 20; // visible for all four inverter types
    if (writable)
        p1 |= 0xFu << 24; // writable for all four inverter types
    if (f.noProcessData)
        p1 |= 1u << 28;
    if (spec.encoderParameter)
        p1 |= 1u << 29;
    if (spec.systemParameter)
        p1 |= 1u << 30;
    p.properties1 = p1;

    quint32 p2 = 1u | 1u << 2; // visible on the display and in COMBIVIS
    if (writable && !f.keypadReadOnly)
        p2 |= 1u << 1;
    if (writable)
        p2 |= 1u << 3;
    if (f.enter)
        p2 |= 1u << 4; // ENTER with dot
    if (live)
        p2 |= 1u << 6 | 1u << 9; // time-slot display filter; the inverter changes the value
    if (f.writeAlways)
        p2 |= 1u << 12;
    if (f.writeOnly)
        p2 |= 1u << 13;
    if (f.excluded)
        p2 |= 1u << 14;
    if (f.noProcessData || f.excluded)
        p2 |= 1u << 15; // not permitted as CP parameter
    if (f.plaintextOnly)
        p2 |= 1u << 16;
    if (f.readOnly || f.listReadOnly)
        p2 |= 1u << 17; // read only for up/download lists
    p.properties2 = p2;

    const std::optional<int> unit = unitCode(spec.unit);
    if (!unit)
        problems << QStringLiteral("%1: unknown unit \"%2\"").arg(spec.id, spec.unit);
    int divisor = 1;
    for (int i = 0; i < spec.decimals; ++i)
        divisor *= 10;
    const int representation = f.hex ? 6 : qBound(0, spec.decimals, 4);
    p.scaling.address = spec.address;
    p.scaling.divisor = spec.explicitScale ? spec.divisor : qint16(divisor);
    p.scaling.multiplier = spec.explicitScale ? spec.multiplier : qint16(1);
    p.scaling.offset = spec.explicitScale ? spec.offset : qint16(0);
    p.scaling.flags = quint16(unit.value_or(0) | representation << 8);

    p.initial.fill(spec.defaultValue);
    if (spec.initial.size() == 1) {
        p.initial.fill(spec.initial.first());
    } else if (spec.initial.size() == kSets && f.setProgrammable) {
        for (int set = 0; set < kSets; ++set)
            p.initial[std::size_t(set)] = spec.initial.at(set);
    } else if (!spec.initial.isEmpty()) {
        problems << QStringLiteral("%1: %2 initial values; give one, or 8 for a set-programmable "
                                   "parameter")
                        .arg(spec.id)
                        .arg(spec.initial.size());
    }
    for (qint32 value : p.initial) {
        if (!live && (value < spec.minimum || value > spec.maximum)) {
            problems << QStringLiteral("%1: initial value %2 outside %3..%4")
                            .arg(spec.id)
                            .arg(value)
                            .arg(spec.minimum)
                            .arg(spec.maximum);
            break;
        }
    }
    return p;
}

} // namespace DriveDesk::Sim
