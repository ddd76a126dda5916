#include "JournalFilter.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QTimeZone>

namespace DriveDesk {

namespace {

// The texts' context, as lupdate finds it.
class JournalFilterText
{
    Q_DECLARE_TR_FUNCTIONS(JournalFilterText)
};

} // namespace

bool JournalFilter::setDrive(const QString &text, QString *error)
{
    const QString drive = text.trimmed();
    // The last '@' followed by a number: a tcp: link holds ':' but never '@'.
    static const QRegularExpression withAddress(QStringLiteral("^(.+)@([0-9]+)$"));
    const QRegularExpressionMatch match = withAddress.match(drive);
    if (drive.isEmpty() || drive.endsWith(QLatin1Char('@'))
        || (match.hasMatch() && match.captured(2).toInt() > 255)) {
        *error = JournalFilterText::tr("'%1' names no drive: give its serial number, its link "
                                       "(serial:/dev/ttyUSB0) or LINK@ADDRESS "
                                       "(serial:/dev/ttyUSB0@3)")
                     .arg(text);
        return false;
    }
    m_serialNumber.clear();
    m_link.clear();
    m_address.reset();
    if (match.hasMatch()) {
        m_link = match.captured(1);
        m_address = match.captured(2).toInt();
    } else if (drive == QLatin1String("sim") || drive.contains(QLatin1Char(':'))) {
        m_link = drive;
    } else {
        m_serialNumber = drive;
    }
    return true;
}

bool JournalFilter::setParameter(const QString &text, QString *error)
{
    static const QRegularExpression hex(QStringLiteral("^(?:0x([0-9a-f]{1,4})|([0-9a-f]{1,4})h)$"),
                                        QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression id(QStringLiteral("^([A-Za-z]{1,3})\\.?([0-9]{1,3})$"));
    const QString parameter = text.trimmed();
    m_parameterAddress.reset();
    m_parameterIds.clear();
    if (const QRegularExpressionMatch match = hex.match(parameter); match.hasMatch()) {
        const QString digits = match.captured(1).isEmpty() ? match.captured(2) : match.captured(1);
        m_parameterAddress = quint16(digits.toUInt(nullptr, 16));
        return true;
    }
    const QRegularExpressionMatch match = id.match(parameter);
    const int number = match.captured(2).toInt();
    if (!match.hasMatch() || number > 255) {
        *error = JournalFilterText::tr("'%1' is no parameter: give its id like op.28 or its "
                                       "address like 0x0A1C")
                     .arg(text);
        return false;
    }
    // The forms a parameter's id is written in: "op.3", "op.03", "op.003".
    const QString group = match.captured(1);
    for (int width = 1; width <= 3; ++width) {
        const QString form
            = QStringLiteral("%1.%2").arg(group).arg(number, width, 10, QLatin1Char('0'));
        if (!m_parameterIds.contains(form))
            m_parameterIds << form;
    }
    return true;
}

bool JournalFilter::setSince(const QString &text, QString *error)
{
    const std::optional<QDateTime> time = parseTime(text, false, error);
    if (time)
        m_since = *time;
    return time.has_value();
}

bool JournalFilter::setUntil(const QString &text, QString *error)
{
    const std::optional<QDateTime> time = parseTime(text, true, error);
    if (time)
        m_until = *time;
    return time.has_value();
}

std::optional<QDateTime> JournalFilter::parseTime(const QString &text, bool end, QString *error)
{
    static const QRegularExpression pattern(QStringLiteral(
        "^([0-9]{4})-([0-9]{2})-([0-9]{2})"
        "(?:[T ]([0-9]{2}):([0-9]{2})(?::([0-9]{2}))?(Z|[+-][0-9]{2}:?[0-9]{2})?)?$"));
    const QRegularExpressionMatch match = pattern.match(text.trimmed());
    const QDate date = match.hasMatch()
        ? QDate(match.captured(1).toInt(), match.captured(2).toInt(), match.captured(3).toInt())
        : QDate();
    const bool hasTime = !match.captured(4).isEmpty();
    const bool hasSeconds = !match.captured(6).isEmpty();
    const QTime time = hasTime
        ? QTime(match.captured(4).toInt(), match.captured(5).toInt(), match.captured(6).toInt())
        : QTime(0, 0);
    if (!date.isValid() || !time.isValid()) {
        *error = JournalFilterText::tr("'%1' is no time: use a date like 2026-11-24 or a date "
                                       "and time like 2026-11-24T10:42 (local time)")
                     .arg(text);
        return std::nullopt;
    }
    QDateTime moment;
    const QString zone = match.captured(7);
    if (zone.isEmpty()) {
        moment = QDateTime(date, time, Qt::LocalTime);
    } else if (zone == QLatin1String("Z")) {
        moment = QDateTime(date, time, Qt::UTC);
    } else {
        QString digits = zone.mid(1);
        digits.remove(QLatin1Char(':'));
        const int seconds = (digits.left(2).toInt() * 60 + digits.mid(2).toInt()) * 60;
        moment = QDateTime(date, time,
                           QTimeZone(zone.startsWith(QLatin1Char('-')) ? -seconds : seconds));
    }
    if (end) {
        // The moment after the span the text names (a date alone is local: a day of 23 or 25
        // hours where the clocks change).
        moment = hasTime ? moment.addSecs(hasSeconds ? 1 : 60)
                         : QDateTime(date.addDays(1), QTime(0, 0), Qt::LocalTime);
    }
    return moment.toUTC();
}

} // namespace DriveDesk
