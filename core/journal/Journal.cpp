#include "Journal.h"

#include "journal/JournalCheckpointer.h"
#include "journal/JournalProblem.h"
#include "journal/JournalRows.h"
#include "journal/JournalSchema.h"

#include <QAtomicInt>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QSysInfo>
#include <QThread>
#include <QUrl>

#include <algorithm>

#ifdef Q_OS_UNIX
#include <pwd.h>
#include <unistd.h>
#endif

namespace DriveDesk {

namespace {

const char kInsertEntry[]
    = "INSERT INTO entries (time_utc_ms, user, host, program, job_id, link, protocol, address, "
      "drive_kind, software_version, serial_number, parameter_id, parameter_address, "
      "parameter_name, parameter_set, password, before_raw, before_text, written_raw, "
      "written_text, outcome) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, 'unknown')";
// A password's entry keeps no value, whatever it is completed with.
const char kCompleteEntry[]
    = "UPDATE entries SET completed_utc_ms = ?, "
      "read_back_raw = CASE password WHEN 0 THEN ? END, "
      "read_back_text = CASE password WHEN 0 THEN ? END, outcome = ?, reason = ? WHERE id = ?";
const char kInsertJob[] = "INSERT INTO jobs (description, time_utc_ms) VALUES (?, ?)";

// The user's login name, as the system knows it.
QString loginName()
{
#ifdef Q_OS_UNIX
    if (const passwd *user = ::getpwuid(::geteuid()); user && user->pw_name)
        return QString::fromLocal8Bit(user->pw_name);
#endif
    const QString name = qEnvironmentVariable("USER");
    return name.isEmpty() ? qEnvironmentVariable("USERNAME") : name;
}

// Text columns are NOT NULL: an empty text is stored as one, never as NULL.
QVariant text(const QString &value)
{
    return value.isNull() ? QStringLiteral("") : value;
}

QVariant number(const std::optional<int> &value)
{
    return value ? QVariant(*value) : QVariant(QMetaType::fromType<int>());
}

QVariant raw(const JournalValue &value, bool password)
{
    return password || !value.raw ? QVariant(QMetaType::fromType<int>()) : QVariant(*value.raw);
}

QVariant valueText(const JournalValue &value, bool password)
{
    return password || value.text.isNull() ? QVariant(QMetaType::fromType<QString>())
                                           : QVariant(value.text);
}

} // namespace

// The statements every entry takes, prepared once.
struct Journal::Statements
{
    explicit Statements(const QSqlDatabase &db)
        : insertEntry(db)
        , completeEntry(db)
        , insertJob(db)
        , beginTransaction(db)
        , commit(db)
    { }

