#include "CliTestSupport.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <csignal>

using namespace DriveDesk::CliTest;

namespace {

// From the freeze to the end of drivedesk-cli: the client's bound over TCP (docs/client.md,
// 4.8 s for HSP5 at 38400 Bd), the check after it and a busy machine. Without
// the bound a scan on a frozen line runs for many minutes.
constexpr int kAllowedMs = 10000;

} // namespace

// drivedesk-cli against drivedesk-sim whose drive freezes (SIGUSR1) behind the open connection:
// every command ends within seconds with exit 3, saying the drive stopped answering and how
// far it got.
class TestCliSilence : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(m_cache.isValid() && m_files.isValid()); }

    void aFreezeOnTheWayEndsTheCommand_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::addColumn<QString>("command");
        for (const char *protocol : { "hsp5", "din66019ii" }) {
            for (const char *command : { "scan", "upload" }) {
                QTest::addRow("%s %s", protocol, command)
                    << QString::fromLatin1(protocol) << QString::fromLatin1(command);
            }
        }
    }

    void aFreezeOnTheWayEndsTheCommand()
    {
        QFETCH(QString, protocol);
        QFETCH(QString, command);
        // Paced at the baud rate, a scan of the whole drive takes long enough to freeze it on
        // the way.
        SimulatorProcess server(
            { QStringLiteral("--protocol"), protocol, QStringLiteral("--pace") });
        QVERIFY2(server.started(), qPrintable(server.error()));
        const QString file = m_files.filePath(protocol + QStringLiteral("-upload.json"));
        QStringList arguments { QStringLiteral("--no-cache"), command };
        if (command == QLatin1String("upload"))
            arguments << file;
        else
            arguments << QStringLiteral("--values");
        QProcess cliProcess;
        start(cliProcess, server, protocol, arguments);
        QVERIFY2(server.waitForClient(60000), "drivedesk-cli did not connect");
        QTest::qWait(1500);
        QCOMPARE(cliProcess.state(), QProcess::Running);
        QElapsedTimer sinceFreeze;
        sinceFreeze.start();
        QCOMPARE(::kill(pid_t(server.processId()), SIGUSR1), 0);
        QVERIFY2(cliProcess.waitForFinished(120000), "drivedesk-cli did not finish");
        const qint64 took = sinceFreeze.elapsed();
        const QString err = QString::fromUtf8(cliProcess.readAllStandardError());
        QCOMPARE(cliProcess.exitCode(), 3);
        QVERIFY2(took < kAllowedMs, qPrintable(QStringLiteral("%1 ms after the freeze").arg(took)));
        QVERIFY2(err.contains(QStringLiteral("the drive stopped answering")), qPrintable(err));
        if (command == QLatin1String("scan")) {
            QVERIFY2(
                err.contains(QRegularExpression(QStringLiteral(
                    "the drive stopped answering \\(no answer to \\d+ request.* in [0-9.]+ s\\): "
                    "scan stopped after \\d+ of \\d+ parameter"))),
                qPrintable(err));
        } else {
            QVERIFY(!QFile::exists(file)); // no backup with holes
        }
    }

    // The device server goes away mid-scan (the gateway's power, a pulled cable): no
    // connection is exit 3, as the README says, not 1.
    void aLinkLostOnTheWayEndsWithExit3_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("hsp5") << QStringLiteral("hsp5");
        QTest::newRow("din66019ii") << QStringLiteral("din66019ii");
    }

    void aLinkLostOnTheWayEndsWithExit3()
    {
        QFETCH(QString, protocol);
        SimulatorProcess server(
            { QStringLiteral("--protocol"), protocol, QStringLiteral("--pace") });
        QVERIFY2(server.started(), qPrintable(server.error()));
        QProcess cliProcess;
        start(cliProcess, server, protocol,
              { QStringLiteral("--no-cache"), QStringLiteral("scan"), QStringLiteral("--values") });
        QVERIFY2(server.waitForClient(60000), "drivedesk-cli did not connect");
        QTest::qWait(1500);
        QCOMPARE(cliProcess.state(), QProcess::Running);
        QCOMPARE(::kill(pid_t(server.processId()), SIGKILL), 0);
        QVERIFY2(cliProcess.waitForFinished(120000), "drivedesk-cli did not finish");
        const QString err = QString::fromUtf8(cliProcess.readAllStandardError());
        QCOMPARE(cliProcess.exitCode(), 3);
        QVERIFY2(err.contains(QStringLiteral("connection")), qPrintable(err));
    }

    void aFrozenDriveEndsEveryCommand_data()
    {
        QTest::addColumn<QString>("protocol");
        QTest::addColumn<QStringList>("command");
        for (const char *protocol : { "hsp5", "din66019ii" }) {
            QTest::addRow("%s write", protocol)
                << QString::fromLatin1(protocol)
                << QStringList { QStringLiteral("write"), QStringLiteral("op.11"),
                                 QStringLiteral("2500"), QStringLiteral("--sets"),
                                 QStringLiteral("2") };
            QTest::addRow("%s download", protocol)
                << QString::fromLatin1(protocol)
                << QStringList { QStringLiteral("download"), QStringLiteral("FILE") };
            QTest::addRow("%s read", protocol)
                << QString::fromLatin1(protocol)
                << QStringList { QStringLiteral("read"), QStringLiteral("ru.3") };
        }
    }

    // Frozen before the command starts: the connection opens, nothing answers.
    void aFrozenDriveEndsEveryCommand()
    {
        QFETCH(QString, protocol);
        QFETCH(QStringList, command);
        if (command.contains(QStringLiteral("FILE"))) {
            const QString file = m_files.filePath(protocol + QStringLiteral("-download.json"));
            const Run scan = cli(
                { QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("--protocol"),
                  protocol, QStringLiteral("--quiet"), QStringLiteral("scan"),
                  QStringLiteral("--format"), QStringLiteral("json"), QStringLiteral("--values") },
                m_cache.path());
            QVERIFY2(scan.exitCode == 0, qPrintable(explain(scan)));
            QFile out(file);
            QVERIFY(out.open(QIODevice::WriteOnly) && out.write(scan.out.toUtf8()) > 0);
            out.close();
            command.replace(command.indexOf(QStringLiteral("FILE")), file);
        }
        SimulatorProcess server({ QStringLiteral("--protocol"), protocol });
        QVERIFY2(server.started(), qPrintable(server.error()));
        QCOMPARE(::kill(pid_t(server.processId()), SIGUSR1), 0);
        QTest::qWait(200); // the signal reaches the simulator's event loop
        QElapsedTimer timer;
        timer.start();
        QProcess cliProcess;
        start(cliProcess, server, protocol, command);
        QVERIFY2(cliProcess.waitForFinished(120000), "drivedesk-cli did not finish");
        const QString err = QString::fromUtf8(cliProcess.readAllStandardError());
        QCOMPARE(cliProcess.exitCode(), 3);
        QVERIFY2(timer.elapsed() < kAllowedMs,
                 qPrintable(QStringLiteral("%1 ms").arg(timer.elapsed())));
        QVERIFY2(err.contains(QStringLiteral("the drive stopped answering")), qPrintable(err));
    }

private:
    void start(QProcess &process, const SimulatorProcess &server, const QString &protocol,
               const QStringList &command)
    {
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("XDG_CACHE_HOME"), m_cache.path());
        process.setProcessEnvironment(environment);
        process.start(kCli,
                      QStringList { QStringLiteral("--connect"), server.target(),
                                    QStringLiteral("--protocol"), protocol,
                                    QStringLiteral("--quiet") }
                          + command);
        QVERIFY(process.waitForStarted());
    }

    QTemporaryDir m_cache;
    QTemporaryDir m_files;
};

QTEST_GUILESS_MAIN(TestCliSilence)
#include "tst_clisilence.moc"
