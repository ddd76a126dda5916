#pragma once

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStringList>
#include <QTest>

namespace DriveDesk::CliTest {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

inline const QString kCli = QStringLiteral(DRIVEDESK_BINARY_DIR "/app/cli/drivedesk-cli");
inline const QString kSim = QStringLiteral(DRIVEDESK_BINARY_DIR "/app/sim/drivedesk-sim");

// drivedesk-cli run to its end in `environment`.
inline Run cliIn(const QStringList &arguments, const QProcessEnvironment &environment)
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(kCli, arguments);
    Run run;
    if (!process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        run.err = QStringLiteral("drivedesk-cli did not finish");
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

inline Run cli(const QStringList &arguments, const QString &cacheHome = {})
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    if (!cacheHome.isEmpty())
        environment.insert(QStringLiteral("XDG_CACHE_HOME"), cacheHome);
    return cliIn(arguments, environment);
}

inline Run sim(const QStringList &command)
{
    return cli(QStringList{QStringLiteral("--connect"), QStringLiteral("sim"), QStringLiteral("--quiet")}
               + command);
}

inline QString explain(const Run &run)
{
    return QStringLiteral("exit %1\nstdout: %2\nstderr: %3").arg(run.exitCode).arg(run.out.left(2000), run.err);
}


// drivedesk-sim serving the simulated drive on a free TCP port, for commands that must find
// what the ones before them wrote.
class SimulatorProcess
{
public:
    explicit SimulatorProcess(const QStringList &options = {})
    {
        m_process.start(kSim, QStringList{QStringLiteral("--listen"), QStringLiteral("tcp:127.0.0.1:0")}
                                  + options);
        if (!m_process.waitForStarted())
            return;
        // Not static: the sanitizer build (GCC 12) emits this lambda in a test that never makes
        // a SimulatorProcess, without the static it refers to, and the test does not link.
        const QRegularExpression where(QStringLiteral("tcp:127\\.0\\.0\\.1:(\\d+)"));
        QRegularExpressionMatch match;
        [[maybe_unused]] const bool found = QTest::qWaitFor([&] {
            m_process.waitForReadyRead(100);
            match = where.match(QString::fromUtf8(m_process.peek(4096)));
            return match.hasMatch();
        }, 10000);
        if (match.hasMatch())
            m_target = QStringLiteral("tcp:127.0.0.1:") + match.captured(1);
    }

    ~SimulatorProcess()
    {
        m_process.terminate();
        m_process.waitForFinished(10000);
    }

    bool started() const { return !m_target.isEmpty(); }

    // Whether a client holds a connection to the server, from the kernel's table: a test that
    // cuts or freezes the drive "on the way" must not do it before a slow start has connected.
    bool waitForClient(int timeoutMs) const
    {
        const quint16 port = m_target.section(QLatin1Char(':'), -1).toUShort();
        const QString local = QStringLiteral(":%1 ").arg(port, 4, 16, QLatin1Char('0')).toUpper();
        return QTest::qWaitFor([&] {
            QFile table(QStringLiteral("/proc/net/tcp"));
            if (!table.open(QIODevice::ReadOnly))
                return false;
            const QStringList lines = QString::fromLatin1(table.readAll()).split(QLatin1Char('\n'));
            for (const QString &line : lines) {
                const QStringList fields = line.simplified().split(QLatin1Char(' '));
                // fields: sl local remote state ...; 01 is ESTABLISHED.
                if (fields.size() > 3 && (fields.at(1) + QLatin1Char(' ')).endsWith(local)
                    && fields.at(3) == QLatin1String("01"))
                    return true;
            }
            return false;
        }, timeoutMs);
    }
    QString error() const { return m_process.errorString() + QString::fromUtf8(m_process.readAllStandardError()); }
    QString target() const { return m_target; }
    qint64 processId() const { return m_process.processId(); }

private:
    mutable QProcess m_process;
    QString m_target;
};

} // namespace DriveDesk::CliTest
