#include "JournalFormat.h"

#include "parameters/ParameterCsv.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

#include <algorithm>

namespace DriveDesk {

namespace {

QString setText(const JournalEntry &entry)
{
    return entry.set ? QString::number(*entry.set) : JournalFormat::tr("active");
}

QJsonValue jsonValue(const JournalValue &value, bool password)
{
    if (password || value.isEmpty())
        return QJsonValue::Null;
    QJsonObject object;
    object[QStringLiteral("raw")] = value.raw ? QJsonValue(*value.raw) : QJsonValue::Null;
    object[QStringLiteral("text")] = value.text;
    return object;
}

QJsonValue jsonTime(const QDateTime &time)
{
    return time.isValid() ? QJsonValue(time.toUTC().toString(Qt::ISODateWithMs)) : QJsonValue::Null;
}

// Local times of UTC times, the zone's offset looked up once per quarter of an hour (every
// zone changes its offset on a quarter hour): each lookup reads the system's zone from the disk.
class LocalTimes
{
public:
    QDateTime of(const QDateTime &time)
    {
        if (!time.isValid())
            return {};
        constexpr qint64 kQuarterMs = 15 * 60 * 1000;
        const qint64 ms = time.toMSecsSinceEpoch();
        const qint64 quarter = ms >= 0 ? ms / kQuarterMs : (ms - kQuarterMs + 1) / kQuarterMs;
        auto offset = m_offsets.constFind(quarter);
        if (offset == m_offsets.constEnd()) {
            const QDateTime start = QDateTime::fromMSecsSinceEpoch(quarter * kQuarterMs, Qt::UTC);
            offset = m_offsets.insert(quarter, start.toLocalTime().offsetFromUtc());
        }
        return QDateTime::fromMSecsSinceEpoch(ms, Qt::OffsetFromUTC, *offset);
    }

