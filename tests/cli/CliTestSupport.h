#pragma once

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

inline Run cli(const QStringList &arguments, const QString &cacheHome = {})
{
    QProcess process;
    if (!cacheHome.isEmpty()) {
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("XDG_CACHE_HOME"), cacheHome);
        process.setProcessEnvironment(environment);
    }
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
    QString error() const { return m_process.errorString() + QString::fromUtf8(m_process.readAllStandardError()); }
    QString target() const { return m_target; }
    qint64 processId() const { return m_process.processId(); }

private:
    mutable QProcess m_process;
    QString m_target;
};

} // namespace DriveDesk::CliTest