    QSqlQuery insertEntry;
    QSqlQuery completeEntry;
    QSqlQuery insertJob;
    // Prepared once: a transaction's first telegram waits for them.
    QSqlQuery beginTransaction;
    QSqlQuery commit;
};

Journal::Journal(QString path)
    : m_path(path.isEmpty() ? defaultPath() : QDir::cleanPath(path))
{
    static QAtomicInt counter;
    m_connection = QStringLiteral("drivedesk-journal-%1").arg(counter.fetchAndAddRelaxed(1));
}

Journal::~Journal()
{
    close();
}

void Journal::close()
{
    m_checkpointer.reset(); // a checkpoint under way ends first
    if (isOpen() && m_access == Access::Write) {
        // What this program wrote, into the file, now that no entry waits.
        QSqlQuery(QSqlDatabase::database(m_connection, false))
            .exec(QStringLiteral("PRAGMA wal_checkpoint(PASSIVE)"));
    }
    m_statements.reset(); // the queries go before their connection
    if (QSqlDatabase::contains(m_connection)) {
        QSqlDatabase::database(m_connection, false).close();
        QSqlDatabase::removeDatabase(m_connection);
    }
}

bool Journal::fail(const QString &message)
{
    m_error = message;
    return false;
}

bool Journal::open(Access access)
{
    close();
    m_error.clear();
    m_access = access;
    const QString problem = access == Access::Write ? JournalProblem::beforeWriting(m_path)
                                                    : JournalProblem::beforeReading(m_path);
    if (!problem.isEmpty())
        return fail(problem);
    if (!prepare(access)) {
        close();
        return false;
    }
    return true;
}

bool Journal::switchToLog(QSqlQuery &query) const
{
    // A new file's switch needs it to itself for a moment, and SQLite does not wait for that
    // (no busy handler): another program starting on the same new file is waited for here, as
    // long as the busy timeout. A file in the log's mode already switches at once.
    QElapsedTimer waited;
    waited.start();
    for (;;) {
        if (query.exec(QStringLiteral("PRAGMA journal_mode = WAL")) && query.next())
            return true;
        if (!JournalProblem::isBusy(query.lastError()) || waited.elapsed() >= m_busyTimeoutMs)
            return false;
        QThread::msleep(2);
    }
}

bool Journal::prepare(Access access)
{
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_connection);
    if (!db.isValid())
        return fail(
            tr("cannot open the journal %1: Qt's SQLite driver (QSQLITE) is missing").arg(m_path));
    db.setDatabaseName(m_path);
    QString options = QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(m_busyTimeoutMs);
    if (access == Access::Read) {
        options += QStringLiteral(";QSQLITE_OPEN_READONLY");
        // In a folder no one may write (a backup medium, a read-only share) SQLite cannot make
        // the log's index beside the file; nothing can write the journal there either, so it
        // is read as it lies (a log left there by a crash is not read).
        if (!JournalProblem::isWritable(QFileInfo(m_path).absolutePath())) {
            db.setDatabaseName(QUrl::fromLocalFile(m_path).toString(QUrl::FullyEncoded)
                               + QStringLiteral("?immutable=1"));
            options += QStringLiteral(";QSQLITE_OPEN_URI");
        }
    }
    db.setConnectOptions(options);
    if (!db.open())
        return fail(JournalProblem::of(m_path, db.lastError(), m_busyTimeoutMs));

    QSqlQuery query(db);
    const auto failed = [this](const QSqlError &error) {
        return fail(JournalProblem::of(m_path, error, m_busyTimeoutMs));
    };
    int version = 0;
    QSqlError error;
    JournalSchema::State state = JournalSchema::inspect(db, &version, &error);
    if (state == JournalSchema::State::Failed)
        return failed(error);
    if (state == JournalSchema::State::NotJournal)
        return fail(JournalProblem::notJournal(m_path));
    if (access == Access::Write) {
        if (state == JournalSchema::State::Newer)
            return fail(JournalProblem::newer(m_path, version));
        // The log lets readers read while a writer writes; NORMAL syncs at checkpoints only: an
        // entry committed survives the program's end however it ends (docs/journal.md).
        if (!switchToLog(query))
            return failed(query.lastError());
        if (query.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) != 0)
            return fail(tr("cannot write the journal %1: SQLite cannot keep a write-ahead log "
                           "there (journal mode %2)")
                            .arg(m_path, query.value(0).toString()));
        // Checkpoints sync the disk (milliseconds): never in the middle of an entry, but beside
        // it (JournalCheckpointer) and at close() (docs/journal.md, "Nothing is lost").
        if (!query.exec(QStringLiteral("PRAGMA synchronous = NORMAL"))
            || !query.exec(QStringLiteral("PRAGMA wal_autocheckpoint = 0")))
            return failed(query.lastError());
        if (state == JournalSchema::State::Empty)
            state = JournalSchema::create(db, &error);
        if (state == JournalSchema::State::Failed)
            return failed(error);
        if (state != JournalSchema::State::Ready)
            return fail(state == JournalSchema::State::Newer
                            ? JournalProblem::newer(m_path, version)
                            : JournalProblem::notJournal(m_path));
        // Whether an entry could be written now: the write lock taken and a write begun (SQLite
        // opens a read-only file for reading without a word), then given back.
        if (!query.exec(QStringLiteral("BEGIN IMMEDIATE")))
            return failed(query.lastError());
        const bool writes = query.exec(QStringLiteral("DELETE FROM jobs WHERE 0"));
        const QSqlError writeError = query.lastError();
        query.exec(QStringLiteral("ROLLBACK"));
        if (!writes)
            return failed(writeError);
    }
    query.finish();

    auto statements = std::make_unique<Statements>(db);
    if (access == Access::Write) {
        const std::pair<QSqlQuery *, QString> prepared[] = {
            { &statements->insertEntry, QString::fromLatin1(kInsertEntry) },
            { &statements->completeEntry, QString::fromLatin1(kCompleteEntry) },
            { &statements->insertJob, QString::fromLatin1(kInsertJob) },
            { &statements->beginTransaction, QStringLiteral("BEGIN IMMEDIATE") },
            { &statements->commit, QStringLiteral("COMMIT") },
        };
        for (const auto &[statement, text] : prepared) {
            if (!statement->prepare(text))
                return failed(statement->lastError());
        }
    }
    m_statements = std::move(statements);
    m_entriesSinceCheckpoint = 0;
    return true;
}

