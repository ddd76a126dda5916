// drivedesk: the parameter editor's window, connected to the drive the command line names or
// opening the connection dialog.
#include "main/MainWindow.h"
#include "main/StartupOptions.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTimer>
#include <QTranslator>

#include <cstdio>

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DriveDesk"));
    QApplication::setApplicationName(QStringLiteral("DriveDesk"));
    QApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));

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

    const DriveDesk::Language language = options.uiLanguage();
    const bool german = language == DriveDesk::Language::German;
    // Qt's own dialogs and buttons, then ours; English has a catalogue too, for its plurals.
    QTranslator qtTranslator;
    if (german
        && qtTranslator.load(QLocale(QLocale::German), QStringLiteral("qtbase"),
                             QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);
    QTranslator translator;
    if (translator.load(german ? QStringLiteral(":/i18n/drivedesk_de.qm")
                               : QStringLiteral(":/i18n/drivedesk_en.qm")))
        QApplication::installTranslator(&translator);
    QLocale::setDefault(QLocale(german ? QLocale::German : QLocale::English));

    DriveDesk::MainWindow window(language);
    window.show();
    if (options.connection)
        window.connectTo(*options.connection);
    else
        QTimer::singleShot(0, &window, &DriveDesk::MainWindow::openConnectionDialog);
    return app.exec();
}
