#include "ScopeFileFormat.h"

#include "ScopeRecording.h"
#include "parameters/JsonObjectReader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

#include <limits>

namespace DriveDesk {

namespace {

QJsonObject channelJson(const ScopeChannel &channel)
{
    const DisplayScalingData &scaling = channel.scaling.data();
    return QJsonObject {
        { QStringLiteral("source"), channel.source ? QJsonValue(*channel.source) : QJsonValue() },
        { QStringLiteral("setMask"), channel.setMask },
        { QStringLiteral("enabled"), channel.enabled },
        { QStringLiteral("id"), channel.id },
        { QStringLiteral("name"), channel.name },
        { QStringLiteral("scaling"),
          QJsonObject {
              { QStringLiteral("address"), scaling.address },
              { QStringLiteral("divisor"), scaling.divisor },
              { QStringLiteral("multiplier"), scaling.multiplier },
              { QStringLiteral("offset"), scaling.offset },
              { QStringLiteral("flags"), scaling.flags },
          } },
    };
}

ScopeChannel readChannel(JsonObjectReader &reader)
{
    ScopeChannel channel;
    const QString sourceKey = QStringLiteral("source");
    const QJsonValue source = reader.value(sourceKey);
    if (reader.ok() && !source.isNull()) {
        if (const auto address = reader.checkedInteger(source, reader.place(sourceKey), 0, 0xFFFF))
            channel.source = quint16(*address);
    }
    channel.setMask = quint8(reader.integer(QStringLiteral("setMask"), 0, 0xFF));
    channel.enabled = reader.boolean(QStringLiteral("enabled"));
    channel.id = reader.string(QStringLiteral("id"));
    channel.name = reader.string(QStringLiteral("name"));

    JsonObjectReader scaling(reader.object(QStringLiteral("scaling")),
                             reader.place(QStringLiteral("scaling")), reader.error());
    DisplayScalingData data;
    data.address = quint16(scaling.integer(QStringLiteral("address"), 0, 0xFFFF));
    data.divisor = qint16(scaling.integer(QStringLiteral("divisor"), -32768, 32767));
    data.multiplier = qint16(scaling.integer(QStringLiteral("multiplier"), -32768, 32767));
    data.offset = qint16(scaling.integer(QStringLiteral("offset"), -32768, 32767));
    data.flags = quint16(scaling.integer(QStringLiteral("flags"), 0, 0xFFFF));
    scaling.finish();
    channel.scaling = DisplayScaling(data);
    reader.finish();
    return channel;
}

} // namespace

ScopeFileHeader ScopeFileHeader::of(const ScopeRecording &recording)
{
    return { recording.started, recording.source, recording.channels, recording.math,
             recording.triggerMs };
}

QByteArray ScopeFileFormat::start(const ScopeFileHeader &header)
{
    Q_ASSERT(header.channels.size() == ScopeSample::kChannelCount); // the reader insists
    QJsonArray channels;
    for (const ScopeChannel &channel : header.channels)
        channels.append(channelJson(channel));
    const QJsonValue started = header.started.isValid()
        ? QJsonValue(header.started.toUTC().toString(Qt::ISODateWithMs))
        : QJsonValue();
    QJsonObject object {
        { QStringLiteral("started"), started },
        { QStringLiteral("source"), header.source },
        { QStringLiteral("channels"), channels },
    };
    // Only where there are some: a file without math channels stays one that earlier versions
    // of DriveDesk read.
    if (!header.math.isEmpty()) {
        QJsonArray math;
        for (const ScopeMathDefinition &definition : header.math)
            math.append(definition.toJson());
        object.insert(QStringLiteral("math"), math);
    }
    if (header.triggerMs)
        object.insert(QStringLiteral("trigger"), QJsonValue(*header.triggerMs));
    const QByteArray json = QJsonDocument(object).toJson(QJsonDocument::Compact);

    QByteArray bytes = kMagic + QByteArray::number(kVersion) + '\n';
    const qsizetype lengthAt = bytes.size();
    bytes.resize(lengthAt + 4);
    qToLittleEndian(quint32(json.size()), bytes.data() + lengthAt);
    return bytes + json;
}

bool ScopeFileFormat::parseHeader(const QByteArray &json, ScopeFileHeader &header, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !document.isObject()) {
        if (error)
            *error = document.isNull() ? tr("not JSON (%1 at byte %2)")
                                             .arg(parseError.errorString())
                                             .arg(parseError.offset)
                                       : tr("not a JSON object");
        return false;
    }
    JsonFault fault;
    JsonObjectReader reader(document.object(), QString(), &fault);

    const QString startedKey = QStringLiteral("started");
    const QJsonValue started = reader.value(startedKey);
    if (reader.ok() && !started.isNull()) {
        header.started = QDateTime::fromString(started.toString(), Qt::ISODateWithMs).toUTC();
        if (!started.isString() || !header.started.isValid())
            reader.fail(startedKey, tr("expected a date and time (ISO 8601) or null"));
    }
    header.source = reader.string(QStringLiteral("source"));

    const QString channelsKey = QStringLiteral("channels");
    const QJsonArray channels = reader.array(channelsKey);
    if (reader.ok() && channels.size() != ScopeSample::kChannelCount)
        reader.fail(channelsKey,
                    tr("expected %1 channels, found %2")
                        .arg(ScopeSample::kChannelCount)
                        .arg(channels.size()));
    for (qsizetype i = 0; reader.ok() && i < channels.size(); ++i) {
        JsonObjectReader channel = reader.element(channelsKey, channels, i);
        header.channels[i] = readChannel(channel);
    }
    const QString mathKey = QStringLiteral("math");
    if (reader.ok() && reader.has(mathKey)) {
        const QJsonArray math = reader.array(mathKey);
        for (qsizetype i = 0; reader.ok() && i < math.size(); ++i) {
            const QString place = JsonObjectReader::indexed(reader.place(mathKey), i);
            QString wrong;
            const std::optional<ScopeMathDefinition> definition
                = math.at(i).isObject()
                ? ScopeMathDefinition::fromJson(math.at(i).toObject(), &wrong)
                : std::nullopt;
            if (!math.at(i).isObject())
                wrong = tr("expected an object");
            if (definition)
                header.math << *definition;
            else
                reader.fail(place, wrong);
        }
    }
    const QString triggerKey = QStringLiteral("trigger");
    if (reader.ok() && reader.has(triggerKey))
        header.triggerMs = reader.integer(triggerKey, std::numeric_limits<qint64>::min() / 2,
                                          std::numeric_limits<qint64>::max() / 2);
    reader.finish();
    if (!fault.isEmpty() && error)
        *error = fault.text();
    return fault.isEmpty();
}

void ScopeFileFormat::encode(const ScopeSample &sample, char *to)
{
    qToLittleEndian(sample.time, to);
    qToLittleEndian(sample.wide[0], to + 8);
    qToLittleEndian(sample.wide[1], to + 12);
    qToLittleEndian(sample.narrow[0], to + 16);
    qToLittleEndian(sample.narrow[1], to + 18);
}

ScopeSample ScopeFileFormat::decode(const char *from)
{
    ScopeSample sample;
    sample.time = qFromLittleEndian<qint64>(from);
    sample.wide = { qFromLittleEndian<qint32>(from + 8), qFromLittleEndian<qint32>(from + 12) };
    sample.narrow = { qFromLittleEndian<qint16>(from + 16), qFromLittleEndian<qint16>(from + 18) };
    return sample;
}

} // namespace DriveDesk
