// drivedesk-cli spectrum: the highest peaks of a channel's spectrum in a scope CSV export or a
// recording file, with no drive.
#include "CliSpectrum.h"

#include "CliFormatOption.h"

#include "link/ConnectionOptions.h"
#include "scope/ScopeCsvReader.h"
#include "scope/ScopeFileFormat.h"
#include "scope/ScopeFileReader.h"
#include "scope/ScopeRecording.h"
#include "scope/ScopeSpectrum.h"

#include <QCommandLineParser>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <cmath>
#include <memory>

namespace DriveDesk {

namespace {

// The context of the command's messages.
struct CliSpectrum
{
    Q_DECLARE_TR_FUNCTIONS(CliSpectrum)
};

// --from, --to: a number of ms, 0 or more.
bool parseMs(const QCommandLineParser &parser, const QString &name, std::optional<double> *ms,
             QString *error)
{
    if (!parser.isSet(name))
        return true;
    bool ok = false;
    const double value = parser.value(name).toDouble(&ok);
    if (!ok || !std::isfinite(value) || value < 0) {
        *error
            = QStringLiteral("--%1 takes ms from the recording's start, e.g. --%1 1500").arg(name);
        return false;
    }
    *ms = value;
    return true;
}

// "ru.03" and "ru.3" alike: the number after the point without leading zeros, lower case.
QString normalisedId(const QString &id)
{
    static const QRegularExpression pattern(QStringLiteral("^([A-Za-z]+)\\.0*([0-9]+)$"));
    const QRegularExpressionMatch match = pattern.match(id);
    return match.hasMatch() ? match.captured(1).toLower() + QLatin1Char('.') + match.captured(2)
                            : id.toLower();
}

// A channel the file holds: its number (a recording's channel 1..4, a CSV's column after the
// time), title and unit.
struct Channel
{
    int number = 0;
    QString title;
    QString unit;
};

// The channel `name` means: its number, its title, or the id its title starts with. -1 when
// none does; -2 when the id fits several (the same parameter from two sets).
qsizetype findChannel(const QList<Channel> &channels, const QString &name)
{
    if (name.isEmpty())
        return channels.isEmpty() ? -1 : 0;
    bool isNumber = false;
    const int number = name.toInt(&isNumber);
    qsizetype byId = -1;
    int idMatches = 0;
    for (qsizetype i = 0; i < channels.size(); ++i) {
        const Channel &channel = channels.at(i);
        if ((isNumber && channel.number == number)
            || channel.title.compare(name, Qt::CaseInsensitive) == 0)
            return i;
        const QString id = channel.title.section(QLatin1Char(' '), 0, 0);
        if (id.contains(QLatin1Char('.')) && normalisedId(id) == normalisedId(name)) {
            byId = i;
            ++idMatches;
        }
    }
    return idMatches > 1 ? -2 : byId;
}

QString channelList(const QList<Channel> &channels)
{
    QStringList names;
    for (const Channel &channel : channels)
        names << QStringLiteral("%1 (%2)").arg(channel.title).arg(channel.number);
    return names.join(QStringLiteral(", "));
}

// Enough decimals to tell neighbouring bins apart, and one more.
int frequencyDecimals(double binHz)
{
    return std::clamp(int(std::ceil(-std::log10(binHz))) + 1, 0, 6);
}

QString table(const ScopeSpectrum &spectrum, const QString &file, double originMs)
{
    const QString label = spectrum.unit.isEmpty()
        ? spectrum.title
        : QStringLiteral("%1 [%2]").arg(spectrum.title, spectrum.unit);
    QString text = CliSpectrum::tr("%1 in '%2', %3 to %4 ms")
                       .arg(label, file)
                       .arg(spectrum.fromMs - originMs)
                       .arg(spectrum.toMs - originMs)
        + QLatin1Char('\n');
    text += CliSpectrum::tr("%1 samples at %2 Hz, %3 Hz a bin")
                .arg(spectrum.samples)
                .arg(spectrum.sampleRateHz, 0, 'g', 6)
                .arg(spectrum.binHz, 0, 'g', 4);
    if (spectrum.resampled)
        text += CliSpectrum::tr("; they came unevenly and were resampled to even spacing");
    text += QStringLiteral("\n\n");
    if (spectrum.peaks.isEmpty())
        return text + CliSpectrum::tr("no peaks: the channel is flat in the window")
            + QLatin1Char('\n');

    const QString frequency = CliSpectrum::tr("frequency [Hz]");
    const QString amplitude = spectrum.unit.isEmpty()
        ? CliSpectrum::tr("amplitude")
        : CliSpectrum::tr("amplitude [%1]").arg(spectrum.unit);
    QList<QStringList> rows { { frequency, amplitude } };
    const int decimals = frequencyDecimals(spectrum.binHz);
    // Five digits of the highest peak, the others to the same decimal.
    const double highest = spectrum.peaks.constFirst().amplitude;
    const int amplitudeDecimals
        = highest > 0 ? std::clamp(4 - int(std::floor(std::log10(highest))), 0, 9) : 4;
    for (const ScopeSpectrumPeak &peak : spectrum.peaks)
        rows << QStringList { QString::number(peak.frequencyHz, 'f', decimals),
                              QString::number(peak.amplitude, 'f', amplitudeDecimals) };
    qsizetype width[2] = { 0, 0 };
    for (const QStringList &row : rows) {
        width[0] = std::max(width[0], row[0].size());
        width[1] = std::max(width[1], row[1].size());
    }
    for (const QStringList &row : rows)
        text += row[0].rightJustified(width[0]) + QStringLiteral("  ")
            + row[1].rightJustified(width[1]) + QLatin1Char('\n');
    return text;
}

QString json(const ScopeSpectrum &spectrum, const QString &file, double originMs)
{
    QJsonArray peaks;
    for (const ScopeSpectrumPeak &peak : spectrum.peaks)
        peaks.append(QJsonObject { { QStringLiteral("frequencyHz"), peak.frequencyHz },
                                   { QStringLiteral("amplitude"), peak.amplitude } });
    const QJsonObject root { { QStringLiteral("file"), file },
                             { QStringLiteral("channel"), spectrum.title },
                             { QStringLiteral("unit"), spectrum.unit },
                             { QStringLiteral("fromMs"), spectrum.fromMs - originMs },
                             { QStringLiteral("toMs"), spectrum.toMs - originMs },
                             { QStringLiteral("samples"), spectrum.samples },
                             { QStringLiteral("points"), spectrum.points },
                             { QStringLiteral("sampleRateHz"), spectrum.sampleRateHz },
                             { QStringLiteral("binHz"), spectrum.binHz },
                             { QStringLiteral("resampled"), spectrum.resampled },
                             { QStringLiteral("peaks"), peaks } };
    return QString::fromUtf8(QJsonDocument(root).toJson(QJsonDocument::Indented));
}

bool isRecordingFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly)
        && file.read(qint64(sizeof ScopeFileFormat::kMagic - 1)) == ScopeFileFormat::kMagic;
}

} // namespace

