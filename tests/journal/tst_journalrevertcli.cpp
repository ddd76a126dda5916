// `drivedesk-cli journal revert` against drivedesk-sim (docs/journal.md): the entries' values
// before written back, the oldest one's where several touch a value, and nothing else, checked
// by backing the whole drive up again and comparing; bad input (an unknown entry, another
// drive's entry, a password entry) refused with a clear message and nothing written.
#include "../cli/CliTestSupport.h"

#include "journal/Journal.h"

#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;
using namespace DriveDesk::CliTest;

class TestJournalRevertCli : public QObject
{
    Q_OBJECT

private:
    Run cliOn(const SimulatorProcess &server, const QStringList &command) const
    {
        return cli(QStringList { QStringLiteral("--connect"), server.target(),
                                 QStringLiteral("--journal"), m_path }
                       + command,
                   m_dir.path());
    }

    // "op.20  Fixed speed 1 = 222 1/min  (raw 222, set 2)": what the drive holds now.
    QString held(const SimulatorProcess &server, const QString &set) const
    {
        const Run run = cliOn(server, { QStringLiteral("read"), QStringLiteral("op.20"),
                                        QStringLiteral("--set"), set });
        return run.exitCode == 0 ? run.out.trimmed() : run.err;
    }

    bool write(const SimulatorProcess &server, const QString &set, const QString &value) const
    {
        return cliOn(server, { QStringLiteral("write"), QStringLiteral("--sets"), set,
                               QStringLiteral("op.20"), value })
                   .exitCode
            == 0;
    }

    // The drive backed up to a file (`upload`): every setting of every set.
    QString backUp(const SimulatorProcess &server, const QString &name) const
    {
        const QString path = m_dir.filePath(name);
        return cliOn(server, { QStringLiteral("upload"), path }).exitCode == 0 ? path : QString();
    }

    // `diff` of two backups: 0 equal, 1 different.
    int differ(const QString &a, const QString &b) const
    {
        return cli({ QStringLiteral("diff"), a, b }, m_dir.path()).exitCode;
    }

    QList<JournalEntry> entries() const
    {
        Journal journal(m_path);
        if (!journal.open(Journal::Access::Read))
            return {};
        return journal.entries().value_or(QList<JournalEntry>());
    }

    // An entry as another program would have left it: stored and completed as written.
    qint64 store(JournalEntry entry) const
    {
        Journal journal(m_path);
        if (!journal.open())
            return 0;
        const std::optional<qint64> id = journal.begin(entry);
        if (!id || !journal.complete(*id, entry.written, JournalOutcome::Written))
            return 0;
        return *id;
    }

    QTemporaryDir m_dir;
    QString m_path;

private slots:
    void init()
    {
        m_path = m_dir.filePath(QStringLiteral("%1.sqlite")
                                    .arg(QString::fromLatin1(QTest::currentTestFunction())));
    }

    void theValuesBeforeComeBackAndNothingElseIsWritten()
    {
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString before = backUp(server, QStringLiteral("before.json"));
        QVERIFY(!before.isEmpty());
        QVERIFY(write(server, QStringLiteral("2"), QStringLiteral("222")));
        QVERIFY(write(server, QStringLiteral("2"), QStringLiteral("333")));
        QVERIFY(write(server, QStringLiteral("3"), QStringLiteral("444")));
        QCOMPARE(entries().size(), 3);
        QCOMPARE(differ(before, backUp(server, QStringLiteral("written.json"))), 1);

        // A look first: what would be written, and nothing written.
        const Run look = cliOn(server, { QStringLiteral("journal"), QStringLiteral("revert"),
                                         QStringLiteral("1..3"), QStringLiteral("--dry-run") });
        QVERIFY2(look.exitCode == 0, qPrintable(explain(look)));
        QVERIFY2(look.out.contains(QStringLiteral("sets 2, 3: 333 1/min / 444 1/min -> 100 1/min")),
                 qPrintable(look.out));
        QVERIFY(held(server, QStringLiteral("2")).contains(QStringLiteral("= 333 1/min")));

        const Run run = cliOn(server, { QStringLiteral("journal"), QStringLiteral("revert"),
                                        QStringLiteral("1"), QStringLiteral("2..3") });
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.err.contains(QStringLiteral("revert of entries 1..3")), qPrintable(run.err));
        // The oldest entry's value before: 100, not the 222 the second entry found.
        QVERIFY2(held(server, QStringLiteral("2")).contains(QStringLiteral("= 100 1/min")),
                 qPrintable(held(server, QStringLiteral("2"))));
        QVERIFY2(held(server, QStringLiteral("3")).contains(QStringLiteral("= 100 1/min")),
                 qPrintable(held(server, QStringLiteral("3"))));
        QCOMPARE(differ(before, backUp(server, QStringLiteral("reverted.json"))), 0);