std::optional<qint64> Journal::beginJob(const QString &description)
{
    if (!isOpen() || m_access != Access::Write) {
        fail(tr("the journal %1 is not open for writing").arg(m_path));
        return std::nullopt;
    }
    QSqlQuery &query = m_statements->insertJob;
    query.bindValue(0, text(description));
    query.bindValue(1, QDateTime::currentMSecsSinceEpoch());
    if (!query.exec()) {
        fail(JournalProblem::of(m_path, query.lastError(), m_busyTimeoutMs));
        return std::nullopt;
    }
    return query.lastInsertId().toLongLong();
}

std::optional<qint64> Journal::begin(const JournalEntry &entry)
{
    if (!isOpen() || m_access != Access::Write) {
        fail(tr("the journal %1 is not open for writing").arg(m_path));
        return std::nullopt;
    }
    static const QString login = loginName();
    static const QString host = QSysInfo::machineHostName();
    const QString program = QStringLiteral("%1 %2").arg(QCoreApplication::applicationName(),
                                                        QCoreApplication::applicationVersion());
    QSqlQuery &query = m_statements->insertEntry;
    int i = 0;
    query.bindValue(i++,
                    entry.time.isValid() ? entry.time.toMSecsSinceEpoch()
                                         : QDateTime::currentMSecsSinceEpoch());
    query.bindValue(i++, text(entry.user.isEmpty() ? login : entry.user));
    query.bindValue(i++, text(entry.host.isEmpty() ? host : entry.host));
    query.bindValue(i++, text(entry.program.isEmpty() ? program.trimmed() : entry.program));
    query.bindValue(
        i++, entry.jobId > 0 ? QVariant(entry.jobId) : QVariant(QMetaType::fromType<qint64>()));
    query.bindValue(i++, text(entry.drive.link));
    query.bindValue(i++, text(entry.drive.protocol));
    query.bindValue(i++, number(entry.drive.address));
    query.bindValue(i++, text(entry.drive.kind));
    query.bindValue(i++, text(entry.drive.softwareVersion));
    query.bindValue(i++, text(entry.drive.serialNumber));
    query.bindValue(i++, text(entry.parameterId));
    query.bindValue(i++, int(entry.parameterAddress));
    query.bindValue(i++, text(entry.parameterName));
    query.bindValue(i++, number(entry.set));
    query.bindValue(i++, entry.password ? 1 : 0);
    query.bindValue(i++, raw(entry.before, entry.password));
    query.bindValue(i++, valueText(entry.before, entry.password));
    query.bindValue(i++, raw(entry.written, entry.password));
    query.bindValue(i++, valueText(entry.written, entry.password));
    if (!query.exec()) {
        fail(JournalProblem::of(m_path, query.lastError(), m_busyTimeoutMs));
        return std::nullopt;
    }
    return query.lastInsertId().toLongLong();
}

