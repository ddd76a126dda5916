// The journal's storage: an entry begun and completed reads back with every field, one begun
// and never completed reads unknown, a password's values are never stored, and the filters
// find what they name, newest last.
#include "JournalTestSupport.h"

#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::JournalTest;

class tst_Journal : public QObject
{
    Q_OBJECT

private:
    QString journalPath() const { return m_dir.filePath(QStringLiteral("journal.sqlite")); }

    // All entries of the journal at journalPath(), read by a journal of its own.
    QList<JournalEntry> readAll(const JournalFilter &filter = {})
    {
        Journal reader(journalPath());
        if (!reader.open(Journal::Access::Read))
            qWarning("%s", qPrintable(reader.errorString()));
        return reader.entries(filter).value_or(QList<JournalEntry>());
    }

    QList<qint64> ids(const JournalFilter &filter)
    {
        QList<qint64> found;
        for (const JournalEntry &entry : readAll(filter))
            found << entry.id;
        return found;
    }

    QTemporaryDir m_dir;

private slots:
    void init()
    {
        QFile::remove(journalPath());
        QFile::remove(journalPath() + QStringLiteral("-wal"));
        QFile::remove(journalPath() + QStringLiteral("-shm"));
    }

    void everyFieldReadsBack()
    {
        Journal journal(journalPath());
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        QVERIFY(QFileInfo::exists(journalPath()));
        const std::optional<qint64> job = journal.beginJob(QStringLiteral("download of f5.json"));
        QVERIFY2(job, qPrintable(journal.errorString()));
        JournalEntry entry = fullEntry();
        entry.jobId = *job;
        const std::optional<qint64> id = journal.begin(entry);
        QVERIFY2(id, qPrintable(journal.errorString()));
        const QDateTime beforeCompletion = QDateTime::currentDateTimeUtc().addMSecs(-1);
        QVERIFY2(journal.complete(*id, { qint32(750), QStringLiteral("7.50 s") },
                                  JournalOutcome::Written),
                 qPrintable(journal.errorString()));

        const QList<JournalEntry> entries = readAll();
        QCOMPARE(entries.size(), 1);
        const JournalEntry &read = entries.first();
        QCOMPARE(read.id, *id);
        QCOMPARE(read.time, entry.time);
        QCOMPARE(read.time.timeSpec(), Qt::UTC);
        QVERIFY(read.completedTime >= beforeCompletion);
        QCOMPARE(read.user, entry.user);
        QCOMPARE(read.host, entry.host);
        QCOMPARE(read.program, entry.program);
        QCOMPARE(read.jobId, *job);
        QCOMPARE(read.jobDescription, QStringLiteral("download of f5.json"));
        QCOMPARE(read.drive, entry.drive);
        QCOMPARE(read.parameterId, entry.parameterId);
        QCOMPARE(read.parameterAddress, entry.parameterAddress);
        QCOMPARE(read.parameterName, entry.parameterName);
        QCOMPARE(read.set, std::optional<int>(2));
        QCOMPARE(read.password, false);
        QCOMPARE(read.before, entry.before);
        QCOMPARE(read.written, entry.written);
        QCOMPARE(read.readBack, (JournalValue { qint32(750), QStringLiteral("7.50 s") }));
        QCOMPARE(read.outcome, JournalOutcome::Written);
        QCOMPARE(read.outcomeText(), QStringLiteral("written"));
    }

    void aRefusalKeepsTheDrivesReason()
    {
        Journal journal(journalPath());
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        JournalEntry entry = fullEntry();
        entry.set.reset(); // the active set
        entry.drive.address.reset(); // HSP5
        entry.drive.serialNumber.clear();
        const std::optional<qint64> id = journal.begin(entry);
        QVERIFY(id);
        QVERIFY(journal.complete(*id, { qint32(500), QStringLiteral("5.00 s") },
                                 JournalOutcome::Refused,
                                 QStringLiteral("the value is outside the limits")));
        const JournalEntry read = readAll().value(0);
        QCOMPARE(read.outcome, JournalOutcome::Refused);
        QCOMPARE(read.outcomeText(), QStringLiteral("refused: the value is outside the limits"));
        QCOMPARE(read.set, std::nullopt);
        QCOMPARE(read.drive.address, std::nullopt);
        QCOMPARE(read.drive.name(), QStringLiteral("serial:/dev/ttyUSB0"));
        QCOMPARE(read.jobId, 0);
    }

