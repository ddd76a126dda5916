// drivedesk: the parameter editor's window, connected to the drive the command line names or
// opening the connection dialog.
#include "main/MainWindow.h"
#include "main/StartupOptions.h"

#include <QApplication>
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
    QTranslator translator;
    // Without the German catalogue the window stays English; the drive's texts are German still.
    if (language == DriveDesk::Language::German
        && translator.load(QStringLiteral(":/i18n/drivedesk_de.qm")))
        QApplication::installTranslator(&translator);

    DriveDesk::MainWindow window(language);
    window.show();
    if (options.connection)
        window.connectTo(*options.connection);
    else
        QTimer::singleShot(0, &window, &DriveDesk::MainWindow::openConnectionDialog);
    return app.exec();
}
