#include "Git.h"

#include <QProcess>

namespace DriveDesk {

namespace {

const QString kProgram = QStringLiteral("git");

// Options on every run, ahead of the command: what a user's configuration could otherwise
// add to a run that is meant to be the same everywhere.
QStringList fixedOptions()
{
    return {QStringLiteral("-c"), QStringLiteral("core.hooksPath=/dev/null"),
            QStringLiteral("-c"), QStringLiteral("commit.gpgSign=false"),
            QStringLiteral("-c"), QStringLiteral("tag.gpgSign=false"),
            QStringLiteral("-c"), QStringLiteral("log.showSignature=false"),
            QStringLiteral("-c"), QStringLiteral("core.autocrlf=false"),
            QStringLiteral("-c"), QStringLiteral("core.fsmonitor=false"),
            QStringLiteral("-c"), QStringLiteral("core.quotePath=false"),
            QStringLiteral("-c"), QStringLiteral("color.ui=false"),
            QStringLiteral("-c"), QStringLiteral("i18n.logOutputEncoding=UTF-8"),
            QStringLiteral("--no-pager")};
}

QProcessEnvironment fixedEnvironment()
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"GIT_DIR", "GIT_WORK_TREE", "GIT_INDEX_FILE", "GIT_OBJECT_DIRECTORY",
                             "GIT_ALTERNATE_OBJECT_DIRECTORIES", "GIT_CONFIG_PARAMETERS",
                             "GIT_CONFIG_COUNT", "GIT_NAMESPACE", "GIT_CEILING_DIRECTORIES",
                             "GIT_EXTERNAL_DIFF", "GIT_TRACE", "LANGUAGE", "LANG"})
        environment.remove(QLatin1String(name));
    environment.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
    environment.insert(QStringLiteral("GIT_PAGER"), QStringLiteral("cat"));
    environment.insert(QStringLiteral("PAGER"), QStringLiteral("cat"));
    environment.insert(QStringLiteral("GIT_TERMINAL_PROMPT"), QStringLiteral("0"));
    environment.insert(QStringLiteral("GIT_ASKPASS"), QStringLiteral("true"));
    environment.insert(QStringLiteral("GIT_EDITOR"), QStringLiteral("true"));
    return environment;
}

// git's own words, the lines that say why ("fatal: ...", "error: ..."), hints left out.
QString gitSays(const QByteArray &errorOutput)
{
    QStringList lines;
    for (const QString &line : QString::fromUtf8(errorOutput).split(QLatin1Char('\n'))) {
        const QString trimmed = line.trimmed();
        if (!trimmed.isEmpty() && !trimmed.startsWith(QLatin1String("hint:")))
            lines << trimmed;
    }
    return lines.join(QLatin1Char(' '));
}

} // namespace

Git::Git(QString directory)
    : m_directory(std::move(directory))
    , m_environment(fixedEnvironment())
{}

void Git::setVariable(const QString &name, const QString &value)
{
    m_environment.insert(name, value);
}

Git::Result Git::run(const QStringList &arguments, const QByteArray &input) const
{
    QProcess process;
    process.setProcessEnvironment(m_environment);
    process.setWorkingDirectory(m_directory);
    process.start(kProgram, fixedOptions() + arguments);
    Result result;
    if (!process.waitForStarted(-1)) {
        result.error = tr("git cannot be run (%1): install git").arg(process.errorString());
        return result;
    }
    result.started = true;
    if (!input.isEmpty())
        process.write(input);
    process.closeWriteChannel();
    process.waitForFinished(-1);
    result.out = process.readAllStandardOutput();
    const QByteArray errorOutput = process.readAllStandardError();
    result.ok = process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
    if (!result.ok) {
        const QString said = gitSays(errorOutput);
        result.error = said.isEmpty()
                           ? tr("git %1 failed with exit code %2")
                                 .arg(arguments.value(0))
                                 .arg(process.exitCode())
                           : tr("git %1 failed: %2").arg(arguments.value(0), said);
    }
    return result;
}

bool Git::isAvailable(QString *error)
{
    const Result result = Git(QString()).run({QStringLiteral("--version")});
    if (!result.ok && error)
        *error = result.error;
    return result.ok;
}

} // namespace DriveDesk