    // "2026-11-24T10:42:05.123+01:00", empty for no time.
    QString iso(const QDateTime &time)
    {
        return time.isValid() ? of(time).toString(Qt::ISODateWithMs) : QString();
    }

private:
    QHash<qint64, int> m_offsets;
};

QString csvRaw(const JournalValue &value)
{
    return value.raw ? QString::number(*value.raw) : QString();
}

} // namespace

QString JournalFormat::valueText(const JournalValue &value, bool password)
{
    if (password)
        return tr("(password)");
    if (!value.text.isEmpty())
        return value.text;
    return value.raw ? QString::number(*value.raw) : QStringLiteral("-");
}

QString JournalFormat::table(const QList<JournalEntry> &entries)
{
    if (entries.isEmpty())
        return tr("no entries") + QLatin1Char('\n');
    LocalTimes localTimes;
    QList<QStringList> rows;
    rows.reserve(entries.size() + 1);
    rows << QStringList { tr("#"),         tr("Time"),    tr("User"),   tr("Drive"),
                          tr("Parameter"), tr("Set"),     tr("Before"), tr("Written"),
                          tr("Read back"), tr("Outcome"), tr("Job") };
    for (const JournalEntry &entry : entries) {
        rows << QStringList {
            QString::number(entry.id),
            localTimes.of(entry.time).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
            QStringLiteral("%1@%2").arg(entry.user, entry.host),
            entry.drive.name(),
            entry.parameterId,
            setText(entry),
            valueText(entry.before, entry.password),
            valueText(entry.written, entry.password),
            valueText(entry.readBack, entry.password),
            entry.outcomeText(),
            entry.jobDescription
        };
    }
    QList<qsizetype> widths(rows.first().size(), 0);
    for (const QStringList &row : std::as_const(rows)) {
        for (qsizetype column = 0; column < row.size(); ++column)
            widths[column] = std::max(widths[column], row[column].size());
    }
    QString text;
    for (const QStringList &row : std::as_const(rows)) {
        QString line;
        for (qsizetype column = 0; column < row.size(); ++column) {
            // The id is a number: right-aligned; the last column is not padded.
            const QString &cell = row[column];
            line += column == 0            ? cell.rightJustified(widths[column])
                : column + 1 == row.size() ? cell
                                           : cell.leftJustified(widths[column]);
            if (column + 1 < row.size())
                line += QStringLiteral("  ");
        }
        while (line.endsWith(QLatin1Char(' ')))
            line.chop(1);
        text += line + QLatin1Char('\n');
    }
    return text;
}

QByteArray JournalFormat::json(const QList<JournalEntry> &entries)
{
    QJsonArray array;
    for (const JournalEntry &entry : entries) {
        QJsonObject drive;
        drive[QStringLiteral("link")] = entry.drive.link;
        drive[QStringLiteral("protocol")] = entry.drive.protocol;
        drive[QStringLiteral("address")]
            = entry.drive.address ? QJsonValue(*entry.drive.address) : QJsonValue::Null;
        drive[QStringLiteral("kind")] = entry.drive.kind;
        drive[QStringLiteral("softwareVersion")] = entry.drive.softwareVersion;
        drive[QStringLiteral("serialNumber")] = entry.drive.serialNumber;
        QJsonObject parameter;
        parameter[QStringLiteral("id")] = entry.parameterId;
        parameter[QStringLiteral("address")] = int(entry.parameterAddress);
        parameter[QStringLiteral("name")] = entry.parameterName;
        QJsonObject job;
        job[QStringLiteral("id")] = entry.jobId > 0 ? QJsonValue(entry.jobId) : QJsonValue::Null;
        job[QStringLiteral("description")] = entry.jobDescription;

        QJsonObject object;
        object[QStringLiteral("id")] = entry.id;
        object[QStringLiteral("time")] = jsonTime(entry.time);
        object[QStringLiteral("completed")] = jsonTime(entry.completedTime);
        object[QStringLiteral("user")] = entry.user;
        object[QStringLiteral("host")] = entry.host;
        object[QStringLiteral("program")] = entry.program;
        object[QStringLiteral("job")] = job;
        object[QStringLiteral("drive")] = drive;
        object[QStringLiteral("parameter")] = parameter;
        object[QStringLiteral("set")] = entry.set ? QJsonValue(*entry.set) : QJsonValue::Null;
        object[QStringLiteral("password")] = entry.password;
        object[QStringLiteral("before")] = jsonValue(entry.before, entry.password);
        object[QStringLiteral("written")] = jsonValue(entry.written, entry.password);
        object[QStringLiteral("readBack")] = jsonValue(entry.readBack, entry.password);
        object[QStringLiteral("outcome")] = journalOutcomeName(entry.outcome);
        object[QStringLiteral("reason")] = entry.reason;
        array.append(object);
    }
    return QJsonDocument(array).toJson(QJsonDocument::Indented);
}

QByteArray JournalFormat::csv(const QList<JournalEntry> &entries)
{
    const auto line = [](const QStringList &fields) { return csvRecord(fields).toUtf8() + "\r\n"; };
    LocalTimes localTimes;
    QByteArray text = line({ QStringLiteral("id"),
                             QStringLiteral("time"),
                             QStringLiteral("completed"),
                             QStringLiteral("user"),
                             QStringLiteral("host"),
                             QStringLiteral("program"),
                             QStringLiteral("job id"),
                             QStringLiteral("job"),
                             QStringLiteral("link"),
                             QStringLiteral("protocol"),
                             QStringLiteral("address"),
                             QStringLiteral("kind"),
                             QStringLiteral("software version"),
                             QStringLiteral("serial number"),
                             QStringLiteral("parameter"),
                             QStringLiteral("parameter address"),
                             QStringLiteral("parameter name"),
                             QStringLiteral("set"),
                             QStringLiteral("password"),
                             QStringLiteral("before raw"),
                             QStringLiteral("before"),
                             QStringLiteral("written raw"),
                             QStringLiteral("written"),
                             QStringLiteral("read back raw"),
                             QStringLiteral("read back"),
                             QStringLiteral("outcome"),
                             QStringLiteral("reason") });
    for (const JournalEntry &entry : entries) {
        text += line({ QString::number(entry.id),
                       localTimes.iso(entry.time),
                       localTimes.iso(entry.completedTime),
                       entry.user,
                       entry.host,
                       entry.program,
                       entry.jobId > 0 ? QString::number(entry.jobId) : QString(),
                       entry.jobDescription,
                       entry.drive.link,
                       entry.drive.protocol,
                       entry.drive.address ? QString::number(*entry.drive.address) : QString(),
                       entry.drive.kind,
                       entry.drive.softwareVersion,
                       entry.drive.serialNumber,
                       entry.parameterId,
                       QStringLiteral("0x%1").arg(entry.parameterAddress, 4, 16, QLatin1Char('0')),
                       entry.parameterName,
                       entry.set ? QString::number(*entry.set) : QString(),
                       entry.password ? QStringLiteral("yes") : QStringLiteral("no"),
                       csvRaw(entry.before),
                       entry.before.text,
                       csvRaw(entry.written),
                       entry.written.text,
                       csvRaw(entry.readBack),
                       entry.readBack.text,
                       journalOutcomeName(entry.outcome),
                       entry.reason });
    }
    return text;
}

} // namespace DriveDesk
