// `drivedesk-cli download` journals every value it writes (docs/journal.md), against
// drivedesk-sim read again: one entry per value; killed half way, every write sent is in the
// journal as written or unknown and none the drive took is missing; a journal that cannot be
// written stops it with nothing written; --no-journal downloads without one.
#include "../cli/CliTestSupport.h"

#include "journal/Journal.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTemporaryDir>

#include <algorithm>
#include <csignal>
#include <unistd.h>

using namespace DriveDesk;
using namespace DriveDesk::CliTest;

namespace {

QList<JournalEntry> entriesOf(const QString &path)
{
    Journal journal(path);
    if (!journal.open(Journal::Access::Read))
        return {};
    return journal.entries().value_or(QList<JournalEntry>());
}

// A parameter file's values: "op.20" -> raw per set.
using FileValues = QHash<QString, QList<qint64>>;

FileValues valuesOf(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    FileValues values;
    const QJsonArray groups
        = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("groups")).toArray();
    for (const QJsonValue &group : groups) {
        for (const QJsonValue &parameter :
             group.toObject().value(QStringLiteral("parameters")).toArray()) {
            QList<qint64> raw;
            for (const QJsonValue &value :
                 parameter.toObject().value(QStringLiteral("values")).toArray())
                raw << value.toInteger(-1);
            values.insert(parameter.toObject().value(QStringLiteral("id")).toString(), raw);
        }
    }
    return values;
}

// Each set of the parameters named moved `step` times its number + 1 away from what it holds.
bool changeFile(const QString &path, const QStringList &ids, int step)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    QJsonArray groups = root.value(QStringLiteral("groups")).toArray();
    int changed = 0;
    for (qsizetype g = 0; g < groups.size(); ++g) {
        QJsonObject group = groups[g].toObject();
        QJsonArray parameters = group.value(QStringLiteral("parameters")).toArray();
        for (qsizetype p = 0; p < parameters.size(); ++p) {
            QJsonObject parameter = parameters[p].toObject();
            if (!ids.contains(parameter.value(QStringLiteral("id")).toString()))
                continue;
            QJsonArray values = parameter.value(QStringLiteral("values")).toArray();
            for (qsizetype set = 0; set < values.size(); ++set) {
                const qint64 held = values[set].toInteger();
                const qint64 by = step * (set + 1);
                values[set] = held > by ? held - by : held + by;
            }
            parameter.insert(QStringLiteral("values"), values);
            parameters[p] = parameter;
            ++changed;
        }
        group.insert(QStringLiteral("parameters"), parameters);
        groups[g] = group;
    }
    root.insert(QStringLiteral("groups"), groups);
    return changed == ids.size() && file.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && file.write(QJsonDocument(root).toJson()) > 0;
}

// A parameter's id as the parameter file has it: "dr.4" for the journal's "dr.04".
QString fileId(const QString &id)
{
    return QStringLiteral("%1.%2").arg(id.section(QLatin1Char('.'), 0, 0)).arg(id.section(QLatin1Char('.'), 1).toInt());
}

// drivedesk-cli with a data folder of its own (where the default journal lives).
Run cliWithData(const QStringList &arguments, const QString &home)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("XDG_CACHE_HOME"), home + QStringLiteral("/cache"));
    environment.insert(QStringLiteral("XDG_DATA_HOME"), home + QStringLiteral("/data"));
    return cliIn(arguments, environment);
}

} // namespace

class TestCliDownloadJournal : public QObject
{
    Q_OBJECT

private:
    Run cliOn(const SimulatorProcess &server, const QStringList &command) const
    {
        return cliWithData(QStringList { QStringLiteral("--connect"), server.target() } + command,
                           m_dir->path());
    }

    // The drive behind `server` as a parameter file, read now.
    FileValues driveNow(const SimulatorProcess &server, const QString &name,
                        const QStringList &options = {}) const
    {
        const QString path = m_dir->filePath(name);
        const Run run = cliOn(server, options + QStringList { QStringLiteral("upload"), path });
        return run.exitCode == 0 ? valuesOf(path) : FileValues {};
    }

