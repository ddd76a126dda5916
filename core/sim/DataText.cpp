#include "DataText.h"

#include <cmath>
#include <limits>

namespace DriveDesk::Sim {

std::optional<qint32> parseNumber(const QString &text, int decimals, bool hex)
{
    QString t = text.trimmed();
    if (t.endsWith(QLatin1Char('h')) || t.endsWith(QLatin1Char('H'))) {
        t.chop(1);
        hex = true;
    }
    if (t.isEmpty())
        return std::nullopt;
    bool ok = false;
    qint64 value = 0;
    if (hex) {
        value = t.toLongLong(&ok, 16);
    } else {
        const double number = t.toDouble(&ok);
        if (ok)
            value = std::llround(number * std::pow(10.0, decimals));
    }
    if (!ok || value < std::numeric_limits<qint32>::min()
        || value > std::numeric_limits<qint32>::max())
        return std::nullopt;
    return qint32(value);
}

bool isDecimalNumber(const QString &text)
{
    bool ok = false;
    text.trimmed().toDouble(&ok);
    return ok;
}

QByteArray lineText(const QString &text, const QString &what, QStringList &problems)
{
    for (const QChar c : text) {
        if (c.unicode() < 0x20 || c.unicode() > 0x7E) {
            problems << QStringLiteral("%1 \"%2\" is not 7-bit ASCII").arg(what, text);
            break;
        }
    }
    QByteArray bytes = text.toLatin1();
    if (bytes.size() > 24) {
        problems << QStringLiteral("%1 \"%2\" is longer than 24 characters").arg(what, text);
        bytes.truncate(24);
    }
    return bytes;
}

} // namespace DriveDesk::Sim