std::optional<CliRequest> parseSpectrumCommand(const QCommandLineParser &parser,
                                               const ConnectionOptions &connection,
                                               const QStringList &positional, QString *error)
{
    if (!refuseDriveOptions(parser, connection, QStringLiteral("spectrum"),
                            QStringLiteral("reads a file"), error))
        return std::nullopt;
    if (positional.size() != 2) {
        *error = QStringLiteral("spectrum takes a scope CSV export or recording file, e.g. "
                                "spectrum trace.csv");
        return std::nullopt;
    }
    CliRequest request;
    request.command = CliRequest::Command::Spectrum;
    SpectrumRequest &spectrum = request.spectrum;
    spectrum.file = positional.at(1);
    spectrum.channel = parser.value(QStringLiteral("channel")).trimmed();
    if (parser.isSet(QStringLiteral("channel")) && spectrum.channel.isEmpty()) {
        *error = QStringLiteral("--channel takes a channel's id, title or number, e.g. ru.3");
        return std::nullopt;
    }
    if (!parseMs(parser, QStringLiteral("from"), &spectrum.fromMs, error)
        || !parseMs(parser, QStringLiteral("to"), &spectrum.toMs, error))
        return std::nullopt;
    if (spectrum.fromMs && spectrum.toMs && *spectrum.fromMs >= *spectrum.toMs) {
        *error = QStringLiteral("--from must come before --to");
        return std::nullopt;
    }
    if (!ConnectionOptions::integer(
            parser, QCommandLineOption(QStringLiteral("peaks"), {}, QStringLiteral("n")), 1, 1000,
            &spectrum.peaks, error))
        return std::nullopt;
    if (!parseFormatOption(parser, QStringLiteral("spectrum"),
                           { QStringLiteral("json"), QStringLiteral("table") }, &request, error))
        return std::nullopt;
    std::optional<Language> language;
    if (!connection.language(parser, &language, error))
        return std::nullopt;
    if (language)
        request.connection.language = *language;
    request.quiet = parser.isSet(QStringLiteral("quiet"));
    return request;
}

