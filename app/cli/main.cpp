// drivedesk-cli: DriveDesk on the command line.
#include "Translations.h"
#include "cli/CliRunner.h"
#include "cli/CommandLine.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSocketNotifier>
#include <QTimer>

#include <csignal>
#include <cstdio>
#include <memory>
#include <sys/socket.h>
#include <unistd.h>

namespace {

// Ctrl+C reaches the event loop through a socket pair: a signal handler may do no more than
// write a byte.
int interruptSockets[2] = {-1, -1};

void onInterrupt(int)
{
    const char byte = 1;
    [[maybe_unused]] const ssize_t written = ::write(interruptSockets[0], &byte, 1);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    // Numbers print with '.' whatever the system's locale: output that scripts read.
    QLocale::setDefault(QLocale::c());
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));

    QString error;
    QString help;
    const auto request = DriveDesk::parseCommandLine(QCoreApplication::arguments(), &error, &help);
    if (!request) {
        if (!help.isEmpty() && error.isEmpty()) {
            std::fputs(qPrintable(help), stdout);
            return 0;
        }
        std::fprintf(stderr, "drivedesk-cli: %s\n\n%s", qPrintable(error), qPrintable(help));
        return 2;
    }

    // The drive's texts and the messages speak one language, as in the window.
    DriveDesk::installTranslations(DriveDesk::languageCode(request->connection.language));
    DriveDesk::CliRunner runner(*request);
    QObject::connect(&runner, &DriveDesk::CliRunner::finished, &app, &QCoreApplication::exit,
                     Qt::QueuedConnection);
    // A download stops after the value on its way and reports what it wrote, a scope recording
    // stops and writes what it recorded; anything else just ends (exit 130, as a shell reports an interrupted program).
    std::unique_ptr<QSocketNotifier> interrupts;
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, interruptSockets) == 0) {
        interrupts = std::make_unique<QSocketNotifier>(interruptSockets[1], QSocketNotifier::Read);
        QObject::connect(interrupts.get(), &QSocketNotifier::activated, &runner, [&runner, &app] {
            char byte = 0;
            [[maybe_unused]] const ssize_t read = ::read(interruptSockets[1], &byte, 1);
            if (!runner.interrupt())
                app.exit(130);
        });
        std::signal(SIGINT, onInterrupt);
    }
    QTimer::singleShot(0, &runner, &DriveDesk::CliRunner::start);
    return app.exec();
}
