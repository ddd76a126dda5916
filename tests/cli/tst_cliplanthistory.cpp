#include "CliTestSupport.h"

#include <QDate>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcessEnvironment>
#include <QTcpServer>
#include <QTemporaryDir>

using namespace DriveDesk::CliTest;

namespace {

bool writeText(const QString &path, const QString &text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && file.write(text.toUtf8()) == text.toUtf8().size();
}

} // namespace

// drivedesk-cli plant backup --commit, plant history and verify/download --at: a plant's
// backups as revisions of a git repository, against a DIN66019II bus of two drives and an
// HSP5 drive, with a home of its own so that no configuration of the user's leaks in.
class TestCliPlantHistory : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        m_bus = std::make_unique<SimulatorProcess>(
            QStringList{QStringLiteral("--protocol"), QStringLiteral("din66019ii"),
                        QStringLiteral("--address"), QStringLiteral("2,5")});
        QVERIFY2(m_bus->started(), qPrintable(m_bus->error()));
        m_hoist = std::make_unique<SimulatorProcess>();
        QVERIFY2(m_hoist->started(), qPrintable(m_hoist->error()));
        QVERIFY(m_dir.isValid());
        m_home = m_dir.filePath(QStringLiteral("home"));
        QVERIFY(QDir().mkpath(m_home));
        QVERIFY(writeText(QDir(m_home).filePath(QStringLiteral(".gitconfig")),
                          QStringLiteral("[user]\n\tname = Test Engineer\n\temail = test@example.org\n")));
        m_backups = m_dir.filePath(QStringLiteral("backups"));
        m_plant = m_dir.filePath(QStringLiteral("line3.json"));
        QVERIFY(writeText(m_plant, QStringLiteral(
            "{\"format\": \"drivedesk-plant\", \"version\": 1, \"name\": \"Line 3\", \"links\": ["
            "{\"name\": \"cabinet\", \"connect\": \"%1\", \"protocol\": \"din66019ii\", "
            "\"addresses\": [2, 5]}, "
            "{\"name\": \"hoist\", \"connect\": \"%2\", \"protocol\": \"hsp5\"}]}\n")
                                        .arg(m_bus->target(), m_hoist->target())));
    }

    void cleanupTestCase()
    {
        m_bus.reset();
        m_hoist.reset();
    }

    void theFirstBackupCommitsEveryDriveAsAdded()
    {
        const Run run = plant({QStringLiteral("backup"), m_plant, m_backups, QStringLiteral("--commit")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QRegularExpression(
                     QStringLiteral("\ncommitted [0-9a-f]{12}: Line 3: backup, cabinet-2, cabinet-5, hoist changed\n"
                                    "  cabinet-2 added\n  cabinet-5 added\n  hoist added\n"))),
                 qPrintable(run.out));
        QCOMPARE(git({QStringLiteral("rev-list"), QStringLiteral("--count"), QStringLiteral("HEAD")}),
                 QStringLiteral("1"));
        QCOMPARE(git({QStringLiteral("log"), QStringLiteral("-1"), QStringLiteral("--format=%an <%ae>")}),
                 QStringLiteral("Test Engineer <test@example.org>"));
        m_first = git({QStringLiteral("rev-parse"), QStringLiteral("HEAD")});
    }

    void aBackupThatChangedNoSettingMakesNoCommit()
    {
        const Run run = plant({QStringLiteral("backup"), m_plant, m_backups, QStringLiteral("--commit")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("no setting changed since the last commit: nothing committed\n")),
                 qPrintable(run.out));
        QCOMPARE(git({QStringLiteral("rev-list"), QStringLiteral("--count"), QStringLiteral("HEAD")}),
                 QStringLiteral("1"));
    }

    void oneChangeMakesOneCommitThatNamesIt()
    {
        Run run = cli(drive5({QStringLiteral("write"), QStringLiteral("op.11"), QStringLiteral("2500"),
                              QStringLiteral("--sets"), QStringLiteral("2")}));
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        run = plant({QStringLiteral("backup"), m_plant, m_backups, QStringLiteral("--commit"),
                     QStringLiteral("--message"), QStringLiteral("Speed limit for the new gear")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(git({QStringLiteral("rev-list"), QStringLiteral("--count"), QStringLiteral("HEAD")}),
                 QStringLiteral("2"));
        QCOMPARE(git({QStringLiteral("log"), QStringLiteral("-1"), QStringLiteral("--format=%B")}),
                 QStringLiteral("Speed limit for the new gear\n\n"
                                "cabinet-5 op.11 set 2: 3000 1/min -> 2500 1/min"));
        m_second = git({QStringLiteral("rev-parse"), QStringLiteral("HEAD")});
    }

    void historyListsTheRevisionsNewestFirstWithTheirChanges()
    {
        Run run = plant({QStringLiteral("history"), m_plant, m_backups});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QStringList lines = run.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 6);
        QVERIFY2(lines[0].startsWith(m_second.left(12) + QStringLiteral("  ")), qPrintable(run.out));
        QVERIFY2(lines[0].endsWith(QStringLiteral("  Test Engineer  Speed limit for the new gear")), qPrintable(run.out));
        QCOMPARE(lines[1], QStringLiteral("  cabinet-5 op.11 set 2: 3000 1/min -> 2500 1/min"));
        QVERIFY2(lines[2].startsWith(m_first.left(12) + QStringLiteral("  ")), qPrintable(run.out));
        QCOMPARE(lines.mid(3), (QStringList{QStringLiteral("  cabinet-2 added"),
                                            QStringLiteral("  cabinet-5 added"),
                                            QStringLiteral("  hoist added")}));

        run = plant({QStringLiteral("history"), m_plant, m_backups, QStringLiteral("--parameter"),
                     QStringLiteral("op.11"), QStringLiteral("--format"), QStringLiteral("json")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        const QJsonArray revisions = QJsonDocument::fromJson(run.out.toUtf8()).object()
                                         .value(QStringLiteral("revisions")).toArray();
        QCOMPARE(revisions.size(), 1);
        const QJsonObject revision = revisions[0].toObject();
        QCOMPARE(revision.value(QStringLiteral("id")).toString(), m_second);
        QCOMPARE(revision.value(QStringLiteral("author")).toString(), QStringLiteral("Test Engineer"));
        const QJsonObject change = revision.value(QStringLiteral("changes")).toArray()[0].toObject();
        QCOMPARE(change.value(QStringLiteral("drive")).toString(), QStringLiteral("cabinet-5"));
        QCOMPARE(change.value(QStringLiteral("id")).toString(), QStringLiteral("op.11"));
        QCOMPARE(change.value(QStringLiteral("set")).toInt(), 2);
        QCOMPARE(change.value(QStringLiteral("before")).toString(), QStringLiteral("3000 1/min"));
        QCOMPARE(change.value(QStringLiteral("after")).toString(), QStringLiteral("2500 1/min"));

        run = plant({QStringLiteral("history"), m_plant, m_backups, QStringLiteral("--drive"),
                     QStringLiteral("hoist")});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(run.out.count(QLatin1Char('\n')), 2);
        QVERIFY2(run.out.endsWith(QStringLiteral("\n  hoist added\n")), qPrintable(run.out));
    }

    void verifyAtARevisionReportsTheDifference()
    {
        Run run = plant({QStringLiteral("verify"), m_plant, m_backups, QStringLiteral("--at"),
                         m_first.left(10)});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral(
                     "cabinet-5: 1 difference\n  op.11  Maximum speed forward  set 2  file 3000 1/min  drive 2500 1/min\n")),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-2: equal\n")), qPrintable(run.out));
        // A day names the last revision on or before it: today's is the newest, which the
        // drives equal.
        run = plant({QStringLiteral("verify"), m_plant, m_backups, QStringLiteral("--at"),
                     QDate::currentDate().toString(Qt::ISODate)});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
    }

    void downloadAtARevisionRestoresTheChangedDriveOnly()
    {
        Run run = plant({QStringLiteral("download"), m_plant, m_backups, QStringLiteral("--at"),
                         m_first});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QVERIFY2(run.out.contains(QStringLiteral("cabinet-5: written\n")), qPrintable(run.out));
        for (const QString &drive : {QStringLiteral("cabinet-2"), QStringLiteral("hoist")}) {
            QVERIFY2(run.out.contains(QStringLiteral("%1: already equal, nothing written\n").arg(drive)),
                     qPrintable(run.out));
        }
        run = cli(drive5({QStringLiteral("read"), QStringLiteral("op.11"), QStringLiteral("--set"),
                          QStringLiteral("2")}));
        QVERIFY2(run.out.contains(QStringLiteral("3000 1/min")), qPrintable(explain(run)));
        // The drives read again equal the first revision; the folder still holds the newest.
        run = plant({QStringLiteral("verify"), m_plant, m_backups, QStringLiteral("--at"), m_first});
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(git({QStringLiteral("status"), QStringLiteral("--porcelain"), QStringLiteral("--untracked-files=no")}),
                 QString());
        run = plant({QStringLiteral("verify"), m_plant, m_backups});
        QVERIFY2(run.exitCode == 1, qPrintable(explain(run)));
    }

    void aRevisionThatDoesNotExistIsBadInput()
    {
        Run run = plant({QStringLiteral("verify"), m_plant, m_backups, QStringLiteral("--at"),
                         QStringLiteral("before-the-fire")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("'before-the-fire' is no revision of ")), qPrintable(run.err));
        run = plant({QStringLiteral("download"), m_plant, m_backups, QStringLiteral("--at"),
                     QStringLiteral("1999-12-31")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("no revision on or before 1999-12-31")), qPrintable(run.err));
        QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("nothing"))));
        run = plant({QStringLiteral("history"), m_plant, m_dir.filePath(QStringLiteral("nothing"))});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("is not a git repository of backups")), qPrintable(run.err));
        run = plant({QStringLiteral("backup"), m_plant, m_backups, QStringLiteral("--at"), m_first});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--at belongs to plant verify and plant download")),
                 qPrintable(run.err));
    }

    // No drive answered: nothing saved, so no revision, and the last one stays the newest.
    void aBackupThatSavedNothingCommitsNothing()
    {
        QTcpServer closed;
        QVERIFY(closed.listen(QHostAddress::LocalHost));
        const QString dead = QStringLiteral("tcp:127.0.0.1:%1").arg(closed.serverPort());
        closed.close();
        const QString plantFile = m_dir.filePath(QStringLiteral("dead.json"));
        QVERIFY(writeText(plantFile, QStringLiteral(
            "{\"format\": \"drivedesk-plant\", \"version\": 1, \"name\": \"Line 3\", \"links\": ["
            "{\"name\": \"hoist\", \"connect\": \"%1\", \"protocol\": \"hsp5\"}]}\n").arg(dead)));
        const Run run = plant({QStringLiteral("backup"), plantFile, m_backups, QStringLiteral("--commit")});
        QCOMPARE(run.exitCode, 3);
        QVERIFY2(run.out.contains(QStringLiteral("no drive saved: nothing committed\n")), qPrintable(run.out));
        QCOMPARE(git({QStringLiteral("rev-list"), QStringLiteral("--count"), QStringLiteral("HEAD")}),
                 QStringLiteral("2"));
    }

    // Neither user.name nor user.email anywhere: the login name stands in.
    void withoutAConfiguredUserTheLoginNameCommits()
    {
        const QString home = m_dir.filePath(QStringLiteral("bare-home"));
        QVERIFY(QDir().mkpath(home));
        const QString backups = m_dir.filePath(QStringLiteral("bare-backups"));
        const Run run = plant({QStringLiteral("backup"), m_plant, backups, QStringLiteral("--commit")},
                              home);
        QVERIFY2(run.exitCode == 0, qPrintable(explain(run)));
        QCOMPARE(git({QStringLiteral("log"), QStringLiteral("-1"), QStringLiteral("--format=%an")},
                     backups),
                 QStringLiteral("plantuser"));
    }

    // No git program: refused before anything is sent.
    void withoutGitTheCommitIsRefusedBeforeTheBackup()
    {
        const QString backups = m_dir.filePath(QStringLiteral("no-git"));
        QProcessEnvironment environment = this->environment(m_home);
        environment.insert(QStringLiteral("PATH"), m_dir.filePath(QStringLiteral("empty")));
        const Run run = runCli({QStringLiteral("plant"), QStringLiteral("backup"), m_plant, backups,
                                QStringLiteral("--commit"), QStringLiteral("--quiet")},
                               environment);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("git cannot be run")), qPrintable(run.err));
        QVERIFY(!QFile::exists(QDir(backups).filePath(QStringLiteral("hoist.json"))));
    }

