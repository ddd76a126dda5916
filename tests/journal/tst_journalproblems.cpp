// A journal that cannot be written says so before anything would be sent, naming the file and
// what is wrong: a read-only file or folder, a damaged file or none at all, another program's
// file, a newer journal, a lock held past the timeout, a disk that fills. What was journaled
// before stays.
#include "JournalTestSupport.h"

#include <QProcess>
#include <QRandomGenerator>
#include <QSemaphore>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <unistd.h>

using namespace DriveDesk;
using namespace DriveDesk::JournalTest;

namespace {

// Another program's connection to the file, holding the write lock while it lives.
class LockHolder
{
public:
    explicit LockHolder(const QString &path, const QString &name)
        : m_name(name)
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_name);
        db.setDatabaseName(path);
        m_locked = db.open() && QSqlQuery(db).exec(QStringLiteral("BEGIN EXCLUSIVE"))
            && QSqlQuery(db).exec(QStringLiteral("DELETE FROM jobs"));
    }
    ~LockHolder() { release(); }

    bool isLocked() const { return m_locked; }
    void release()
    {
        if (!QSqlDatabase::contains(m_name))
            return;
        {
            QSqlDatabase db = QSqlDatabase::database(m_name, false);
            QSqlQuery(db).exec(QStringLiteral("COMMIT"));
            db.close();
        }
        QSqlDatabase::removeDatabase(m_name);
    }

private:
    QString m_name;
    bool m_locked = false;
};

} // namespace

class tst_JournalProblems : public QObject
{
    Q_OBJECT

private:
    QString journalPath() const { return m_dir->filePath(QStringLiteral("journal.sqlite")); }

    // A journal with one entry, closed.
    void makeJournal(const QString &path)
    {
        Journal journal(path);
        QVERIFY2(journal.open(), qPrintable(journal.errorString()));
        QVERIFY(journal.begin(fullEntry()));
    }

    int entryCount(const QString &path)
    {
        Journal journal(path);
        if (!journal.open(Journal::Access::Read))
            return -1;
        return int(journal.entries().value_or(QList<JournalEntry>()).size());
    }

