// drivedesk: the parameter editor's window, connected to the drive the command line names,
// showing the parameter file it names, or opening the connection dialog.
#include "Translations.h"
#include "files/ParameterFileFeature.h"
#include "main/MainWindow.h"
#include "journal/Journal.h"
#include "main/StartupOptions.h"

#include <QApplication>
#include <QLocale>
#include <QTimer>

#include <cstdio>
#include <cstring>

int main(int argc, char **argv)
{
    // Answered before the window system is reached: works on a machine with no display.
    if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
        std::fputs("drivedesk " DRIVEDESK_VERSION "\n", stdout);
        return 0;
    }

    // --help too: the usage needs no window system. Anything else waits for QApplication,
    // which takes its own options (-platform, -style) out of the list first.
    QStringList given;
    for (int i = 0; i < argc; ++i)
        given << QString::fromLocal8Bit(argv[i]);
    if (DriveDesk::StartupOptions::parse(given).help) {
        std::fputs(qPrintable(DriveDesk::StartupOptions::usage()), stdout);
        return 0;
    }

    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DriveDesk"));
    QApplication::setApplicationName(QStringLiteral("DriveDesk"));
    QApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));
    // The installed desktop entry's name: Wayland compositors match the window to it by this id.
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.drivedesk.DriveDesk"));

    const auto options = DriveDesk::StartupOptions::parse(QApplication::arguments());
    if (options.help) {
        std::fputs(qPrintable(DriveDesk::StartupOptions::usage()), stdout);
        return 0;
    }
    if (!options.error.isEmpty()) {
        std::fprintf(stderr, "drivedesk: %s\n\n%s", qPrintable(options.error),
                     qPrintable(DriveDesk::StartupOptions::usage()));
        return 2;
    }

    // Before the window: its edits, downloads and journal view all open this one.
    DriveDesk::Journal::setDefaultPath(options.journalPath);

    const DriveDesk::Language language = options.uiLanguage();
    DriveDesk::installTranslations(DriveDesk::languageCode(language));
    QLocale::setDefault(
        QLocale(language == DriveDesk::Language::German ? QLocale::German : QLocale::English));

    DriveDesk::MainWindow window(language);
    window.show();
    if (!options.parameterFile.isEmpty()) {
        // A file it cannot read: it says why.
        window.feature<DriveDesk::ParameterFileFeature>()->openParameterFile(
            options.parameterFile);
    } else if (options.connection) {
        window.connectTo(*options.connection);
    } else {
        QTimer::singleShot(0, &window, &DriveDesk::MainWindow::openConnectionDialog);
    }
    return app.exec();
}