    // A program killed between sending and the answer leaves the entry, unknown.
    void anEntryNeverCompletedReadsUnknown()
    {
        {
            Journal journal(journalPath());
            QVERIFY2(journal.open(), qPrintable(journal.errorString()));
            QVERIFY(journal.begin(fullEntry()));
        } // closed without completing it
        const QList<JournalEntry> entries = readAll();
        QCOMPARE(entries.size(), 1);
        QCOMPARE(entries.first().outcome, JournalOutcome::Unknown);
        QCOMPARE(entries.first().outcomeText(), QStringLiteral("unknown"));
        QVERIFY(!entries.first().completedTime.isValid());
        QVERIFY(entries.first().readBack.isEmpty());
        QCOMPARE(entries.first().written, fullEntry().written);
    }

    // Left empty, the time is now and the user, host and program are this process's.
    void theProcessFillsWhatTheEntryLeavesEmpty()
    {
        Journal journal(journalPath());
        QVERIFY(journal.open());
        JournalEntry entry = fullEntry();
        entry.time = {};
        entry.user.clear();
        entry.host.clear();
        entry.program.clear();
        const QDateTime start = QDateTime::currentDateTimeUtc().addMSecs(-1);
        QVERIFY(journal.begin(entry));
        const JournalEntry read = readAll().value(0);
        QVERIFY(read.time >= start && read.time <= QDateTime::currentDateTimeUtc());
        QVERIFY(!read.user.isEmpty());
        QVERIFY(!read.host.isEmpty());
        QVERIFY2(read.program.startsWith(QCoreApplication::applicationName()),
                 qPrintable(read.program));
    }

    void aPasswordIsNeverStored()
    {
        Journal journal(journalPath());
        QVERIFY(journal.open());
        JournalEntry entry = fullEntry();
        entry.parameterId = QStringLiteral("ud.01");
        entry.parameterName = QStringLiteral("Password");
        entry.password = true;
        entry.before = { qint32(4711), QStringLiteral("4711") };
        entry.written = { qint32(500), QStringLiteral("500") };
        const std::optional<qint64> id = journal.begin(entry);
        QVERIFY(id);
        QVERIFY(
            journal.complete(*id, { qint32(500), QStringLiteral("500") }, JournalOutcome::Written));
        const JournalEntry read = readAll().value(0);
        QVERIFY(read.password);
        QVERIFY(read.before.isEmpty());
        QVERIFY(read.written.isEmpty());
        QVERIFY(read.readBack.isEmpty());
        // Nowhere in the file either.
        journal.close();
        QFile file(journalPath());
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        QVERIFY(!bytes.contains("4711"));
    }

    void completingAnUnknownIdFails()
    {
        Journal journal(journalPath());
        QVERIFY(journal.open());
        QVERIFY(!journal.complete(99, {}, JournalOutcome::Written));
        QVERIFY2(journal.errorString().contains(journalPath()), qPrintable(journal.errorString()));
        QVERIFY2(journal.errorString().contains(QStringLiteral("99")),
                 qPrintable(journal.errorString()));
    }

    void aJournalOpenedToReadIsNotWritten()
    {
        {
            Journal journal(journalPath());
            QVERIFY(journal.open());
        }
        Journal reader(journalPath());
        QVERIFY(reader.open(Journal::Access::Read));
        QVERIFY(!reader.begin(fullEntry()));
        QVERIFY(!reader.errorString().isEmpty());
        QVERIFY(reader.entries().value().isEmpty());
    }

