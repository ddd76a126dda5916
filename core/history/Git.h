#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace DriveDesk {

// The git program, run in one directory with a fixed environment: no pager, no terminal
// prompt, messages in C so they read the same everywhere, none of the caller's GIT_DIR and
// the like, and neither hooks nor signing from the user's configuration (user.name and
// user.email are still read from it). Blocks until git has ended, waiting on the process and
// running no event loop: a window runs it on a thread of its own.
class Git
{
    Q_DECLARE_TR_FUNCTIONS(Git)
public:
    struct Result
    {
        bool ok = false;
        bool started = false; // false: the git program could not be run at all
        QByteArray out;
        QString error; // what went wrong, naming what git said; empty when ok
    };

    explicit Git(QString directory);

    const QString &directory() const { return m_directory; }
    // Extra variables for the runs that follow (the author where git's configuration has none).
    void setVariable(const QString &name, const QString &value);

    // `git ARGUMENTS` in the directory, `input` on its standard input.
    Result run(const QStringList &arguments, const QByteArray &input = {}) const;

    // Whether the git program can be run at all; its absence named in *error otherwise.
    static bool isAvailable(QString *error);

private:
    QString m_directory;
    QProcessEnvironment m_environment;
};

} // namespace DriveDesk
