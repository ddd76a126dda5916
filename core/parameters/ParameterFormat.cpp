#include "ParameterFormat.h"

#include "DecimalText.h"

#include <QRegularExpression>

#include <limits>

namespace DriveDesk {

namespace {

// The number at the start of a text as "-12.5"; empty when the text does not start with one.
QString canonicalNumber(const QString &text)
{
    const std::optional<DecimalText> number = DecimalText::read(text.trimmed());
    return number ? number->canonical() : QString();
}

bool looksNumeric(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral("^[+-]?[0-9.,]"));
    return pattern.match(text).hasMatch();
}

} // namespace

ParameterFormat::ParameterFormat(const ParameterDescription &parameter)
    : m_scaling(parameter.scaling)
    , m_plaintexts(parameter.plaintexts, m_scaling)
    , m_minimum(parameter.minimum)
    , m_maximum(parameter.maximum)
{
}

ParameterFormat ParameterFormat::rawFormat() const
{
    ParameterFormat format;
    format.m_minimum = m_minimum;
    format.m_maximum = m_maximum;
    format.m_raw = true;
    return format;
}

bool ParameterFormat::isHexadecimal() const
{
    return !m_raw && m_scaling.representation() == DisplayScaling::Representation::Hexadecimal;
}

QString ParameterFormat::text(qint32 raw, bool withUnit) const
{
    return m_raw ? number(raw, withUnit) : m_plaintexts.shown(raw, withUnit);
}

QString ParameterFormat::number(qint32 raw, bool withUnit) const
{
    return m_raw ? QString::number(raw) : m_scaling.format(raw, withUnit);
}

QString ParameterFormat::limitsProblem(qint32 raw) const
{
    if (isWithinLimits(raw))
        return {};
    return tr("%1 is outside the limits %2 .. %3")
        .arg(number(raw, true), number(m_minimum, false), number(m_maximum, true));
}

std::optional<qint32> ParameterFormat::parse(const QString &input, QString *error,
                                             Limits limits) const
{
    auto fail = [error](const QString &message) -> std::optional<qint32> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QString text = input.trimmed();
    if (text.isEmpty())
        return fail(tr("no value given"));

    std::optional<qint32> raw;
    QString plaintextError;
    if (!m_raw && !m_plaintexts.isEmpty())
        raw = m_plaintexts.value(text, &plaintextError);
    if (!raw) {
        QString numberError;
        raw = parseNumber(text, &numberError);
        if (!raw)
            return fail(plaintextError.isEmpty() || looksNumeric(text) ? numberError
                                                                       : plaintextError);
    }
    if (limits == Limits::Check && !isWithinLimits(*raw))
        return fail(limitsProblem(*raw));
    return raw;
}

std::optional<qint32> ParameterFormat::parseNumber(const QString &text, QString *error) const
{
    auto fail = [error](const QString &message) -> std::optional<qint32> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    if (m_raw) {
        // Decimal, or hexadecimal with 0x as the drive's hex parameters are usually written.
        const bool hex = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                         || text.startsWith(QLatin1String("-0x"), Qt::CaseInsensitive);
        bool ok = false;
        qint64 value = 0;
        if (hex) {
            const bool negative = text.startsWith(QLatin1Char('-'));
            value = text.mid(negative ? 3 : 2).toLongLong(&ok, 16);
            value = negative ? -value : value;
        } else {
            value = text.toLongLong(&ok);
        }
        if (!ok)
            return fail(tr("'%1' is not a whole number").arg(text));
        if (value < std::numeric_limits<qint32>::min()
            || value > std::numeric_limits<qint32>::max())
            return fail(tr("'%1' does not fit in 32 bits").arg(text));
        return qint32(value);
    }
    const std::optional<qint32> raw = m_scaling.parse(text, error);
    if (!raw || m_scaling.representation() == DisplayScaling::Representation::Hexadecimal)
        return raw; // hexadecimal is the raw value itself: always exact
    const QString shown = m_scaling.format(*raw, false);
    if (canonicalNumber(shown) != canonicalNumber(text)) {
        return fail(tr("%1 cannot be set exactly: the nearest value this parameter can hold "
                       "is %2")
                        .arg(text, m_scaling.format(*raw, true)));
    }
    return raw;
}

} // namespace DriveDesk