        // Reverted again: the drive holds every value before already, so nothing is written.
        const Run again = cliOn(server, { QStringLiteral("journal"), QStringLiteral("revert"),
                                          QStringLiteral("1..3"), QStringLiteral("--dry-run") });
        QVERIFY2(again.exitCode == 0, qPrintable(explain(again)));
        QVERIFY2(again.out.contains(QStringLiteral("dry run: 0 value"))
                     && !again.out.contains(QStringLiteral("->")),
                 qPrintable(again.out));
    }

    void badEntriesWriteNothing()
    {
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        QVERIFY(write(server, QStringLiteral("4"), QStringLiteral("555")));
        const QList<JournalEntry> written = entries();
        QCOMPARE(written.size(), 1);
        const qint64 own = written.constFirst().id;

        const Run unknown = cliOn(server, { QStringLiteral("journal"), QStringLiteral("revert"),
                                            QString::number(own), QStringLiteral("99") });
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY2(unknown.err.contains(QStringLiteral("entry 99: the journal has no such entry"))
                     && unknown.err.contains(QStringLiteral("nothing was written")),
                 qPrintable(unknown.err));

        JournalEntry otherDrive = written.constFirst();
        otherDrive.drive.serialNumber = QStringLiteral("999999");
        otherDrive.set = 5;
        const qint64 other = store(otherDrive);
        QVERIFY(other > 0);
        const Run foreign = cliOn(server, { QStringLiteral("journal"), QStringLiteral("revert"),
                                            QString::number(own), QString::number(other) });
        QCOMPARE(foreign.exitCode, 2);
        QVERIFY2(foreign.err.contains(QStringLiteral("was written to another drive (999999)")),
                 qPrintable(foreign.err));

        JournalEntry password = written.constFirst();
        password.password = true;
        password.parameterId = QStringLiteral("ud.01");
        password.parameterAddress = 0x0801;
        password.set.reset();
        const qint64 secret = store(password);
        QVERIFY(secret > 0);
        const Run refused = cliOn(server, { QStringLiteral("journal"), QStringLiteral("revert"),
                                            QString::number(secret) });
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(QStringLiteral("is a password entered"))
                     && refused.err.contains(QStringLiteral("cannot be reverted")),
                 qPrintable(refused.err));
        QVERIFY2(held(server, QStringLiteral("4")).contains(QStringLiteral("= 555 1/min")),
                 qPrintable(held(server, QStringLiteral("4"))));

        // By time: the connected drive's entries, the password left out and named.
        const Run since = cliOn(server, { QStringLiteral("journal"), QStringLiteral("revert"),
                                          QStringLiteral("--since"), QStringLiteral("2000-01-01") });
        QVERIFY2(since.exitCode == 0, qPrintable(explain(since)));
        QVERIFY2(since.err.contains(QStringLiteral("left out: entry %1").arg(secret)),
                 qPrintable(since.err));
        QVERIFY2(held(server, QStringLiteral("4")).contains(QStringLiteral("= 100 1/min")),
                 qPrintable(held(server, QStringLiteral("4"))));
        QVERIFY2(held(server, QStringLiteral("5")).contains(QStringLiteral("= 100 1/min")),
                 qPrintable(held(server, QStringLiteral("5"))));
    }

    void badArguments()
    {
        const Run noDrive = cli({ QStringLiteral("journal"), QStringLiteral("revert"),
                                  QStringLiteral("3") });
        QCOMPARE(noDrive.exitCode, 2);
        QVERIFY2(noDrive.err.contains(QStringLiteral("needs --connect")), qPrintable(noDrive.err));
        const Run neither = cli({ QStringLiteral("--connect"), QStringLiteral("sim"),
                                  QStringLiteral("journal"), QStringLiteral("revert") });
        QCOMPARE(neither.exitCode, 2);
        QVERIFY2(neither.err.contains(QStringLiteral("entry numbers")), qPrintable(neither.err));
        const Run range = cli({ QStringLiteral("--connect"), QStringLiteral("sim"),
                                QStringLiteral("journal"), QStringLiteral("revert"),
                                QStringLiteral("9..3") });
        QCOMPARE(range.exitCode, 2);
        QVERIFY2(range.err.contains(QStringLiteral("'9..3' names no entry")), qPrintable(range.err));
    }
};

QTEST_GUILESS_MAIN(TestJournalRevertCli)
#include "tst_journalrevertcli.moc"
