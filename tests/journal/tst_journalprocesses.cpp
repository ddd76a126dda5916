// Several programs write one journal at once (the window and command lines): nothing is lost,
// even when they start together on a journal that does not exist yet.
#include "journal/Journal.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace DriveDesk;

class tst_JournalProcesses : public QObject
{
    Q_OBJECT

private slots:
    void twoWritersLoseNothing()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
        constexpr int kEach = 500;
        QProcess first;
        QProcess second;
        QSignalSpy firstDone(&first, &QProcess::finished);
        QSignalSpy secondDone(&second, &QProcess::finished);
        const QString writer = QStringLiteral(JOURNAL_WRITER);
        first.start(writer, { path, QString::number(kEach), QStringLiteral("AAAA") });
        second.start(writer, { path, QString::number(kEach), QStringLiteral("BBBB") });
        QVERIFY(first.waitForStarted());
        QVERIFY(second.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(!firstDone.isEmpty() && !secondDone.isEmpty(), 120000);
        for (QProcess *process : { &first, &second }) {
            const QByteArray output = process->readAllStandardOutput();
            QVERIFY2(process->exitStatus() == QProcess::NormalExit && process->exitCode() == 0,
                     qPrintable(QString::fromUtf8(output + process->readAllStandardError())));
            QCOMPARE(output.trimmed(), QByteArray("wrote 500"));
        }

        Journal journal(path);
        QVERIFY2(journal.open(Journal::Access::Read), qPrintable(journal.errorString()));
        const QList<JournalEntry> entries = journal.entries().value();
        QCOMPARE(entries.size(), 2 * kEach);
        QSet<qint64> ids;
        QHash<QString, QList<int>> values; // per writer, in the order it wrote them
        for (const JournalEntry &entry : entries) {
            ids.insert(entry.id);
            QCOMPARE(entry.outcome, JournalOutcome::Written);
            QCOMPARE(entry.readBack, entry.written);
            values[entry.drive.serialNumber] << *entry.written.raw;
        }
        QCOMPARE(ids.size(), 2 * kEach);
        QList<int> expected;
        for (int i = 0; i < kEach; ++i)
            expected << i;
        QCOMPARE(values.value(QStringLiteral("AAAA")), expected);
        QCOMPARE(values.value(QStringLiteral("BBBB")), expected);
    }
};

QTEST_GUILESS_MAIN(tst_JournalProcesses)
#include "tst_journalprocesses.moc"
