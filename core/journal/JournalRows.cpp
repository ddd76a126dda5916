#include "JournalRows.h"

#include "journal/JournalFilter.h"

#include <QSqlQuery>
#include <QStringList>

namespace DriveDesk {

namespace {

enum Column {
    Id,
    Time,
    CompletedTime,
    User,
    Host,
    Program,
    JobId,
    JobDescription,
    Link,
    Protocol,
    Address,
    DriveKind,
    SoftwareVersion,
    SerialNumber,
    ParameterId,
    ParameterAddress,
    ParameterName,
    ParameterSet,
    Password,
    BeforeRaw,
    BeforeText,
    WrittenRaw,
    WrittenText,
    ReadBackRaw,
    ReadBackText,
    Outcome,
    Reason,
};

// In the order of Column.
const char kColumns[]
    = "e.id, e.time_utc_ms, e.completed_utc_ms, e.user, e.host, e.program, e.job_id, "
      "j.description, e.link, e.protocol, e.address, e.drive_kind, e.software_version, "
      "e.serial_number, e.parameter_id, e.parameter_address, e.parameter_name, e.parameter_set, "
      "e.password, e.before_raw, e.before_text, e.written_raw, e.written_text, e.read_back_raw, "
      "e.read_back_text, e.outcome, e.reason";

std::optional<int> optionalInt(const QVariant &value)
{
    if (value.isNull())
        return std::nullopt;
    return value.toInt();
}

JournalValue valueOf(const QSqlQuery &row, int raw, int text)
{
    JournalValue value;
    value.raw = optionalInt(row.value(raw));
    value.text = row.value(text).toString();
    return value;
}

QDateTime timeOf(const QVariant &msSinceEpoch)
{
    if (msSinceEpoch.isNull())
        return {};
    return QDateTime::fromMSecsSinceEpoch(msSinceEpoch.toLongLong(), Qt::UTC);
}

} // namespace

JournalSelect journalSelect(const JournalFilter &filter)
{
    QStringList conditions;
    JournalSelect select;
    if (!filter.serialNumber().isEmpty()) {
        conditions << QStringLiteral("e.serial_number = ?");
        select.values << filter.serialNumber();
    }
    if (!filter.link().isEmpty()) {
        conditions << QStringLiteral("e.link = ?");
        select.values << filter.link();
    }
    if (filter.driveAddress()) {
        conditions << QStringLiteral("e.address = ?");
        select.values << *filter.driveAddress();
    }
    if (filter.parameterAddress()) {
        conditions << QStringLiteral("e.parameter_address = ?");
        select.values << int(*filter.parameterAddress());
    } else if (!filter.parameterIds().isEmpty()) {
        // The column compares without case (JournalSchema): "OP.28" finds "op.28".
        QStringList marks;
        for (const QString &id : filter.parameterIds()) {
            marks << QStringLiteral("?");
            select.values << id;
        }
        conditions << QStringLiteral("e.parameter_id IN (%1)").arg(marks.join(QLatin1Char(',')));
    }
    if (filter.since().isValid()) {
        conditions << QStringLiteral("e.time_utc_ms >= ?");
        select.values << filter.since().toMSecsSinceEpoch();
    }
    if (filter.until().isValid()) {
        conditions << QStringLiteral("e.time_utc_ms < ?");
        select.values << filter.until().toMSecsSinceEpoch();
    }
    if (!filter.entries().isEmpty()) {
        QStringList marks;
        for (const qint64 id : filter.entries()) {
            marks << QStringLiteral("?");
            select.values << id;
        }
        conditions << QStringLiteral("e.id IN (%1)").arg(marks.join(QLatin1Char(',')));
    }
    if (filter.afterEntry() > 0) {
        conditions << QStringLiteral("e.id > ?");
        select.values << filter.afterEntry();
    }
    if (filter.beforeEntry() > 0) {
        conditions << QStringLiteral("e.id < ?");
        select.values << filter.beforeEntry();
    }
    if (!filter.user().isEmpty()) {
        conditions << QStringLiteral("e.user = ?");
        select.values << filter.user();
    }
    select.statement
        = QStringLiteral("SELECT %1 FROM entries e LEFT JOIN jobs j ON j.id = e.job_id")
              .arg(QLatin1String(kColumns));
    if (!conditions.isEmpty())
        select.statement += QStringLiteral(" WHERE ") + conditions.join(QStringLiteral(" AND "));
    // The newest page comes newest first; Journal::entries() turns it round.
    if (filter.newest() > 0)
        select.statement += QStringLiteral(" ORDER BY e.id DESC LIMIT %1").arg(filter.newest());
    else
        select.statement += QStringLiteral(" ORDER BY e.id");
    return select;
}

JournalEntry journalEntryOf(const QSqlQuery &row)
{
    JournalEntry entry;
    entry.id = row.value(Id).toLongLong();
    entry.time = timeOf(row.value(Time));
    entry.completedTime = timeOf(row.value(CompletedTime));
    entry.user = row.value(User).toString();
    entry.host = row.value(Host).toString();
    entry.program = row.value(Program).toString();
    entry.jobId = row.value(JobId).toLongLong();
    entry.jobDescription = row.value(JobDescription).toString();
    entry.drive.link = row.value(Link).toString();
    entry.drive.protocol = row.value(Protocol).toString();
    entry.drive.address = optionalInt(row.value(Address));
    entry.drive.kind = row.value(DriveKind).toString();
    entry.drive.softwareVersion = row.value(SoftwareVersion).toString();
    entry.drive.serialNumber = row.value(SerialNumber).toString();
    entry.parameterId = row.value(ParameterId).toString();
    entry.parameterAddress = quint16(row.value(ParameterAddress).toUInt());
    entry.parameterName = row.value(ParameterName).toString();
    entry.set = optionalInt(row.value(ParameterSet));
    entry.password = row.value(Password).toBool();
    entry.before = valueOf(row, BeforeRaw, BeforeText);
    entry.written = valueOf(row, WrittenRaw, WrittenText);
    entry.readBack = valueOf(row, ReadBackRaw, ReadBackText);
    entry.outcome
        = journalOutcomeFromName(row.value(Outcome).toString()).value_or(JournalOutcome::Unknown);
    entry.reason = row.value(Reason).toString();
    return entry;
}

} // namespace DriveDesk
