#include "DisplayScaling.h"

#include "DecimalText.h"
#include "DisplayUnit.h"

#include <QLocale>
#include <QRegularExpression>

#include <array>
#include <cmath>
#include <limits>

namespace DriveDesk {

namespace {

constexpr std::array<qint64, 19> kPow10 { {
    1LL,
    10LL,
    100LL,
    1000LL,
    10000LL,
    100000LL,
    1000000LL,
    10000000LL,
    100000000LL,
    1000000000LL,
    10000000000LL,
    100000000000LL,
    1000000000000LL,
    10000000000000LL,
    100000000000000LL,
    1000000000000000LL,
    10000000000000000LL,
    100000000000000000LL,
    1000000000000000000LL,
} };

// Integer a / b rounded half away from zero. b != 0; |a|, |b| < 2^62.
qint64 divideRounded(qint64 a, qint64 b)
{
    if (b < 0) {
        a = -a;
        b = -b;
    }
    const qint64 quotient = a / b;
    const qint64 remainder = a % b;
    if (2 * (remainder < 0 ? -remainder : remainder) >= b)
        return quotient + (a < 0 ? -1 : 1);
    return quotient;
}

// `scaled` / 10^decimals as text; a rounded zero carries no sign.
// The decimal separator of the language the user reads: QLocale's default, which the window
// sets to its language ("5,00 s" in German) and the command line keeps at C's '.' so that
// scripts read its output alike everywhere.
QChar decimalSeparator()
{
    const QString point = QLocale().decimalPoint();
    return point.size() == 1 ? point.front() : QLatin1Char('.');
}

QString fixedPoint(qint64 scaled, int decimals, bool trimZeros)
{
    const bool negative = scaled < 0;
    QString digits = QString::number(negative ? -scaled : scaled);
    if (decimals > 0) {
        if (digits.size() <= decimals)
            digits.prepend(QString(decimals - digits.size() + 1, QLatin1Char('0')));
        const QChar separator = decimalSeparator();
        digits.insert(digits.size() - decimals, separator);
        if (trimZeros) {
            while (digits.endsWith(QLatin1Char('0')))
                digits.chop(1);
            if (digits.endsWith(separator))
                digits.chop(1);
        }
    }
    if (negative && scaled != 0)
        digits.prepend(QLatin1Char('-'));
    return digits;
}

constexpr qint64 kExactMantissa = 1LL << 47;
constexpr int kExactDecimals = 14;
constexpr long double kRoundable = 4.0e18L; // llroundl stays defined below this

} // namespace

QString DisplayScaling::unitSymbol() const
{
    return displayUnitSymbol(unitCode());
}

DisplayScaling::Representation DisplayScaling::representation() const
{
    const int code = representationCode();
    return code <= int(Representation::Hexadecimal) ? Representation(code)
                                                    : Representation::Integer;
}

int DisplayScaling::decimals() const
{
    switch (representation()) {
    case Representation::F1:
    case Representation::F2:
    case Representation::F3:
    case Representation::F4:
        return representationCode();
    case Representation::VariableDecimals:
        return kMaxDecimals;
    case Representation::Integer:
    case Representation::Hexadecimal:
        break;
    }
    return 0;
}

QString DisplayScaling::invalidReason() const
{
    if (representation() == Representation::Hexadecimal)
        return {};
    if (calculationMode() > 1)
        return tr("calculation mode %1").arg(calculationMode());
    if (m_data.divisor == 0)
        return tr("divisor 0");
    return {};
}

std::optional<double> DisplayScaling::toDisplay(qint32 raw) const
{
    if (representation() == Representation::Hexadecimal)
        return double(raw);
    if (!isValid())
        return std::nullopt;
    const qint64 shifted = qint64(raw) + m_data.offset;
    if (calculationMode() == 0)
        return double(shifted * m_data.multiplier) / double(m_data.divisor);
    const qint64 denominator = shifted * m_data.divisor;
    if (denominator == 0)
        return std::nullopt;
    return double(m_data.multiplier) / double(denominator);
}

QString DisplayScaling::format(qint32 raw, bool withUnit) const
{
    const QString unit = withUnit ? unitSymbol() : QString();
    const QString suffix = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;

    if (representation() == Representation::Hexadecimal) {
        const auto bits = quint32(raw);
        const int width = bits > 0xFFFF ? 8 : 4;
        return QString::number(bits, 16).toUpper().rightJustified(width, QLatin1Char('0'))
            + QLatin1Char('h') + suffix;
    }

    const QString reason = invalidReason();
    if (!reason.isEmpty())
        return tr("%1 (no scaling: %2)").arg(raw).arg(reason);

    const std::optional<qint64> scaled = toFixedPoint(raw);
    if (!scaled)
        return tr("%1 (no scaling: value + offset is 0)").arg(raw);
    const bool trim = representation() == Representation::VariableDecimals;
    return fixedPoint(*scaled, decimals(), trim) + suffix;
}

std::optional<qint64> DisplayScaling::toFixedPoint(qint32 raw) const
{
    // The checks of invalidReason() without its texts.
    if (representation() == Representation::Hexadecimal || calculationMode() > 1
        || m_data.divisor == 0)
        return std::nullopt;
    const int shown = decimals();
    const qint64 shifted = qint64(raw) + m_data.offset;
    if (calculationMode() == 0)
        return divideRounded(shifted * m_data.multiplier * kPow10[shown], m_data.divisor);
    const qint64 denominator = shifted * m_data.divisor;
    if (denominator == 0)
        return std::nullopt;
    return divideRounded(qint64(m_data.multiplier) * kPow10[shown], denominator);
}

std::optional<qint32> DisplayScaling::parse(const QString &text, QString *error) const
{
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty()) {
        if (error)
            *error = tr("no value given");
        return std::nullopt;
    }
    if (representation() == Representation::Hexadecimal)
        return parseHex(trimmed, error);
    const QString reason = invalidReason();
    if (!reason.isEmpty()) {
        if (error)
            *error = tr("'%1' cannot be converted: the scaling of this parameter is invalid (%2)")
                         .arg(trimmed, reason);
        return std::nullopt;
    }
    return parseDecimal(trimmed, error);
}