    void filtersFindWhatTheyName()
    {
        Journal journal(journalPath());
        QVERIFY(journal.open());
        const JournalDrive first = busDrive(QStringLiteral("1111"), 3);
        const JournalDrive second = busDrive(QStringLiteral("2222"), 5);
        JournalDrive tcp = busDrive(QString(), 1);
        tcp.link = QStringLiteral("tcp:10.0.0.5:5020");
        QList<qint64> id;
        const auto add = [&](const JournalEntry &entry) {
            const std::optional<qint64> begun = journal.begin(entry);
            QVERIFY(begun);
            id << *begun;
        };
        add(entryAt(0, first, QStringLiteral("anna"))); // 0
        add(entryAt(30, second, QStringLiteral("ben"))); // 1
        add(entryAt(60, first, QStringLiteral("ben"), QStringLiteral("op.03"), 0x0A03)); // 2
        add(entryAt(24 * 60, tcp, QStringLiteral("anna"), QStringLiteral("ru.03"), 0x0203)); // 3
        add(entryAt(-10, first, QStringLiteral("anna"))); // 4: clock earlier

        JournalFilter filter;
        QString error;
        QVERIFY(filter.setDrive(QStringLiteral("1111"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[0], id[2], id[4] }));
        QVERIFY(filter.setDrive(QStringLiteral("serial:/dev/ttyUSB0@5"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[1] }));
        QVERIFY(filter.setDrive(QStringLiteral("serial:/dev/ttyUSB0"), &error)); // every address
        QCOMPARE(ids(filter), (QList<qint64> { id[0], id[1], id[2], id[4] }));
        QVERIFY(filter.setDrive(QStringLiteral("tcp:10.0.0.5:5020@1"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[3] }));
        QVERIFY(filter.setDrive(QStringLiteral("9999"), &error));
        QCOMPARE(ids(filter), QList<qint64>());

        filter = {};
        QVERIFY(filter.setParameter(QStringLiteral("OP.3"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[2] }));
        QVERIFY(filter.setParameter(QStringLiteral("op.028"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[0], id[1], id[4] }));
        QVERIFY(filter.setParameter(QStringLiteral("0x0203"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[3] }));
        QVERIFY(filter.setParameter(QStringLiteral("0203h"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[3] }));

        filter = {};
        QVERIFY(filter.setSince(QStringLiteral("2026-11-24T10:30"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[1], id[2], id[3] }));
        QVERIFY(filter.setUntil(QStringLiteral("2026-11-24"), &error)); // the whole day
        QCOMPARE(ids(filter), (QList<qint64> { id[1], id[2] }));
        filter = {};
        QVERIFY(filter.setUntil(QStringLiteral("2026-11-24T10:30"), &error)); // to 10:30:59
        QCOMPARE(ids(filter), (QList<qint64> { id[0], id[1], id[4] }));
        QVERIFY(filter.setUntil(QStringLiteral("2026-11-24T10:29:59"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[0], id[4] }));

        filter = {};
        filter.setUser(QStringLiteral("ben"));
        QCOMPARE(ids(filter), (QList<qint64> { id[1], id[2] }));
        QVERIFY(filter.setDrive(QStringLiteral("1111"), &error));
        QCOMPARE(ids(filter), (QList<qint64> { id[2] }));
        // Newest last: in the order begun, whatever the clocks said.
        QCOMPARE(ids({}), id);
    }

    // A journal is reopened and appended to; entries of earlier runs stay.
    void reopeningAppends()
    {
        for (int run = 0; run < 3; ++run) {
            Journal journal(journalPath());
            QVERIFY2(journal.open(), qPrintable(journal.errorString()));
            QVERIFY(journal.begin(fullEntry()));
        }
        QCOMPARE(readAll().size(), 3);
        QSqlDatabase db
            = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("check"));
        db.setDatabaseName(journalPath());
        QVERIFY(db.open());
        {
            QSqlQuery query(db);
            QVERIFY(query.exec(QStringLiteral("PRAGMA journal_mode")) && query.next());
            QCOMPARE(query.value(0).toString(), QStringLiteral("wal"));
            QVERIFY(query.exec(QStringLiteral("PRAGMA user_version")) && query.next());
            QCOMPARE(query.value(0).toInt(), 1);
        }
        db.close();
        db = {};
        QSqlDatabase::removeDatabase(QStringLiteral("check"));
    }

    // The log is copied into the file beside the entries, every kCheckpointEntries, while the
    // journal stays open: the file grows, the log does not grow for ever, nothing is lost.
    void theLogIsCopiedBesideTheEntries()
    {
        Journal journal(journalPath());
        QVERIFY(journal.open());
        const qint64 newFile = QFileInfo(journalPath()).size();
        for (int i = 0; i < Journal::kCheckpointEntries; ++i) {
            const std::optional<qint64> id = journal.begin(fullEntry());
            QVERIFY(id);
            QVERIFY(journal.complete(*id, {}, JournalOutcome::Written));
        }
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(journalPath()).size() > newFile, 30000);
        QCOMPARE(readAll().size(), Journal::kCheckpointEntries);
    }

    // Two journals in one process each have a connection of their own.
    void twoJournalsInOneProcess()
    {
        Journal a(journalPath());
        Journal b(journalPath());
        QVERIFY(a.open());
        QVERIFY(b.open());
        const std::optional<qint64> first = a.begin(fullEntry());
        const std::optional<qint64> second = b.begin(fullEntry());
        QVERIFY(first && second && *first != *second);
        QVERIFY(b.complete(*first, {}, JournalOutcome::Written));
        QCOMPARE(readAll().size(), 2);
    }
};

QTEST_GUILESS_MAIN(tst_Journal)
#include "tst_journal.moc"