int runSpectrumCommand(const CliRequest &request, QTextStream &out, QTextStream &err)
{
    const SpectrumRequest &asked = request.spectrum;
    const auto fail = [&err](const QString &message) {
        err << QStringLiteral("drivedesk-cli: ") << message << Qt::endl;
        return 2;
    };
    // The file's channels; a recording file's read in place, a CSV's columns as series.
    QList<Channel> channels;
    std::unique_ptr<ScopeRecording> recording;
    QList<ScopeSeries> columns;
    double firstMs = 0; // the file's time axis: ms from the recording's first sample
    double lastMs = 0;
    double originMs = 0; // a recording's own time at its first sample
    QString error;
    if (isRecordingFile(asked.file)) {
        recording = std::make_unique<ScopeRecording>();
        QStringList warnings;
        if (!readScopeFile(asked.file, *recording, &error, &warnings))
            return fail(error);
        for (const QString &warning : std::as_const(warnings))
            err << warning << Qt::endl;
        for (const int channel : recording->recordedChannels()) {
            const ScopeChannel &described = recording->channels.at(channel);
            channels << Channel { channel + 1, described.title(channel), described.unit() };
        }
        originMs = double(recording->firstTime());
        lastMs = double(recording->lastTime() - recording->firstTime());
        if (recording->buffer.count() == 0)
            return fail(CliSpectrum::tr("'%1' holds no samples").arg(asked.file));
    } else {
        if (!readScopeCsv(asked.file, columns, &error))
            return fail(error);
        firstMs = std::numeric_limits<double>::infinity();
        lastMs = -std::numeric_limits<double>::infinity();
        for (qsizetype i = 0; i < columns.size(); ++i) {
            const ScopeSeries &column = columns.at(i);
            channels << Channel { int(i + 1), column.title, column.unit };
            if (!column.isEmpty()) {
                firstMs = std::min(firstMs, column.timeMs.front());
                lastMs = std::max(lastMs, column.timeMs.back());
            }
        }
        if (firstMs > lastMs)
            return fail(CliSpectrum::tr("'%1' holds no samples").arg(asked.file));
    }

    const qsizetype found = findChannel(channels, asked.channel);
    if (found == -2) {
        return fail(CliSpectrum::tr("'%1' fits several channels of '%2': give its title or "
                                    "number (%3)")
                        .arg(asked.channel, asked.file, channelList(channels)));
    }
    if (found < 0) {
        return fail(CliSpectrum::tr("'%1' has no channel '%2'; it holds %3")
                        .arg(asked.file, asked.channel, channelList(channels)));
    }
    for (const auto &[option, ms] :
         { std::pair { "--from", asked.fromMs }, std::pair { "--to", asked.toMs } }) {
        if (ms && (*ms < firstMs || *ms > lastMs)) {
            return fail(CliSpectrum::tr("%1 %2 ms is outside the recording in '%3' (%4 to %5 ms)")
                            .arg(QLatin1String(option))
                            .arg(*ms)
                            .arg(asked.file)
                            .arg(firstMs)
                            .arg(lastMs));
        }
    }

    ScopeSpectrumOptions options;
    options.fromMs = originMs + asked.fromMs.value_or(firstMs);
    options.toMs = originMs + asked.toMs.value_or(lastMs);
    options.peaks = asked.peaks;
    const Channel &channel = channels.at(found);
    const std::optional<ScopeSpectrum> spectrum = recording
        ? computeScopeSpectrum(*recording, channel.number - 1, options, &error)
        : computeScopeSpectrum(columns.at(found), options, &error);
    if (!spectrum)
        return fail(QStringLiteral("'%1', %2: %3").arg(asked.file, channel.title, error));
    out << (request.format == CliRequest::Format::Json ? json(*spectrum, asked.file, originMs)
                                                       : table(*spectrum, asked.file, originMs));
    out.flush();
    return 0;
}

} // namespace DriveDesk
