// `drivedesk-cli write` journals what it writes (docs/journal.md): one entry with the drive,
// the value before, the value written and the value read back, checked against the drive read
// again; a journal that cannot take the entry stops the write before anything is sent;
// --no-journal writes without one.
#include "../cli/CliTestSupport.h"

#include "journal/Journal.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::CliTest;

class TestJournalWrites : public QObject
{
    Q_OBJECT

private:
    Run cliOn(const SimulatorProcess &server, const QStringList &command) const
    {
        return cli(QStringList { QStringLiteral("--connect"), server.target() } + command,
                   m_dir.path());
    }

    // The value the drive holds now, as `read` shows it ("op.20  Fixed speed 1 = 222 1/min").
    QString held(const SimulatorProcess &server, const QString &id, const QString &set) const
    {
        const Run run = cliOn(server, { QStringLiteral("read"), id, QStringLiteral("--set"), set });
        return run.exitCode == 0 ? run.out.trimmed() : run.err;
    }

    QTemporaryDir m_dir;

private slots:
    void aWriteIsJournaledAsTheDriveTookIt()
    {
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString path = m_dir.filePath(QStringLiteral("writes.sqlite"));
        const Run run = cliOn(server, { QStringLiteral("--journal"), path, QStringLiteral("write"),
                                        QStringLiteral("--sets"), QStringLiteral("2"),
                                        QStringLiteral("op.20"), QStringLiteral("222") });
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(held(server, QStringLiteral("op.20"), QStringLiteral("2")).contains(QStringLiteral("= 222 1/min")),
                 qPrintable(held(server, QStringLiteral("op.20"), QStringLiteral("2"))));

        Journal journal(path);
        QVERIFY2(journal.open(Journal::Access::Read), qPrintable(journal.errorString()));
        const std::optional<QList<JournalEntry>> entries = journal.entries();
        QVERIFY(entries);
        QCOMPARE(entries->size(), 1);
        const JournalEntry &entry = entries->constFirst();
        QCOMPARE(entry.parameterId, QStringLiteral("op.20"));
        QCOMPARE(entry.set, 2);
        QCOMPARE(entry.before.text, QStringLiteral("100 1/min"));
        QCOMPARE(entry.written.raw, 222);
        QCOMPARE(entry.readBack.raw, 222);
        QCOMPARE(entry.outcome, JournalOutcome::Written);
        QCOMPARE(entry.drive.link, server.target());
        QCOMPARE(entry.drive.protocol, QStringLiteral("hsp5"));
        QVERIFY(!entry.drive.serialNumber.isEmpty());
        QVERIFY(!entry.drive.softwareVersion.isEmpty());
        QCOMPARE(entry.jobDescription, QStringLiteral("write op.20"));
        QVERIFY(entry.completedTime.isValid());
    }

    void aJournalThatCannotTakeTheEntryStopsTheWriteUnsent()
    {
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        // Not a journal: a file of other bytes.
        const QString path = m_dir.filePath(QStringLiteral("corrupt.sqlite"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(4096, 'x'));
        file.close();
        const Run run = cliOn(server, { QStringLiteral("--journal"), path, QStringLiteral("write"),
                                        QStringLiteral("--sets"), QStringLiteral("3"),
                                        QStringLiteral("op.20"), QStringLiteral("333") });
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("op.20 not written"))
                     && run.err.contains(path) && run.err.contains(QStringLiteral("--no-journal")),
                 qPrintable(run.err));
        QVERIFY2(held(server, QStringLiteral("op.20"), QStringLiteral("3")).contains(QStringLiteral("= 100 1/min")),
                 qPrintable(held(server, QStringLiteral("op.20"), QStringLiteral("3"))));

        // The user's choice: write without the journal.
        const Run without = cliOn(server, { QStringLiteral("--no-journal"), QStringLiteral("write"),
                                            QStringLiteral("--sets"), QStringLiteral("3"),
                                            QStringLiteral("op.20"), QStringLiteral("333") });
        QVERIFY2(without.exitCode == 0, qPrintable(without.err));
        QVERIFY(held(server, QStringLiteral("op.20"), QStringLiteral("3")).contains(QStringLiteral("= 333 1/min")));
    }

    void noJournalWritesWithoutOne()
    {
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString path = m_dir.filePath(QStringLiteral("never.sqlite"));
        const Run run = cliOn(server, { QStringLiteral("--no-journal"), QStringLiteral("write"),
                                        QStringLiteral("--sets"), QStringLiteral("4"),
                                        QStringLiteral("op.20"), QStringLiteral("444") });
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY(!QFile::exists(path));
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("DriveDesk/journal.sqlite"))));
        QVERIFY2(held(server, QStringLiteral("op.20"), QStringLiteral("4")).contains(QStringLiteral("= 444 1/min")),
                 qPrintable(held(server, QStringLiteral("op.20"), QStringLiteral("4"))));
    }
};

QTEST_GUILESS_MAIN(TestJournalWrites)
#include "tst_journalwrites.moc"