    std::unique_ptr<QTemporaryDir> m_dir; // made as the user the tests run as

private slots:
    void initTestCase()
    {
        // Root writes into a read-only file: the commands run as an ordinary user, as the
        // program is used, so that a read-only journal is one.
        if (::geteuid() == 0) {
            QVERIFY(::setgid(65534) == 0);
            QVERIFY(::setuid(65534) == 0);
        }
        m_dir = std::make_unique<QTemporaryDir>();
        QVERIFY(m_dir->isValid());
    }

    void theCommandLineJournalsItsDownload()
    {
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString file = m_dir->filePath(QStringLiteral("f5.json"));
        QVERIFY2(cliOn(server, { QStringLiteral("upload"), file }).exitCode == 0, "upload");
        QVERIFY(changeFile(file, { QStringLiteral("op.20") }, 10));
        const QString path = m_dir->filePath(QStringLiteral("cli.sqlite"));
        const Run run = cliOn(server, { QStringLiteral("--journal"), path, QStringLiteral("download"), file });
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));

        const FileValues now = driveNow(server, QStringLiteral("cli-after.json"));
        const FileValues wanted = valuesOf(file);
        QVERIFY(!now.isEmpty());
        int fixedSpeed = 0;
        for (const JournalEntry &entry : entriesOf(path)) {
            QCOMPARE(entry.jobDescription, QStringLiteral("download of f5.json"));
            QCOMPARE(entry.drive.link, server.target());
            QCOMPARE(entry.outcome, JournalOutcome::Written);
            if (entry.parameterId != QLatin1String("op.20"))
                continue;
            ++fixedSpeed;
            const qsizetype set = entry.set.value_or(0);
            QCOMPARE(entry.written.raw, wanted.value(entry.parameterId).value(set));
            QCOMPARE(entry.readBack.raw, now.value(entry.parameterId).value(set));
            QCOMPARE(entry.before.raw, entry.written.raw.value_or(0) + 10 * (set + 1));
        }
        QCOMPARE(fixedSpeed, 8);
    }

    // SIGKILL in the middle of the writing: every value sent has its entry, written or
    // unknown, and the drive read again agrees; none the drive took is missing.
    void aKilledDownloadLeavesEveryWriteSentInTheJournal()
    {
        // Paced slow enough that the writing takes about a second; the command waits as long
        // for an answer as the line needs.
        const QStringList baud { QStringLiteral("--baud"), QStringLiteral("4800") };
        SimulatorProcess server(QStringList { QStringLiteral("--pace") } + baud);
        QVERIFY2(server.started(), qPrintable(server.error()));
        // The same simulated drive in process, quicker to read.
        const QString file = m_dir->filePath(QStringLiteral("killed.json"));
        const Run upload = cliWithData({ QStringLiteral("--connect"), QStringLiteral("sim"),
                                         QStringLiteral("upload"), file },
                                       m_dir->path());
        QVERIFY2(upload.exitCode == 0, qPrintable(explain(upload)));
        const FileValues before = valuesOf(file);
        const QStringList ids { QStringLiteral("op.10"), QStringLiteral("op.11"),
                                QStringLiteral("op.20"), QStringLiteral("dr.4") };
        QVERIFY(changeFile(file, ids, 1));
        const FileValues wanted = valuesOf(file);

        const QString path = m_dir->filePath(QStringLiteral("killed.sqlite"));
        QProcess process;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("XDG_CACHE_HOME"), m_dir->filePath(QStringLiteral("cache")));
        process.setProcessEnvironment(environment);
        process.start(kCli, QStringList { QStringLiteral("--connect"), server.target() } + baud
                                + QStringList { QStringLiteral("--journal"), path,
                                                QStringLiteral("download"), file });
        QVERIFY(process.waitForStarted());
        // Killed once the drive has taken a first value, with more on their way.
        const bool writing = QTest::qWaitFor([&] {
            if (process.state() != QProcess::Running)
                return true;
            const QList<JournalEntry> entries = entriesOf(path);
            return std::any_of(entries.begin(), entries.end(), [](const JournalEntry &entry) {
                return entry.outcome != JournalOutcome::Unknown;
            });
        }, 120000);
        QVERIFY(writing);
        QCOMPARE(process.state(), QProcess::Running);
        ::kill(pid_t(process.processId()), SIGKILL);
        QVERIFY(process.waitForFinished(10000));

        const FileValues now = driveNow(server, QStringLiteral("killed-after.json"), baud);
        QVERIFY(!now.isEmpty());
        const QList<JournalEntry> entries = entriesOf(path);
        QVERIFY(!entries.isEmpty());
        int unknown = 0;
        QSet<QString> journaled;
        for (const JournalEntry &entry : entries) {
            const qsizetype set = entry.set.value_or(0);
            const QString id = fileId(entry.parameterId);
            const qint64 held = now.value(id).value(set, -1);
            const QString what = QStringLiteral("%1 set %2: %3, holds %4").arg(id).arg(set).arg(entry.outcomeText()).arg(held);
            journaled << QStringLiteral("%1/%2").arg(id).arg(set);
            if (!ids.contains(id))
                continue; // written whatever the drive holds (Fr.09, ud.11)
            QCOMPARE(entry.before.raw, before.value(id).value(set));
            QCOMPARE(entry.written.raw, wanted.value(id).value(set));
            if (entry.outcome == JournalOutcome::Written) {
                QVERIFY2(held == *entry.written.raw, qPrintable(what));
            } else {
                QVERIFY2(entry.outcome == JournalOutcome::Unknown, qPrintable(what));
                QVERIFY2(held == *entry.written.raw || held == *entry.before.raw, qPrintable(what));
                ++unknown;
            }
        }
        QVERIFY2(unknown > 0, "the download ended before it was killed");
        // Every value the drive took from the download has its entry.
        for (const QString &id : ids) {
            for (qsizetype set = 0; set < wanted.value(id).size(); ++set) {
                if (now.value(id).value(set) == wanted.value(id).value(set))
                    QVERIFY2(journaled.contains(QStringLiteral("%1/%2").arg(id).arg(set)), qPrintable(id));
            }
        }
    }

    void aJournalThatCannotBeWrittenStopsTheDownloadUnsent_data()
    {
        QTest::addColumn<bool>("readOnly");
        QTest::newRow("read-only") << true;
        QTest::newRow("not a journal") << false;
    }

    void aJournalThatCannotBeWrittenStopsTheDownloadUnsent()
    {
        QFETCH(bool, readOnly);
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString file = m_dir->filePath(QStringLiteral("refused.json"));
        QVERIFY2(cliOn(server, { QStringLiteral("upload"), file }).exitCode == 0, "upload");
        QVERIFY(changeFile(file, { QStringLiteral("op.20") }, 10));

        const QString path = m_dir->filePath(readOnly ? QStringLiteral("read-only.sqlite")
                                                     : QStringLiteral("corrupt.sqlite"));
        if (readOnly) {
            Journal journal(path);
            QVERIFY(journal.open());
            journal.close();
            QVERIFY(QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::ReadGroup));
        } else {
            QFile corrupt(path);
            QVERIFY(corrupt.open(QIODevice::WriteOnly));
            corrupt.write(QByteArray(4096, 'x'));
        }
        const Run run = cliOn(server, { QStringLiteral("--journal"), path, QStringLiteral("download"), file });
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("nothing was written")) && run.err.contains(path)
                     && run.err.contains(QStringLiteral("--no-journal")),
                 qPrintable(run.err));
        const FileValues now = driveNow(server, QStringLiteral("refused-after.json"));
        const FileValues wanted = valuesOf(file);
        for (qsizetype set = 0; set < 8; ++set)
            QCOMPARE(now.value(QStringLiteral("op.20")).value(set), wanted.value(QStringLiteral("op.20")).value(set) + 10 * (set + 1));
    }

    void noJournalDownloadsWithoutOne()
    {
        SimulatorProcess server;
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString file = m_dir->filePath(QStringLiteral("without.json"));
        QVERIFY2(cliOn(server, { QStringLiteral("upload"), file }).exitCode == 0, "upload");
        QVERIFY(changeFile(file, { QStringLiteral("op.20") }, 10));
        QTemporaryDir home;
        const Run run = cliWithData({ QStringLiteral("--connect"), server.target(),
                                      QStringLiteral("--no-journal"), QStringLiteral("download"), file },
                                    home.path());
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY(!QFile::exists(home.filePath(QStringLiteral("data/DriveDesk/journal.sqlite"))));
        const FileValues now = driveNow(server, QStringLiteral("without-after.json"));
        QCOMPARE(now.value(QStringLiteral("op.20")), valuesOf(file).value(QStringLiteral("op.20")));
    }
};

QTEST_GUILESS_MAIN(TestCliDownloadJournal)
#include "tst_clidownloadjournal.moc"
