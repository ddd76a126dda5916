#include "ParameterProperties.h"

#include <array>

namespace DriveDesk {

namespace {

struct Flag
{
    int bit;
    const char *text;
};

constexpr std::array<const char *, 4> kWidths { {
    QT_TRANSLATE_NOOP("ParameterProperties", "stored as byte"),
    QT_TRANSLATE_NOOP("ParameterProperties", "stored as word"),
    QT_TRANSLATE_NOOP("ParameterProperties", "stored as long"),
    QT_TRANSLATE_NOOP("ParameterProperties", "storage width 3 (not used)"),
} };

constexpr std::array<const char *, 4> kScalingResults { {
    QT_TRANSLATE_NOOP("ParameterProperties", "scaling result: byte"),
    QT_TRANSLATE_NOOP("ParameterProperties", "scaling result: word"),
    QT_TRANSLATE_NOOP("ParameterProperties", "scaling result: long"),
    QT_TRANSLATE_NOOP("ParameterProperties", "scaling result: none"),
} };

// The limit types other than constant, each as the whole line for the lower and the upper limit.
constexpr std::array<const char *, 3> kLowerLimits { {
    QT_TRANSLATE_NOOP("ParameterProperties", "lower limit variable at power on"),
    QT_TRANSLATE_NOOP("ParameterProperties", "lower limit always variable"),
    QT_TRANSLATE_NOOP("ParameterProperties", "lower limit type 3 (not used)"),
} };

constexpr std::array<const char *, 3> kUpperLimits { {
    QT_TRANSLATE_NOOP("ParameterProperties", "upper limit variable at power on"),
    QT_TRANSLATE_NOOP("ParameterProperties", "upper limit always variable"),
    QT_TRANSLATE_NOOP("ParameterProperties", "upper limit type 3 (not used)"),
} };

constexpr std::array<const char *, 4> kEnterModes { {
    QT_TRANSLATE_NOOP("ParameterProperties", "no enter"),
    QT_TRANSLATE_NOOP("ParameterProperties", "enter with dot"),
    QT_TRANSLATE_NOOP("ParameterProperties", "enter without dot"),
    QT_TRANSLATE_NOOP("ParameterProperties", "enter mode 3 (not used)"),
} };

constexpr std::array<const char *, 4> kFilterings { {
    QT_TRANSLATE_NOOP("ParameterProperties", "no display filtering"),
    QT_TRANSLATE_NOOP("ParameterProperties", "display filtering: time slot"),
    QT_TRANSLATE_NOOP("ParameterProperties", "display filtering: filter"),
    QT_TRANSLATE_NOOP("ParameterProperties", "display filtering 3 (not used)"),
} };

// Single bits of properties 1 worth naming when set (the fields are named separately).
constexpr std::array<Flag, 10> kFlags1 { {
    { 10, QT_TRANSLATE_NOOP("ParameterProperties", "signed") },
    { 11, QT_TRANSLATE_NOOP("ParameterProperties", "set-programmable") },
    { 16, QT_TRANSLATE_NOOP("ParameterProperties", "writable while the active set is displayed") },
    { 17, QT_TRANSLATE_NOOP("ParameterProperties", "scaled in the background") },
    { 18, QT_TRANSLATE_NOOP("ParameterProperties", "variable default value") },
    { 19, QT_TRANSLATE_NOOP("ParameterProperties", "default loaded only for a new device") },
    { 28,
      QT_TRANSLATE_NOOP("ParameterProperties",
                        "not permitted as process data or for surveillance") },
    { 29, QT_TRANSLATE_NOOP("ParameterProperties", "encoder parameter") },
    { 30, QT_TRANSLATE_NOOP("ParameterProperties", "system parameter") },
    { 31, QT_TRANSLATE_NOOP("ParameterProperties", "variable display scaling") },
} };

constexpr std::array<Flag, 20> kFlags2 { {
    { 0, QT_TRANSLATE_NOOP("ParameterProperties", "visible on the display") },
    { 1, QT_TRANSLATE_NOOP("ParameterProperties", "writable on the display") },
    { 2, QT_TRANSLATE_NOOP("ParameterProperties", "visible in COMBIVIS") },
    { 3, QT_TRANSLATE_NOOP("ParameterProperties", "writable via COMBIVIS") },
    { 8, QT_TRANSLATE_NOOP("ParameterProperties", "rotating count") },
    { 9, QT_TRANSLATE_NOOP("ParameterProperties", "changed by the inverter") },
    { 10, QT_TRANSLATE_NOOP("ParameterProperties", "value without plaintext not displayed") },
    { 11,
      QT_TRANSLATE_NOOP(
          "ParameterProperties",
          "configuration flag set (indirect configuration parameters, offline time base µs)") },
    { 12,
      QT_TRANSLATE_NOOP("ParameterProperties", "write always: written by upload and download") },
    { 13,
      QT_TRANSLATE_NOOP("ParameterProperties",
                        "write only: not read by upload, written by download") },
    { 14, QT_TRANSLATE_NOOP("ParameterProperties", "excluded from the complete parameter list") },
    { 15, QT_TRANSLATE_NOOP("ParameterProperties", "not permitted as CP parameter") },
    { 16, QT_TRANSLATE_NOOP("ParameterProperties", "decimal value of plaintexts suppressed") },
    { 17,
      QT_TRANSLATE_NOOP("ParameterProperties",
                        "read-only for up/download lists: not written by download") },
    { 18, QT_TRANSLATE_NOOP("ParameterProperties", "protected") },
    { 19, QT_TRANSLATE_NOOP("ParameterProperties", "writable only at nop or error") },
    { 20, QT_TRANSLATE_NOOP("ParameterProperties", "default not loaded while invisible") },
    { 21, QT_TRANSLATE_NOOP("ParameterProperties", "shows the state at 'NOP' and 'LS'") },
    { 22, QT_TRANSLATE_NOOP("ParameterProperties", "indirectly addressed") },
    { 23, QT_TRANSLATE_NOOP("ParameterProperties", "not set-programmable for 'foc synchron'") },
} };

QStringList inverterTypes(quint32 bits)
{
    QStringList types;
    for (int type = 0; type < ParameterProperties::kInverterTypes; ++type) {
        if (bits & (1u << type))
            types << QString::number(type);
    }
    return types;
}

} // namespace

bool ParameterProperties::isVisibleForInverterType(int type) const
{
    return type >= 0 && type < kInverterTypes && bit1(20 + type);
}

bool ParameterProperties::isWritableForInverterType(int type) const
{
    return type >= 0 && type < kInverterTypes && bit1(24 + type);
}

QStringList ParameterProperties::describe() const
{
    QStringList lines;
    lines << tr("read level: %1").arg(passwordLevelName(readLevel()));
    lines << tr("write level: %1").arg(passwordLevelName(writeLevel()));
    lines << tr(kWidths[std::size_t(width())]);
    lines << tr(kScalingResults[std::size_t(scalingResult())]);
    if (lowerLimitType() != LimitType::Constant)
        lines << tr(kLowerLimits[std::size_t(lowerLimitType()) - 1]);
    if (upperLimitType() != LimitType::Constant)
        lines << tr(kUpperLimits[std::size_t(upperLimitType()) - 1]);
    if (const QStringList visible = inverterTypes(field1(20, 4)); !visible.isEmpty()) {
        const int count = int(visible.size());
        lines << tr("visible for inverter type(s) %1", nullptr, count)
                     .arg(visible.join(QStringLiteral(", ")));
    }
    if (const QStringList writable = inverterTypes(field1(24, 4)); !writable.isEmpty()) {
        const int count = int(writable.size());
        lines << tr("writable for inverter type(s) %1", nullptr, count)
                     .arg(writable.join(QStringLiteral(", ")));
    }
    for (const Flag &flag : kFlags1) {
        if (bit1(flag.bit))
            lines << tr(flag.text);
    }

    if (isReadOnly())
        lines << tr("read-only via COMBIVIS");
    if (enterMode() != EnterMode::None)
        lines << tr(kEnterModes[std::size_t(enterMode())]);
    if (displayFiltering() != DisplayFiltering::None)
        lines << tr(kFilterings[std::size_t(displayFiltering())]);
    for (const Flag &flag : kFlags2) {
        if (bit2(flag.bit))
            lines << tr(flag.text);
    }
    // The free bits are named too: a drive that sets them means something by it.
    for (int bit = 24; bit < 32; ++bit) {
        if (bit2(bit))
            lines << tr("properties 2: free bit %1 set").arg(bit);
    }
    return lines;
}

} // namespace DriveDesk
