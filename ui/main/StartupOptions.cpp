#include "StartupOptions.h"

#include "link/ConnectionOptions.h"

#include <QCommandLineParser>
#include <QLocale>
#include <QSettings>

namespace DriveDesk {

QString StartupOptions::usage()
{
    return StartupText::tr(
        "Usage: drivedesk [--connect TARGET | --open FILE] [options]\n"
        "\n"
        "The DriveDesk parameter editor. Without --connect or --open it opens the connection\n"
        "dialog.\n"
        "\n"
        "  --connect TARGET     tcp:HOST:PORT, serial:DEVICE or sim (the simulated drive)\n"
        "  --open FILE          show and edit a parameter file with no drive\n"
        "  --protocol NAME      hsp5 (default), din66019ii or din66019\n"
        "  --address N          drive address on a DIN66019(II) bus, 0..239 (default 1)\n"
        "  --baud N|auto        baud rate; auto (the default on a serial line) finds the rate\n"
        "                       the drive answers at\n"
        "  --language en|de     language of the window and of the drive's texts\n"
        "  --journal PATH       the journal of the values written, instead of\n"
        "                       ~/.local/share/DriveDesk/journal.sqlite\n");
}

Language StartupOptions::uiLanguage() const
{
    if (language)
        return *language;
    if (const std::optional<Language> chosen
        = languageFromCode(QSettings().value(QStringLiteral("language")).toString()))
        return *chosen;
    return QLocale::system().language() == QLocale::German ? Language::German : Language::English;
}

StartupOptions StartupOptions::parse(const QStringList &arguments)
{
    StartupOptions options;
    QCommandLineParser parser;
    const QCommandLineOption help({ QStringLiteral("h"), QStringLiteral("help") },
                                  QStringLiteral("help"));
    const QCommandLineOption open(QStringLiteral("open"), QStringLiteral("parameter file"),
                                  QStringLiteral("FILE"));
    const QCommandLineOption journal(QStringLiteral("journal"), QStringLiteral("journal"),
                                     QStringLiteral("PATH"));
    const ConnectionOptions connection;
    connection.addTo(parser);
    parser.addOption(open);
    parser.addOption(journal);
    parser.addOption(help);
    if (!parser.parse(arguments)) {
        options.error = parser.errorText();
        return options;
    }
    if (parser.isSet(help)) {
        options.help = true;
        return options;
    }
    if (!parser.positionalArguments().isEmpty()) {
        options.error = StartupText::tr("unexpected argument \"%1\"")
                            .arg(parser.positionalArguments().constFirst());
        return options;
    }
    if (!connection.language(parser, &options.language, &options.error))
        return options;
    if (parser.isSet(journal)) {
        options.journalPath = parser.value(journal);
        if (options.journalPath.isEmpty()) {
            options.error = StartupText::tr("--journal names a file: give a path");
            return options;
        }
    }
    if (parser.isSet(open)) {
        if (connection.hasTarget(parser) || connection.hasTargetDetails(parser)) {
            options.error = StartupText::tr(
                "--open shows a parameter file with no drive: leave out --connect, --protocol, "
                "--address and --baud");
            return options;
        }
        options.parameterFile = parser.value(open);
        return options;
    }
    if (!connection.hasTarget(parser)) {
        if (connection.hasTargetDetails(parser)) {
            options.error = StartupText::tr(
                "--protocol, --address and --baud belong to --connect: give tcp:HOST:PORT, "
                "serial:DEVICE or sim");
        }
        return options;
    }
    ConnectionSettings settings;
    if (!connection.settings(parser, &settings, &options.error))
        return options;
    options.connection = settings;
    return options;
}

} // namespace DriveDesk