bool Journal::complete(qint64 id, const JournalValue &readBack, JournalOutcome outcome,
                       const QString &reason)
{
    if (!isOpen() || m_access != Access::Write)
        return fail(tr("the journal %1 is not open for writing").arg(m_path));
    QSqlQuery &query = m_statements->completeEntry;
    query.bindValue(0, QDateTime::currentMSecsSinceEpoch());
    query.bindValue(1, raw(readBack, false));
    query.bindValue(2, valueText(readBack, false));
    query.bindValue(3, journalOutcomeName(outcome));
    query.bindValue(4, text(reason));
    query.bindValue(5, id);
    if (!query.exec())
        return fail(JournalProblem::of(m_path, query.lastError(), m_busyTimeoutMs));
    if (query.numRowsAffected() != 1)
        return fail(tr("the journal %1 has no entry %2").arg(m_path).arg(id));
    // The log into the file now and then, beside this thread (JournalCheckpointer).
    if (++m_entriesSinceCheckpoint >= kCheckpointEntries) {
        m_entriesSinceCheckpoint = 0;
        if (!m_checkpointer)
            m_checkpointer = std::make_unique<JournalCheckpointer>(m_path, m_busyTimeoutMs);
        m_checkpointer->request();
    }
    return true;
}

bool Journal::transaction(const std::function<bool()> &work)
{
    if (m_inTransaction)
        return work();
    if (!isOpen() || m_access != Access::Write)
        return fail(tr("the journal %1 is not open for writing").arg(m_path));
    QSqlQuery &begin = m_statements->beginTransaction;
    if (!begin.exec())
        return fail(JournalProblem::of(m_path, begin.lastError(), m_busyTimeoutMs));
    begin.finish();
    m_inTransaction = true;
    const bool done = work();
    m_inTransaction = false;
    QSqlQuery &commit = m_statements->commit;
    const bool committed = done && commit.exec();
    const QString error = committed ? QString()
        : done ? JournalProblem::of(m_path, commit.lastError(), m_busyTimeoutMs)
               : m_error;
    commit.finish();
    if (committed)
        return true;
    QSqlQuery(QSqlDatabase::database(m_connection, false)).exec(QStringLiteral("ROLLBACK"));
    return fail(error);
}

std::optional<QList<JournalEntry>> Journal::entries(const JournalFilter &filter)
{
    if (!isOpen()) {
        fail(tr("the journal %1 is not open").arg(m_path));
        return std::nullopt;
    }
    QSqlDatabase db = QSqlDatabase::database(m_connection, false);
    int version = 0;
    QSqlError error;
    if (JournalSchema::inspect(db, &version, &error) == JournalSchema::State::Empty)
        return QList<JournalEntry>(); // a new file nothing was written to yet
    const JournalSelect select = journalSelect(filter);
    QSqlQuery query(db);
    query.setForwardOnly(true);
    if (!query.prepare(select.statement)) {
        fail(JournalProblem::of(m_path, query.lastError(), m_busyTimeoutMs));
        return std::nullopt;
    }
    for (qsizetype i = 0; i < select.values.size(); ++i)
        query.bindValue(int(i), select.values.at(i));
    if (!query.exec()) {
        fail(JournalProblem::of(m_path, query.lastError(), m_busyTimeoutMs));
        return std::nullopt;
    }
    QList<JournalEntry> entries;
    while (query.next())
        entries << journalEntryOf(query);
    if (query.lastError().isValid()) {
        fail(JournalProblem::of(m_path, query.lastError(), m_busyTimeoutMs));
        return std::nullopt;
    }
    if (filter.newest() > 0)
        std::reverse(entries.begin(), entries.end());
    return entries;
}

} // namespace DriveDesk
