#include "DecimalText.h"

#include <QRegularExpression>

namespace DriveDesk {

std::optional<DecimalText> DecimalText::read(const QString &text)
{
    static const QRegularExpression pattern(
        QStringLiteral("^([+-]?)(?:([0-9]+)(?:[.,]([0-9]*))?|[.,]([0-9]+))"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch())
        return std::nullopt;
    DecimalText number;
    number.negative = match.captured(1) == QLatin1String("-");
    number.integral = match.captured(2);
    number.fraction = match.captured(2).isNull() ? match.captured(4) : match.captured(3);
    while (number.integral.startsWith(QLatin1Char('0')))
        number.integral.remove(0, 1);
    while (number.fraction.endsWith(QLatin1Char('0')))
        number.fraction.chop(1);
    number.length = match.capturedLength();
    return number;
}

QString DecimalText::canonical() const
{
    const QString whole = integral.isEmpty() ? QStringLiteral("0") : integral;
    const QString number = fraction.isEmpty() ? whole : whole + QLatin1Char('.') + fraction;
    return negative && number != QLatin1String("0") ? QLatin1Char('-') + number : number;
}

} // namespace DriveDesk
