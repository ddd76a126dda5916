// drivedesk-cli: DriveDesk on the command line.
#include "Translations.h"
#include "cli/CliRunner.h"
#include "cli/CommandLine.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTimer>

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
    QTimer::singleShot(0, &runner, &DriveDesk::CliRunner::start);
    return app.exec();
}