bool DisplayScaling::acceptUnit(const QString &text, const QString &rest, QString *error) const
{
    if (rest.isEmpty())
        return true;
    const std::optional<int> code = displayUnitFromSymbol(rest);
    if (!code) {
        if (error)
            *error = tr("'%1' is not a number").arg(text);
        return false;
    }
    if (*code == unitCode())
        return true;
    if (error) {
        const QString ours = unitSymbol();
        *error = ours.isEmpty() ? tr("unit '%1' does not match: this value has no unit").arg(rest)
                                : tr("unit '%1' does not match '%2'").arg(rest, ours);
    }
    return false;
}

std::optional<qint32> DisplayScaling::parseHex(const QString &text, QString *error) const
{
    static const QRegularExpression pattern(QStringLiteral("^(0[xX])?([0-9A-Fa-f]+)([hH])?"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch()) {
        if (error)
            *error = tr("'%1' is not a hexadecimal number").arg(text);
        return std::nullopt;
    }
    if (!acceptUnit(text, text.mid(match.capturedLength()).trimmed(), error))
        return std::nullopt;
    QString digits = match.captured(2);
    while (digits.size() > 1 && digits.startsWith(QLatin1Char('0')))
        digits.remove(0, 1);
    if (digits.size() > 8) {
        if (error)
            *error = tr("'%1' does not fit in 32 bits").arg(text);
        return std::nullopt;
    }
    return qint32(digits.toUInt(nullptr, 16));
}

std::optional<qint32> DisplayScaling::parseDecimal(const QString &text, QString *error) const
{
    auto fail = [error](const QString &message) -> std::optional<qint32> {
        if (error)
            *error = message;
        return std::nullopt;
    };

    const std::optional<DecimalText> number = DecimalText::read(text);
    if (!number)
        return fail(tr("'%1' is not a number").arg(text));
    if (!acceptUnit(text, text.mid(number->length).trimmed(), error))
        return std::nullopt;

    const bool negative = number->negative;
    const QString &integral = number->integral;
    const QString &fraction = number->fraction;
    const QString digits = integral + fraction;
    if (digits.size() > 18)
        return fail(tr("'%1' has too many digits").arg(text));
    const qint64 mantissa = digits.isEmpty() ? 0 : digits.toLongLong();
    const qint64 value = negative ? -mantissa : mantissa; // value / 10^exponent
    const int exponent = int(fraction.size());
    const qint64 multiplier = m_data.multiplier;
    const qint64 divisor = m_data.divisor;

    if (multiplier == 0) {
        return fail(value == 0 ? tr("every raw value shows 0 in this scaling (multiplier 0): "
                                    "the raw value cannot be chosen")
                               : tr("no raw value gives %1 in this scaling").arg(text));
    }

    long double shifted = 0; // raw + offset
    if (calculationMode() == 0) {
        if (mantissa <= kExactMantissa && exponent <= kExactDecimals) {
            shifted = divideRounded(value * divisor, kPow10[exponent] * multiplier);
        } else {
            const long double exact
                = (long double)value * divisor / ((long double)kPow10[exponent] * multiplier);
            if (std::fabs(exact) > kRoundable)
                return fail(tr("'%1' is out of range").arg(text));
            shifted = std::llround(exact);
        }
    } else {
        if (value == 0)
            return fail(tr("no raw value gives 0 in this scaling"));
        // Reciprocal: of the two raw values around the exact one, the one showing nearer.
        const long double target = (long double)value / kPow10[exponent];
        const long double exact
            = (long double)multiplier * kPow10[exponent] / ((long double)value * divisor);
        if (std::fabs(exact) > kRoundable)
            return fail(tr("'%1' is out of range").arg(text));
        std::optional<long double> best;
        long double bestDistance = 0;
        for (const long double candidate : { std::floor(exact), std::ceil(exact) }) {
            if (candidate == 0)
                continue; // would divide by zero
            const long double shown = (long double)multiplier / (candidate * divisor);
            const long double distance = std::fabs(shown - target);
            if (!best || distance < bestDistance) {
                best = candidate;
                bestDistance = distance;
            }
        }
        shifted = *best; // floor and ceil are both 0 only for exact == 0, ruled out above
    }

    const long double raw = shifted - m_data.offset;
    if (raw < std::numeric_limits<qint32>::min() || raw > std::numeric_limits<qint32>::max()) {
        return fail(tr("'%1' is out of range: it needs raw value %2, beyond 32 bits")
                        .arg(text)
                        .arg(qint64(raw)));
    }
    return qint32(raw);
}

} // namespace DriveDesk
