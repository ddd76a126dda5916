#include "StartupOptions.h"

#include "protocol/Codec.h"

#include <QCommandLineParser>
#include <QLocale>
#include <QSettings>

namespace DriveDesk {

QString StartupOptions::usage()
{
    return StartupText::tr(
        "Usage: drivedesk [--connect TARGET] [options]\n"
        "\n"
        "The DriveDesk parameter editor. Without --connect it opens the connection dialog.\n"
        "\n"
        "  --connect TARGET     tcp:HOST:PORT, serial:DEVICE or sim (the simulated drive)\n"
        "  --protocol NAME      hsp5 (default), din66019ii or din66019\n"
        "  --address N          drive address on a DIN66019(II) bus, 0..239 (default 1)\n"
        "  --baud N             baud rate (default 38400)\n"
        "  --language en|de     language of the window and of the drive's texts\n");
}

Language StartupOptions::uiLanguage() const
{
    if (language)
        return *language;
    const QString chosen = QSettings().value(QStringLiteral("language")).toString();
    if (chosen == QLatin1String("de"))
        return Language::German;
    if (chosen == QLatin1String("en"))
        return Language::English;
    return QLocale::system().language() == QLocale::German ? Language::German : Language::English;
}

StartupOptions StartupOptions::parse(const QStringList &arguments)
{
    StartupOptions options;
    QCommandLineParser parser;
    const QCommandLineOption help({ QStringLiteral("h"), QStringLiteral("help") },
                                  QStringLiteral("help"));
    const QCommandLineOption connect(QStringLiteral("connect"), {}, QStringLiteral("target"));
    const QCommandLineOption protocol(QStringLiteral("protocol"), {}, QStringLiteral("name"));
    const QCommandLineOption address(QStringLiteral("address"), {}, QStringLiteral("n"));
    const QCommandLineOption baud(QStringLiteral("baud"), {}, QStringLiteral("n"));
    const QCommandLineOption language(QStringLiteral("language"), {}, QStringLiteral("lang"));
    parser.addOptions({ help, connect, protocol, address, baud, language });
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
    if (parser.isSet(language)) {
        const QString lang = parser.value(language).toLower();
        if (lang == QLatin1String("en")) {
            options.language = Language::English;
        } else if (lang == QLatin1String("de")) {
            options.language = Language::German;
        } else {
            options.error = StartupText::tr("unknown language \"%1\": use en or de").arg(lang);
            return options;
        }
    }

    const bool connectionOption
        = parser.isSet(protocol) || parser.isSet(address) || parser.isSet(baud);
    if (!parser.isSet(connect)) {
        if (connectionOption) {
            options.error = StartupText::tr(
                "--protocol, --address and --baud belong to --connect: give tcp:HOST:PORT, "
                "serial:DEVICE or sim");
        }
        return options;
    }
    ConnectionSettings settings;
    if (!settings.parseTarget(parser.value(connect), &options.error))
        return options;
    if (parser.isSet(protocol)) {
        const auto p = protocolFromName(parser.value(protocol));
        if (!p) {
            options.error
                = StartupText::tr("unknown protocol \"%1\": use hsp5, din66019ii or din66019")
                      .arg(parser.value(protocol));
            return options;
        }
        settings.protocol = *p;
    }
    auto integer = [&](const QCommandLineOption &option, int low, int high, int *out) {
        if (!parser.isSet(option))
            return true;
        bool ok = false;
        const int n = parser.value(option).toInt(&ok);
        if (!ok || n < low || n > high) {
            options.error = StartupText::tr("--%1 %2: expected a number from %3 to %4")
                                .arg(option.names().constFirst(), parser.value(option))
                                .arg(low)
                                .arg(high);
            return false;
        }
        *out = n;
        return true;
    };
    int baudRate = settings.baudRate;
    if (!integer(address, 0, 239, &settings.driveAddress) || !integer(baud, 50, 4000000, &baudRate))
        return options;
    settings.baudRate = baudRate;
    settings.simulation.driveAddresses = { settings.driveAddress };
    settings.simulation.baudRate = baudRate;
    if (options.language)
        settings.language = *options.language;
    options.connection = settings;
    return options;
}

} // namespace DriveDesk