    std::unique_ptr<QTemporaryDir> m_dir;
    bool m_permissionsHold = true;

private slots:
    void initTestCase()
    {
        // Root writes into a read-only file: the tests take an ordinary user's identity, as the
        // program is used, so that file permissions mean what they say.
        if (::geteuid() == 0) {
            QVERIFY(::setgid(65534) == 0);
            QVERIFY(::setuid(65534) == 0);
        }
        QTemporaryDir probe;
        QFile file(probe.filePath(QStringLiteral("probe")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        QVERIFY(file.setPermissions(QFileDevice::ReadOwner));
        m_permissionsHold = !file.open(QIODevice::WriteOnly);
    }

    void init() { m_dir = std::make_unique<QTemporaryDir>(); }

    void cleanup()
    {
        // Writable again, so that the folder can be removed.
        QFile::setPermissions(m_dir->path(),
                              QFileDevice::ReadOwner | QFileDevice::WriteOwner
                                  | QFileDevice::ExeOwner);
        m_dir.reset();
    }

    void aReadOnlyFile()
    {
        if (!m_permissionsHold)
            QSKIP("file permissions are not enforced for this user");
        makeJournal(journalPath());
        QVERIFY(
            QFile::setPermissions(journalPath(), QFileDevice::ReadOwner | QFileDevice::ReadGroup));
        Journal journal(journalPath());
        QVERIFY(!journal.open());
        QVERIFY2(journal.errorString().contains(journalPath())
                     && journal.errorString().contains(QStringLiteral("read-only")),
                 qPrintable(journal.errorString()));
        QVERIFY(!journal.begin(fullEntry()));
        QCOMPARE(entryCount(journalPath()), 1); // still readable, nothing lost
    }

    void aReadOnlyFolder()
    {
        if (!m_permissionsHold)
            QSKIP("file permissions are not enforced for this user");
        makeJournal(journalPath());
        QVERIFY(
            QFile::setPermissions(m_dir->path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        Journal journal(journalPath());
        QVERIFY(!journal.open());
        QVERIFY2(
            journal.errorString().contains(journalPath())
                && journal.errorString().contains(m_dir->path() + QStringLiteral(" is read-only")),
            qPrintable(journal.errorString()));
        QCOMPARE(entryCount(journalPath()), 1);
    }

    void aFolderThatCannotBeMade()
    {
        if (!m_permissionsHold)
            QSKIP("file permissions are not enforced for this user");
        QVERIFY(
            QFile::setPermissions(m_dir->path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        const QString path = m_dir->filePath(QStringLiteral("DriveDesk/journal.sqlite"));
        Journal journal(path);
        QVERIFY(!journal.open());
        QVERIFY2(journal.errorString().contains(path)
                     && journal.errorString().contains(QStringLiteral("cannot be made")),
                 qPrintable(journal.errorString()));
    }

    void aDamagedFile()
    {
        QFile file(journalPath());
        QVERIFY(file.open(QIODevice::WriteOnly));
        QByteArray noise(8192, Qt::Uninitialized);
        QRandomGenerator generator(7);
        for (char &byte : noise)
            byte = char(generator.bounded(256));
        file.write(noise);
        file.close();
        for (Journal::Access access : { Journal::Access::Write, Journal::Access::Read }) {
            Journal journal(journalPath());
            QVERIFY(!journal.open(access));
            QVERIFY2(journal.errorString().contains(journalPath())
                         && journal.errorString().contains(QStringLiteral("no DriveDesk journal")),
                     qPrintable(journal.errorString()));
        }
        // Left as it was.
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), noise);
    }

    void anotherProgramsDatabase()
    {
        {
            QSqlDatabase db
                = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("other"));
            db.setDatabaseName(journalPath());
            QVERIFY(db.open());
            QVERIFY(QSqlQuery(db).exec(QStringLiteral("CREATE TABLE recipes (name TEXT)")));
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("other"));
        Journal journal(journalPath());
        QVERIFY(!journal.open());
        QVERIFY2(journal.errorString().contains(QStringLiteral("no DriveDesk journal")),
                 qPrintable(journal.errorString()));
    }

    void aNewerJournal()
    {
        makeJournal(journalPath());
        {
            QSqlDatabase db
                = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("newer"));
            db.setDatabaseName(journalPath());
            QVERIFY(db.open());
            QVERIFY(QSqlQuery(db).exec(QStringLiteral("PRAGMA user_version = 2")));
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("newer"));
        Journal journal(journalPath());
        QVERIFY(!journal.open());
        QVERIFY2(journal.errorString().contains(journalPath())
                     && journal.errorString().contains(QStringLiteral("newer DriveDesk"))
                     && journal.errorString().contains(QStringLiteral("version 2")),
                 qPrintable(journal.errorString()));
        QCOMPARE(entryCount(journalPath()), 1); // read as far as it goes
    }

    void aLockHeldPastTheTimeout()
    {
        makeJournal(journalPath());
        Journal early(journalPath());
        early.setBusyTimeout(100);
        QVERIFY(early.open());
        LockHolder holder(journalPath(), QStringLiteral("holder"));
        QVERIFY(holder.isLocked());

        Journal late(journalPath());
        late.setBusyTimeout(100);
        QVERIFY(!late.open());
        QVERIFY2(late.errorString().contains(journalPath())
                     && late.errorString().contains(QStringLiteral("locked by another program"))
                     && late.errorString().contains(QStringLiteral("100 ms")),
                 qPrintable(late.errorString()));
        QVERIFY(!early.begin(fullEntry()));
        QVERIFY2(early.errorString().contains(QStringLiteral("locked")),
                 qPrintable(early.errorString()));

        holder.release();
        QVERIFY2(early.begin(fullEntry()), qPrintable(early.errorString()));
        QCOMPARE(entryCount(journalPath()), 2);
    }

    // Another program's transaction that ends within the timeout is waited for.
    void aShortLockIsWaitedFor()
    {
        makeJournal(journalPath());
        QSemaphore locked;
        QThread *other = QThread::create([this, &locked] {
            LockHolder holder(journalPath(), QStringLiteral("short"));
            locked.release();
            QThread::msleep(300); // the lock the journal below must wait for
        });
        other->start();
        locked.acquire();
        Journal journal(journalPath());
        journal.setBusyTimeout(30000);
        const bool opened = journal.open();
        const std::optional<qint64> id = opened ? journal.begin(fullEntry()) : std::nullopt;
        other->wait();
        delete other;
        QVERIFY2(id, qPrintable(journal.errorString()));
        QCOMPARE(entryCount(journalPath()), 2);
    }

    // A disk that fills while entries are written: the entry that does not fit fails with the
    // file's name, and every entry before it stays.
    void aDiskThatFills()
    {
        makeJournal(journalPath());
        QProcess writer;
        writer.start(QStringLiteral(JOURNAL_WRITER),
                     { journalPath(), QStringLiteral("100000"), QStringLiteral("FULL"),
                       QString::number(256 * 1024) });
        QVERIFY(writer.waitForFinished(120000));
        const QString output = QString::fromUtf8(writer.readAllStandardOutput());
        const QString error = QString::fromUtf8(writer.readAllStandardError());
        QCOMPARE(writer.exitCode(), 1);
        QVERIFY2(error.contains(journalPath()) && error.contains(QStringLiteral("full")),
                 qPrintable(error));
        bool ok = false;
        const int written = output.trimmed().section(QLatin1Char(' '), 1).toInt(&ok);
        QVERIFY2(ok && written > 0, qPrintable(output));
        QCOMPARE(entryCount(journalPath()), 1 + written);
    }
};

QTEST_GUILESS_MAIN(tst_JournalProblems)
#include "tst_journalproblems.moc"