private:
    QProcessEnvironment environment(const QString &home) const
    {
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("HOME"), home);
        environment.insert(QStringLiteral("XDG_CONFIG_HOME"), QDir(home).filePath(QStringLiteral(".config")));
        environment.insert(QStringLiteral("XDG_CACHE_HOME"), QDir(home).filePath(QStringLiteral(".cache")));
        environment.insert(QStringLiteral("XDG_DATA_HOME"), QDir(home).filePath(QStringLiteral(".local/share")));
        environment.insert(QStringLiteral("GIT_CONFIG_NOSYSTEM"), QStringLiteral("1"));
        environment.insert(QStringLiteral("USER"), QStringLiteral("plantuser"));
        environment.insert(QStringLiteral("LOGNAME"), QStringLiteral("plantuser"));
        return environment;
    }

    Run runCli(const QStringList &arguments, const QProcessEnvironment &environment) const
    {
        return cliIn(arguments, environment);
    }

    Run plant(const QStringList &arguments, const QString &home = {}) const
    {
        return runCli(QStringList{QStringLiteral("plant")} + arguments + QStringList{QStringLiteral("--quiet")},
                      environment(home.isEmpty() ? m_home : home));
    }

    Run cli(const QStringList &arguments) const
    {
        return runCli(arguments, environment(m_home));
    }

    QStringList drive5(const QStringList &command) const
    {
        return QStringList{QStringLiteral("--connect"), m_bus->target(), QStringLiteral("--protocol"),
                           QStringLiteral("din66019ii"), QStringLiteral("--address"), QStringLiteral("5"),
                           QStringLiteral("--quiet")}
               + command;
    }

    // git itself, as a user looks at what was committed.
    QString git(const QStringList &arguments, const QString &directory = {}) const
    {
        QProcess process;
        process.setProcessEnvironment(environment(m_home));
        process.setWorkingDirectory(directory.isEmpty() ? m_backups : directory);
        process.start(QStringLiteral("git"), arguments);
        process.waitForFinished();
        return QString::fromUtf8(process.readAllStandardOutput()).trimmed();
    }

    std::unique_ptr<SimulatorProcess> m_bus;
    std::unique_ptr<SimulatorProcess> m_hoist;
    QTemporaryDir m_dir;
    QString m_home;
    QString m_backups;
    QString m_plant;
    QString m_first;
    QString m_second;
};

QTEST_GUILESS_MAIN(TestCliPlantHistory)
#include "tst_cliplanthistory.moc"
