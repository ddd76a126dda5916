#pragma once

#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

// git in the tests of a plant's backup history.
namespace DriveDesk::GitTest {

// No configuration of the user running the tests: git's home is `home`, with an author.
inline bool useHome(const QTemporaryDir &home)
{
    if (!home.isValid())
        return false;
    qputenv("HOME", home.path().toUtf8());
    qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral(".config")).toUtf8());
    qputenv("GIT_CONFIG_NOSYSTEM", "1");
    QFile config(home.filePath(QStringLiteral(".gitconfig")));
    return config.open(QIODevice::WriteOnly)
        && config.write("[user]\n\tname = Test Engineer\n\temail = test@example.org\n") > 0;
}

// git itself, as a user would look at what DriveDesk committed.
inline QString git(const QString &directory, const QStringList &arguments)
{
    QProcess process;
    process.setWorkingDirectory(directory);
    process.start(QStringLiteral("git"), arguments);
    process.waitForFinished();
    return QString::fromUtf8(process.readAllStandardOutput()).trimmed();
}

} // namespace DriveDesk::GitTest
