#pragma once

#include "protocol/Telegram.h"

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace DriveDesk {

// Turns a raw parameter value into the number a user reads and back (service 5, seed 002 2.7).
// Calculation mode 0: display = (raw + offset) * multiplier / divisor; mode 1:
// display = multiplier / ((raw + offset) * divisor). Hexadecimal shows the raw bits unscaled.
// A divisor of 0, or a free calculation mode, is never divided by: the raw value is shown
// with the reason, and parse() refuses.
class DisplayScaling
{
    Q_DECLARE_TR_FUNCTIONS(DisplayScaling)
public:
    // Representation, flags bits 8-11. Codes 7-15 are free and shown as Integer.
    enum class Representation : quint8 {
        Integer = 0,
        F1 = 1,
        F2 = 2,
        F3 = 3,
        F4 = 4,
        VariableDecimals = 5, // up to 4, trailing zeros trimmed
        Hexadecimal = 6,
    };

    static constexpr int kMaxDecimals = 4;

    // Identity: divisor 1, multiplier 1, offset 0, no unit, integer.
    DisplayScaling() = default;
    explicit DisplayScaling(const DisplayScalingData &data)
        : m_data(data)
    { }

    const DisplayScalingData &data() const { return m_data; }
    int unitCode() const { return m_data.flags & 0x3F; }
    QString unitSymbol() const; // empty for no unit and unknown codes
    int calculationMode() const { return (m_data.flags >> 6) & 0x03; }
    int representationCode() const { return (m_data.flags >> 8) & 0x0F; }
    Representation representation() const;
    // Decimals shown: 0..4; variable decimals report the most they show (4).
    int decimals() const;

    // Why no value can be scaled ("divisor 0", "calculation mode 2"); empty when usable.
    QString invalidReason() const;
    bool isValid() const { return invalidReason().isEmpty(); }

    // The unrounded display number, e.g. for plotting; nothing where the scaling is invalid.
    std::optional<double> toDisplay(qint32 raw) const;
    // The display number in units of 10^-decimals(), rounded half away from zero: what format()
    // shows, as an integer (1250 for "12.50"). Nothing for hexadecimal, an invalid scaling, or
    // calculation mode 1 with raw + offset = 0. Allocates nothing: the scope's CSV export
    // formats millions of values with it.
    std::optional<qint64> toFixedPoint(qint32 raw) const;
    // "12.50 Hz", "-3.5 %", "00FFh"; an invalid scaling gives "1234 (no scaling: divisor 0)".
    // The decimal separator is the default QLocale's: "12,50 Hz" where the window speaks German.
    QString format(qint32 raw, bool withUnit = true) const;
    // The inverse of format(): the raw value nearest to the text, with or without its unit,
    // '.' or ',' as decimal separator; hexadecimal as "FF", "0xFF" or "FFh".
    std::optional<qint32> parse(const QString &text, QString *error = nullptr) const;

private:
    std::optional<qint32> parseHex(const QString &text, QString *error) const;
    std::optional<qint32> parseDecimal(const QString &text, QString *error) const;
    // Checks the text after the number; false with the message when it is not our unit.
    bool acceptUnit(const QString &text, const QString &rest, QString *error) const;

    DisplayScalingData m_data { 0, 1, 1, 0, 0 };
};

} // namespace DriveDesk
