// drivedesk-cli: DriveDesk on the command line.
#include "Translations.h"
#include "cli/CliRunner.h"
#include "cli/CommandLine.h"
#include "link/SignalNotifier.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTimer>

#include <csignal>
#include <cstdio>

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
    DriveDesk::SignalNotifier interrupts;
    QObject::connect(&interrupts, &DriveDesk::SignalNotifier::caught, &runner, [&runner, &app] {
        if (!runner.interrupt())
            app.exit(130);
    });
    // Without the socket pair Ctrl+C keeps its default: the program ends at once.
    interrupts.watch({SIGINT});
    QTimer::singleShot(0, &runner, &DriveDesk::CliRunner::start);
    return app.exec();
}
