#include "ScopePreset.h"

#include "parameters/DriveDescription.h"
#include "parameters/JsonObjectReader.h"
#include "parameters/JsonTextPlaces.h"
#include "parameters/ParameterId.h"
#include "parameters/SavedFile.h"
#include "parameters/WholeFile.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QRegularExpression>

#include <cmath>
#include <limits>

// toJson() writes the preset file, fromJson() reads and checks it.

namespace DriveDesk {

const QString ScopePresetFile::kFormat = QStringLiteral("drivedesk-scope-preset");

namespace {

const QString kOff = QStringLiteral("off");
constexpr int kMaxNameLength = 100;

std::optional<double> readNumber(JsonObjectReader &reader, const QString &key, double minimum,
                                 double maximum)
{
    const QJsonValue json = reader.value(key);
    if (!reader.ok())
        return std::nullopt;
    const double number = json.toDouble();
    if (!json.isDouble() || !std::isfinite(number)) {
        reader.fail(reader.place(key), ScopePresetFile::tr("expected a number"));
        return std::nullopt;
    }
    if (number < minimum || number > maximum) {
        reader.fail(reader.place(key),
                    ScopePresetFile::tr("%1 is outside %2..%3").arg(number).arg(minimum).arg(maximum));
        return std::nullopt;
    }
    return number;
}

bool readHeader(JsonObjectReader &root)
{
    const QString formatKey = QStringLiteral("format");
    const QJsonValue format = root.value(formatKey);
    if (root.ok() && format.toString() != ScopePresetFile::kFormat)
        root.fail(formatKey,
                  ScopePresetFile::tr("%1, expected '%2': not a DriveDesk scope preset")
                      .arg(format.isString() ? QStringLiteral("'%1'").arg(format.toString())
                                             : ScopePresetFile::tr("not a string"),
                           ScopePresetFile::kFormat));
    if (!root.ok())
        return false;
    const QString versionKey = QStringLiteral("version");
    const qint64 version = root.integer(versionKey, 1, std::numeric_limits<int>::max());
    if (root.ok() && version > ScopePresetFile::kVersion)
        root.fail(versionKey,
                  ScopePresetFile::tr("%1 is a newer format than this DriveDesk reads (version "
                                      "%2); a newer DriveDesk reads it")
                      .arg(version)
                      .arg(ScopePresetFile::kVersion));
    return root.ok();
}

ScopePresetChannel readPresetChannel(JsonObjectReader &reader)
{
    ScopePresetChannel channel;
    const QString sourceKey = QStringLiteral("source");
    const QJsonValue source = reader.value(sourceKey);
    if (reader.ok() && !source.isNull()) {
        QString why;
        if (!source.isString())
            reader.fail(reader.place(sourceKey),
                        ScopePresetFile::tr("expected a parameter id, \"off\" or null"));
        else if (!(channel.source = ScopeSourceText::parse(source.toString(), &why)))
            reader.fail(reader.place(sourceKey), why);
    }
    const QString colorKey = QStringLiteral("color");
    if (reader.has(colorKey)) {
        channel.color = reader.string(colorKey);
        static const QRegularExpression rgb(QStringLiteral("^#[0-9A-Fa-f]{6}$"));
        if (reader.ok() && !rgb.match(channel.color).hasMatch())
            reader.fail(reader.place(colorKey),
                        ScopePresetFile::tr("'%1' is not a colour: write it as #rrggbb")
                            .arg(channel.color));
    }
    channel.visible = reader.boolean(QStringLiteral("visible"));
    channel.ownAxis = reader.boolean(QStringLiteral("ownAxis"));
    reader.finish();
    return channel;
}

ScopeTriggerSettings readTrigger(JsonObjectReader &reader)
{
    ScopeTriggerSettings trigger;
    trigger.channel = int(reader.integer(QStringLiteral("channel"), 1,
                                         ScopeSample::kChannelCount)) - 1;
    const QString edgeKey = QStringLiteral("edge");
    const QString edge = reader.string(edgeKey);
    if (edge == QLatin1String("falling"))
        trigger.edge = ScopeTriggerSettings::Edge::Falling;
    else if (reader.ok() && edge != QLatin1String("rising"))
        reader.fail(reader.place(edgeKey),
                    ScopePresetFile::tr("'%1': expected rising or falling").arg(edge));
    trigger.level = readNumber(reader, QStringLiteral("level"), -ScopePresetFile::kMaxTriggerLevel,
                               ScopePresetFile::kMaxTriggerLevel)
                        .value_or(0.0);
    trigger.preTriggerShare = readNumber(reader, QStringLiteral("preTrigger"), 0.0, 1.0).value_or(0.0);
    trigger.windowMs = reader.integer(QStringLiteral("shotMs"), ScopePresetFile::kMinShotMs,
                                      ScopePresetFile::kMaxShotMs);
    reader.finish();
    return trigger;
}

// "channels[2].source" as a user counts channels: "channel 3's source".
QString channelSubject(const QString &place)
{
    static const QRegularExpression pattern(QStringLiteral("^channels\\[(\\d+)\\](?:\\.(.+))?$"));
    const QRegularExpressionMatch match = pattern.match(place);
    if (!match.hasMatch())
        return {};
    const int channel = match.captured(1).toInt() + 1;
    return match.captured(2).isEmpty()
        ? ScopePresetFile::tr("channel %1").arg(channel)
        : ScopePresetFile::tr("channel %1's %2").arg(channel).arg(match.captured(2));
}

} // namespace

QString ScopeSourceText::text() const
{
    if (isOff())
        return kOff;
    return set == 0 ? id : QStringLiteral("%1@%2").arg(id).arg(set);
}

std::optional<ScopeSourceText> ScopeSourceText::parse(const QString &input, QString *error)
{
    const QString text = input.trimmed();
    if (text.compare(kOff, Qt::CaseInsensitive) == 0)
        return ScopeSourceText{};
    const qsizetype at = text.indexOf(QLatin1Char('@'));
    ScopeSourceText source{text.left(at).trimmed(), 0};
    const auto fail = [error](const QString &message) -> std::optional<ScopeSourceText> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    if (!ParameterId::isWellFormed(source.id))
        return fail(ScopePresetFile::tr("'%1' is not a parameter id: write it as group.number "
                                        "(ru.03), a hexadecimal address (0203h), with @set "
                                        "where it is read from another set (op.11@2), or off")
                        .arg(text));
    if (at >= 0) {
        bool ok = false;
        source.set = text.mid(at + 1).trimmed().toInt(&ok);
        if (!ok || source.set < 0 || source.set >= kParameterSets)
            return fail(ScopePresetFile::tr("'%1': the set after @ is 0..%2, e.g. op.11@2")
                            .arg(text)
                            .arg(kParameterSets - 1));
    }
    return source;
}

bool ScopePresetChannel::operator==(const ScopePresetChannel &other) const
{
    const auto sourceText = [](const std::optional<ScopeSourceText> &source) {
        return source ? source->text() : QString();
    };
    return sourceText(source) == sourceText(other.source) && color == other.color
        && visible == other.visible && ownAxis == other.ownAxis;
}

bool ScopePreset::operator==(const ScopePreset &other) const
{
    return name == other.name && driveKind == other.driveKind && channels == other.channels
        && trigger == other.trigger && rollSeconds == other.rollSeconds
        && rateLimitHz == other.rateLimitHz;
}

QByteArray ScopePresetFile::toJson(const ScopePreset &preset)
{
    QJsonArray channels;
    for (const ScopePresetChannel &channel : preset.channels) {
        QJsonObject object{
            {QStringLiteral("source"),
             channel.source ? QJsonValue(channel.source->text()) : QJsonValue()},
            {QStringLiteral("visible"), channel.visible},
            {QStringLiteral("ownAxis"), channel.ownAxis},
        };
        if (!channel.color.isEmpty())
            object.insert(QStringLiteral("color"), channel.color);
        channels.append(object);
    }
    const ScopeTriggerSettings &trigger = preset.trigger;
    const QJsonObject root{
        {QStringLiteral("format"), kFormat},
        {QStringLiteral("version"), kVersion},
        {QStringLiteral("name"), preset.name},
        {QStringLiteral("driveKind"), preset.driveKind},
        {QStringLiteral("channels"), channels},
        {QStringLiteral("trigger"),
         QJsonObject{
             {QStringLiteral("channel"), trigger.channel + 1},
             {QStringLiteral("edge"),
              trigger.edge == ScopeTriggerSettings::Edge::Falling ? QStringLiteral("falling")
                                                                  : QStringLiteral("rising")},
             {QStringLiteral("level"), trigger.level},
             {QStringLiteral("preTrigger"), trigger.preTriggerShare},
             {QStringLiteral("shotMs"), trigger.windowMs},
         }},
        {QStringLiteral("rollSeconds"), preset.rollSeconds},
        {QStringLiteral("rateLimitHz"), preset.rateLimitHz},
    };
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<ScopePreset> ScopePresetFile::fromJson(const QByteArray &json, QString *error)
{
    const auto fail = [&](const QString &message, qsizetype offset) -> std::optional<ScopePreset> {
        const JsonTextPlaces::LineColumn at = JsonTextPlaces::lineColumn(json, offset);
        if (error)
            *error = tr("%1 (line %2, column %3)").arg(message).arg(at.line).arg(at.column);
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(tr("not JSON: %1").arg(parseError.errorString()), parseError.offset);
    if (!document.isObject())
        return fail(tr("not a DriveDesk scope preset: the document is not a JSON object"), 0);
    if (const auto duplicate = JsonTextPlaces::firstDuplicateKey(json))
        return fail(tr("%1: appears twice in one object").arg(duplicate->path), duplicate->offset);

    JsonFault fault;
    JsonObjectReader root(document.object(), QString(), &fault);
    ScopePreset preset;
    if (readHeader(root)) {
        const QString nameKey = QStringLiteral("name");
        preset.name = root.string(nameKey).trimmed();
        if (root.ok() && (preset.name.isEmpty() || preset.name.size() > kMaxNameLength))
            root.fail(nameKey, tr("give the preset a name of 1 to %1 characters").arg(kMaxNameLength));
        preset.driveKind = root.string(QStringLiteral("driveKind"));
        const QString channelsKey = QStringLiteral("channels");
        const QJsonArray channels = root.array(channelsKey);
        if (root.ok() && channels.size() != ScopeSample::kChannelCount)
            root.fail(channelsKey, tr("expected %1 channels, found %2")
                                       .arg(ScopeSample::kChannelCount)
                                       .arg(channels.size()));
        for (qsizetype i = 0; i < channels.size() && root.ok(); ++i) {
            JsonObjectReader reader = root.element(channelsKey, channels, i);
            if (reader.ok())
                preset.channels[std::size_t(i)] = readPresetChannel(reader);
        }
        const QString triggerKey = QStringLiteral("trigger");
        const QJsonObject trigger = root.object(triggerKey);
        if (root.ok()) {
            JsonObjectReader reader(trigger, triggerKey, &fault);
            preset.trigger = readTrigger(reader);
        }
        preset.rollSeconds = readNumber(root, QStringLiteral("rollSeconds"), kMinRollSeconds,
                                        kMaxRollSeconds)
                                 .value_or(0.0);
        preset.rateLimitHz = int(root.integer(QStringLiteral("rateLimitHz"), 0, kMaxRateLimitHz));
        root.finish();
    }
    if (!root.ok()) {
        if (fault.subject.isEmpty())
            fault.subject = channelSubject(fault.place);
        return fail(fault.text(), JsonTextPlaces::offsetOf(json, fault.place));
    }
    return preset;
}

bool ScopePresetFile::save(const QString &path, const ScopePreset &preset, QString *error)
{
    return SavedFile::write(path, toJson(preset), error);
}

std::optional<ScopePreset> ScopePresetFile::load(const QString &path, QString *error)
{
    // WholeFile's reasons name the file already.
    const std::optional<QByteArray> json = WholeFile::read(path, kMaxFileSize, error);
    if (!json)
        return std::nullopt;
    QString reason;
    std::optional<ScopePreset> preset = fromJson(*json, &reason);
    if (!preset && error)
        *error = tr("preset file '%1': %2").arg(path, reason);
    return preset;
}

} // namespace DriveDesk
