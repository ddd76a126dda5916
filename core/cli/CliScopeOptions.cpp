// The scope command's options: they belong to scope alone, which needs --csv.
#include "CliScopeOptions.h"

#include "scope/ScopePreset.h"

#include <QCommandLineParser>

#include <algorithm>

namespace DriveDesk {

bool parseScopeOptions(const QCommandLineParser &parser, CliRequest &request, QString *error)
{
    const bool scope = request.command == CliRequest::Command::Scope;
    for (const char *name : {"channels", "duration", "rate", "csv", "offline", "preset"}) {
        if (!scope && parser.isSet(QLatin1String(name))) {
            *error = QStringLiteral("--%1 belongs to scope").arg(QLatin1String(name));
            return false;
        }
    }
    if (!scope)
        return true;
    request.csvFile = parser.value(QStringLiteral("csv"));
    if (request.csvFile.isEmpty()) {
        *error = QStringLiteral("scope needs --csv FILE: where to write what it records");
        return false;
    }
    request.offline = parser.isSet(QStringLiteral("offline"));
    if (request.offline) {
        for (const char *name : {"channels", "duration", "rate", "preset"}) {
            if (parser.isSet(QLatin1String(name))) {
                *error = QStringLiteral("--offline reads what the drive recorded: --%1 does not "
                                        "apply").arg(QLatin1String(name));
                return false;
            }
        }
    }
    if (parser.isSet(QStringLiteral("channels"))) {
        for (const QString &id : parser.value(QStringLiteral("channels")).split(QLatin1Char(',')))
            request.channels << id.trimmed();
        if (request.channels.size() > 4 || request.channels.contains(QString())) {
            *error = QStringLiteral("--channels takes one to four parameters, e.g. ru.3,ru.9");
            return false;
        }
    }
    // A preset gives the channels and the rate limit that --channels and --rate do not; its
    // trigger and looks are the window's. Read before anything reaches the drive.
    if (parser.isSet(QStringLiteral("preset"))) {
        const std::optional<ScopePreset> preset
            = ScopePresetFile::load(parser.value(QStringLiteral("preset")), error);
        if (!preset)
            return false;
        const bool anySource
            = std::any_of(preset->channels.begin(), preset->channels.end(),
                          [](const ScopePresetChannel &c) { return c.source.has_value(); });
        if (!parser.isSet(QStringLiteral("channels")) && anySource) {
            // An empty entry: the channel as the drive has it.
            for (const ScopePresetChannel &channel : preset->channels)
                request.channels << (channel.source ? channel.source->text() : QString());
        }
        if (!parser.isSet(QStringLiteral("rate")))
            request.rateHz = preset->rateLimitHz;
    }
    if (parser.isSet(QStringLiteral("duration"))) {
        const auto ms = parseDuration(parser.value(QStringLiteral("duration")), error);
        if (!ms)
            return false;
        request.durationMs = *ms;
    }
    if (parser.isSet(QStringLiteral("rate"))) {
        bool ok = false;
        request.rateHz = parser.value(QStringLiteral("rate")).toDouble(&ok);
        if (!ok || request.rateHz <= 0 || request.rateHz > 100000) {
            *error = QStringLiteral("--rate takes polls a second, more than 0 and at most 100000");
            return false;
        }
    }
    return true;
}

} // namespace DriveDesk
