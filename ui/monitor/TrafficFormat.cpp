#include "TrafficFormat.h"

#include "parameters/TelegramText.h"

#include <QDateTime>

#include <array>

namespace DriveDesk {

namespace {

// The ASCII names of the control characters 00h..1Fh (DIN66019 uses STX, ETX, EOT, ENQ, ACK
// and NAK; the others only appear on a noisy line).
constexpr std::array<const char *, 32> kControlNames = {
    "NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS",  "HT",  "LF",
    "VT",  "FF",  "CR",  "SO",  "SI",  "DLE", "DC1", "DC2", "DC3", "DC4", "NAK",
    "SYN", "ETB", "CAN", "EM",  "SUB", "ESC", "FS",  "GS",  "RS",  "US",
};

QString flattened(QString text)
{
    text.replace(QLatin1Char('\t'), QLatin1Char(' '));
    text.replace(QLatin1Char('\r'), QLatin1Char(' '));
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    return text;
}

} // namespace

QString TrafficFormat::fieldName(Field field)
{
    switch (field) {
    case Time:
        return tr("Time");
    case Direction:
        return tr("Direction");
    case Bytes:
        return tr("Bytes");
    case Characters:
        return tr("Characters");
    case Meaning:
        return tr("Meaning");
    case FieldCount:
        break;
    }
    return {};
}

QString TrafficFormat::time(qint64 msecsSinceEpoch, Clock clock)
{
    const QDateTime when = QDateTime::fromMSecsSinceEpoch(msecsSinceEpoch);
    return when.toString(clock == Clock::TimeOfDay ? QStringLiteral("hh:mm:ss.zzz")
                                                   : QStringLiteral("yyyy-MM-dd hh:mm:ss.zzz"));
}

QString TrafficFormat::direction(TrafficRecord::Kind kind)
{
    switch (kind) {
    case TrafficRecord::Kind::Sent:
        return tr("→ drive");
    case TrafficRecord::Kind::Received:
        return tr("← drive");
    case TrafficRecord::Kind::Error:
        return tr("error");
    }
    return {};
}

QString TrafficFormat::hex(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

bool TrafficFormat::isAscii(Protocol protocol)
{
    return protocol == Protocol::Din66019II || protocol == Protocol::Din66019;
}

QString TrafficFormat::characters(const TrafficEntry &entry)
{
    if (!isAscii(entry.protocol))
        return {};
    QString text;
    text.reserve(entry.record.bytes.size() + 16);
    for (const char c : entry.record.bytes) {
        const auto byte = quint8(c);
        if (byte < kControlNames.size())
            text += QLatin1Char('<') + QLatin1String(kControlNames[byte]) + QLatin1Char('>');
        else if (byte == 0x7F)
            text += QStringLiteral("<DEL>");
        else if (byte > 0x7F)
            text += QStringLiteral("<%1h>").arg(QString::number(byte, 16).toUpper());
        else
            text += QLatin1Char(c);
    }
    return text;
}

QString TrafficFormat::meaning(const TrafficEntry &entry, const DriveDescription *drive)
{
    const TrafficRecord &record = entry.record;
    const Telegram *request = record.request ? &*record.request : nullptr;
    if (record.telegram) {
        const Telegram &telegram = *record.telegram;
        const QString text = TelegramText::describe(telegram, drive, request);
        // A request that arrives is the drive's own (HSP5 multi-master).
        if (record.kind == TrafficRecord::Kind::Received && !telegram.isResponse())
            return tr("inverter request: %1").arg(text);
        return text;
    }
    if (request) {
        return tr("%1: %2").arg(record.meaning, TelegramText::describe(*request, drive));
    }
    return record.meaning;
}

QStringList TrafficFormat::fields(const TrafficEntry &entry, Clock clock)
{
    QStringList result;
    result.reserve(FieldCount);
    result << time(entry.record.msecsSinceEpoch, clock) << direction(entry.record.kind)
           << hex(entry.record.bytes) << characters(entry)
           << flattened(entry.described ? entry.meaning : meaning(entry, entry.drive.get()));
    return result;
}

QString TrafficFormat::tabSeparated(const QStringList &fields)
{
    QStringList cleaned;
    cleaned.reserve(fields.size());
    for (const QString &field : fields)
        cleaned << flattened(field);
    return cleaned.join(QLatin1Char('\t'));
}

} // namespace DriveDesk
