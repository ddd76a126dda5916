#include "ParameterDocument.h"

#include "DisplayScaling.h"
#include "JsonObjectReader.h"
#include "JsonTextPlaces.h"
#include "ParameterDocumentChecks.h"
#include "ParameterId.h"
#include "ParameterProperties.h"
#include "SetList.h"

#include <QJsonDocument>
#include <QJsonParseError>
#include <QSet>

#include <limits>

// fromJson(): reads and checks a parameter file, naming the place of the first fault.

namespace DriveDesk {

namespace {

constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();

// "uF.07, set 0", "uF.07, min": a place inside a parameter as the user knows it.
QString partOf(const QString &id, const QString &part)
{
    return ParameterDocument::tr("%1, %2", "a parameter id, then a set or a field of it")
        .arg(id, part);
}

// A fault inside the parameter read at `place` names the parameter by its id, not the path to
// it; the path stays in the fault to find the line and column.
void nameFault(JsonFault &fault, const QString &place, const QString &id)
{
    if (fault.isEmpty() || id.isEmpty() || !fault.subject.isEmpty()
        || !fault.place.startsWith(place))
        return;
    if (fault.place.size() == place.size())
        fault.subject = id;
    else if (fault.place.at(place.size()) == QLatin1Char('.'))
        fault.subject = partOf(id, fault.place.mid(place.size() + 1));
}

void readValues(JsonObjectReader &reader, ParameterDescription &parameter, const QString &id)
{
    const QString key = QStringLiteral("values");
    const QJsonArray values = reader.array(key);
    if (!reader.ok())
        return;
    const bool setProgrammable = parameter.isSetProgrammable();
    if (values.size() != kParameterSets && (setProgrammable || values.size() != 1)) {
        reader.fail(reader.place(key),
                    setProgrammable
                        ? ParameterDocument::tr("%n entries; a set-programmable parameter has one "
                                                "for each of the 8 sets",
                                                nullptr, int(values.size()))
                        : ParameterDocument::tr("%n entries; expected 1 (or 8, one for each set)",
                                                nullptr, int(values.size())));
        return;
    }
    for (qsizetype set = 0; set < values.size() && reader.ok(); ++set) {
        if (values.at(set).isNull())
            continue; // the read failed: no value, never a guessed one
        const QString place = JsonObjectReader::indexed(reader.place(key), set);
        parameter.values[set] = qint32(
            reader.checkedInteger(values.at(set), place, kInt32Min, kInt32Max).value_or(0));
        if (!reader.ok())
            reader.error()->subject = partOf(id, SetList::text(quint8(1u << set)));
    }
}

void readPlaintexts(JsonObjectReader &reader, ParameterDescription &parameter)
{
    const QString definitionsKey = QStringLiteral("plaintextDefinitions");
    const QJsonArray definitions = reader.array(definitionsKey);
    for (qsizetype i = 0; i < definitions.size() && reader.ok(); ++i) {
        JsonObjectReader fields = reader.element(definitionsKey, definitions, i);
        PlaintextDefinition definition;
        definition.mask = quint32(fields.integer(QStringLiteral("mask"), 0, 0xFFFFFFFFLL));
        definition.description = fields.string(QStringLiteral("description"));
        fields.finish();
        parameter.plaintexts.append(definition);
    }
    const QString textsKey = QStringLiteral("plaintexts");
    const QJsonArray texts = reader.array(textsKey);
    for (qsizetype i = 0; i < texts.size() && reader.ok(); ++i) {
        JsonObjectReader fields = reader.element(textsKey, texts, i);
        const qint64 definition
            = fields.integer(QStringLiteral("definition"), 0, std::numeric_limits<int>::max());
        PlaintextEntry entry;
        entry.value = qint32(fields.integer(QStringLiteral("value"), kInt32Min, kInt32Max));
        entry.type = quint8(fields.integer(QStringLiteral("type"), 0, 0xFF));
        entry.text = fields.string(QStringLiteral("text"));
        fields.finish();
        if (fields.ok() && definition >= parameter.plaintexts.size()) {
            fields.fail(fields.place(QStringLiteral("definition")),
                        ParameterDocument::tr("%1, but plaintextDefinitions has %n entries",
                                              nullptr, int(parameter.plaintexts.size()))
                            .arg(definition));
        }
        if (fields.ok())
            parameter.plaintexts[definition].entries.append(entry);
    }
}

// `id` is the parameter's id once its address is known to lie in `group`.
ParameterDescription readParameter(JsonObjectReader &reader, const GroupDescription &group,
                                   const QList<GroupAddress> &groups, QString &id)
{
    ParameterDescription parameter;
    parameter.address = quint16(reader.integer(QStringLiteral("address"), 0, 0xFFFF));
    if (reader.ok() && (parameter.address & 0xFF00) != (group.address & 0xFF00)) {
        reader.fail(reader.place(QStringLiteral("address")),
                    ParameterDocument::tr("%1 is not in group %2 (%3)")
                        .arg(ParameterId::hexAddress(parameter.address), group.id,
                             ParameterId::hexAddress(group.address)));
        return parameter;
    }
    if (reader.ok())
        id = parameterId(group, parameter);
    parameter.name = reader.string(QStringLiteral("name"));
    parameter.minimum = qint32(reader.integer(QStringLiteral("min"), kInt32Min, kInt32Max));
    parameter.maximum = qint32(reader.integer(QStringLiteral("max"), kInt32Min, kInt32Max));
    parameter.defaultValue
        = qint32(reader.integer(QStringLiteral("default"), kInt32Min, kInt32Max));
    parameter.properties1 = quint32(reader.integer(QStringLiteral("properties1"), 0, 0xFFFFFFFFLL));
    parameter.properties2 = quint32(reader.integer(QStringLiteral("properties2"), 0, 0xFFFFFFFFLL));
    if (!reader.ok())
        return parameter;
    ParameterDocumentChecks::checkLimits(reader, parameter);
    if (!reader.ok())
        return parameter;

    JsonObjectReader scaling(reader.object(QStringLiteral("scaling")),
                             reader.place(QStringLiteral("scaling")), reader.error());
    parameter.scaling.divisor = qint16(scaling.integer(QStringLiteral("divisor"), -32768, 32767));
    parameter.scaling.multiplier
        = qint16(scaling.integer(QStringLiteral("multiplier"), -32768, 32767));
    parameter.scaling.offset = qint16(scaling.integer(QStringLiteral("offset"), -32768, 32767));
    parameter.scaling.flags = quint16(scaling.integer(QStringLiteral("flags"), 0, 0xFFFF));
    parameter.scaling.address = scaling.has(QStringLiteral("address"))
        ? quint16(scaling.integer(QStringLiteral("address"), 0, 0xFFFF))
        : parameter.address;
    scaling.finish();

    JsonObjectReader indices(reader.object(QStringLiteral("plaintextIndices")),
                             reader.place(QStringLiteral("plaintextIndices")), reader.error());
    PlaintextIndicesData &plaintextIndices = parameter.plaintextIndices;
    plaintextIndices.displayIndex
        = quint16(indices.integer(QStringLiteral("displayIndex"), 0, 0xFFFF));
    plaintextIndices.displayCount
        = quint16(indices.integer(QStringLiteral("displayCount"), 0, 0xFFFF));
    plaintextIndices.combivisIndex
        = quint16(indices.integer(QStringLiteral("combivisIndex"), 0, 0xFFFF));
    plaintextIndices.combivisCount
        = quint16(indices.integer(QStringLiteral("combivisCount"), 0, 0xFFFF));
    plaintextIndices.address = indices.has(QStringLiteral("address"))
        ? quint16(indices.integer(QStringLiteral("address"), 0, 0xFFFF))
        : parameter.address;
    indices.finish();

    readValues(reader, parameter, id);
    readPlaintexts(reader, parameter);
    if (reader.has(QStringLiteral("error")))
        parameter.error = reader.string(QStringLiteral("error"));
    if (reader.ok())
        ParameterDocumentChecks::checkDerived(reader, parameter, groups);
    reader.finish();
    return parameter;
}

GroupDescription readGroupHeader(JsonObjectReader &reader)
{
    GroupDescription group;
    group.id = reader.string(QStringLiteral("id"));
    group.index = quint8(reader.integer(QStringLiteral("index"), 0, 0xFF));
    group.address = quint16(reader.integer(QStringLiteral("address"), 0, 0xFFFF));
    group.name = reader.string(QStringLiteral("name"));
    const QString shortcut = reader.string(QStringLiteral("shortcut"));
    if (reader.ok()
        && (shortcut.size() > 1 || (shortcut.size() == 1 && shortcut.at(0).unicode() > 0xFF)))
        reader.fail(reader.place(QStringLiteral("shortcut")),
                    ParameterDocument::tr("'%1' is not one Latin-1 character").arg(shortcut));
    group.shortcut = shortcut.isEmpty() ? 0 : char(shortcut.at(0).unicode());
    group.properties = quint16(reader.integer(QStringLiteral("properties"), 0, 0xFFFF));
    group.highestNumber = quint8(reader.integer(QStringLiteral("highestNumber"), 0, 0xFF));
    group.parameterCount = int(reader.integer(QStringLiteral("parameterCount"), 0, 256));
    return group;
}

bool readDrive(JsonObjectReader &root, DriveDescription &drive)
{
    JsonObjectReader reader(root.object(QStringLiteral("drive")),
                            root.place(QStringLiteral("drive")), root.error());
    drive.protocol = reader.string(QStringLiteral("protocol"));
    drive.connection = reader.string(QStringLiteral("connection"));
    drive.driveAddress = int(reader.integer(QStringLiteral("address"), -1, 255));
    drive.language = int(reader.integer(QStringLiteral("language"), 0, 255));
    drive.identification = reader.string(QStringLiteral("identification"));
    drive.incompleteReason = reader.string(QStringLiteral("incompleteReason"));
    reader.finish();
    return reader.ok();
}

bool readGroups(JsonObjectReader &root, DriveDescription &drive)
{
    const QString key = QStringLiteral("groups");
    const QJsonArray groups = root.array(key);
    // The group list first: parameter ids name groups that may come later in the file.
    QList<GroupAddress> addresses;
    for (qsizetype i = 0; i < groups.size() && root.ok(); ++i) {
        JsonObjectReader reader = root.element(key, groups, i);
        GroupDescription group = readGroupHeader(reader);
        if (!reader.ok())
            return false;
        for (const GroupDescription &other : std::as_const(drive.groups)) {
            if (other.id == group.id)
                reader.fail(reader.place(QStringLiteral("id")),
                            ParameterDocument::tr("'%1' appears twice").arg(group.id));
            else if (other.address == group.address)
                reader.fail(reader.place(QStringLiteral("address")),
                            ParameterDocument::tr("%1 is also the address of group %2")
                                .arg(ParameterId::hexAddress(group.address), other.id));
        }
        addresses.append({ group.id, group.address });
        drive.groups.append(group);
    }
    // The file names parameters by group id ("ru.3"): a group id such an id cannot carry (a
    // space, a dot) would be saved into ids no reader takes back.
    for (qsizetype i = 0; i < drive.groups.size() && root.ok(); ++i) {
        const GroupDescription &group = drive.groups.at(i);
        const QString id = ParameterId::format(group.address, addresses);
        QString why;
        if (ParameterId::parse(id, addresses, &why) != group.address) {
            JsonObjectReader reader = root.element(key, groups, i);
            reader.fail(reader.place(QStringLiteral("id")),
                        ParameterDocument::tr("'%1' cannot stand in a parameter id: %2")
                            .arg(group.id,
                                 why.isEmpty() ? ParameterDocument::tr("'%1' names another "
                                                                       "address")
                                                     .arg(id)
                                               : why));
        }
    }
    QSet<quint16> seen;
    for (qsizetype i = 0; i < drive.groups.size() && root.ok(); ++i) {
        JsonObjectReader reader = root.element(key, groups, i);
        readGroupHeader(reader); // marks the header fields as read for finish()
        GroupDescription &group = drive.groups[i];
        const QString parametersKey = QStringLiteral("parameters");
        const QJsonArray parameters = reader.array(parametersKey);
        for (qsizetype p = 0; p < parameters.size() && reader.ok(); ++p) {
            JsonObjectReader fields = reader.element(parametersKey, parameters, p);
            QString id;
            ParameterDescription parameter = readParameter(fields, group, addresses, id);
            if (fields.ok() && seen.contains(parameter.address))
                fields.fail(fields.place(QStringLiteral("address")),
                            ParameterDocument::tr("%1 appears twice")
                                .arg(ParameterId::hexAddress(parameter.address)));
            nameFault(*fields.error(), JsonObjectReader::indexed(reader.place(parametersKey), p),
                      id);
            seen.insert(parameter.address);
            group.parameters.append(parameter);
        }
        reader.finish();
    }
    return root.ok();
}

// The fault with the line and column of its place in the text.
QString located(const QByteArray &json, const JsonFault &fault)
{
    const JsonTextPlaces::LineColumn at
        = JsonTextPlaces::lineColumn(json, JsonTextPlaces::offsetOf(json, fault.place));
    return ParameterDocument::tr("%1 (line %2, column %3)")
        .arg(fault.text())
        .arg(at.line)
        .arg(at.column);
}

} // namespace

std::optional<DriveDescription> ParameterDocument::fromJson(const QByteArray &json, QString *error)
{
    JsonFault fault;
    auto fail = [&](const QString &message) -> std::optional<DriveDescription> {
        if (error)
            *error = message;
        return std::nullopt;
    };

    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const JsonTextPlaces::LineColumn at = JsonTextPlaces::lineColumn(json, parseError.offset);
        return fail(ParameterDocument::tr("not valid JSON: %1 at line %2, column %3")
                        .arg(parseError.errorString())
                        .arg(at.line)
                        .arg(at.column));
    }
    if (!document.isObject())
        return fail(ParameterDocument::tr(
            "not a DriveDesk parameter file: the document is not a JSON object"));

    JsonObjectReader root(document.object(), QString(), &fault);
    const QJsonValue format = root.value(QStringLiteral("format"));
    if (!root.ok() || format.toString() != kFormat) {
        return fail(
            ParameterDocument::tr("not a DriveDesk parameter file: format is %1, expected '%2'")
                .arg(format.isString() ? QStringLiteral("'%1'").arg(format.toString())
                                       : ParameterDocument::tr("missing or not a string"),
                     kFormat));
    }
    const QJsonValue version = root.value(QStringLiteral("version"));
    if (!version.isDouble())
        return fail(ParameterDocument::tr("version: missing or not a number"));
    if (version.toDouble() > kVersion) {
        return fail(ParameterDocument::tr("version: %1 is a newer format than this DriveDesk "
                                          "reads (version %2); a newer DriveDesk reads it")
                        .arg(version.toDouble())
                        .arg(kVersion));
    }
    if (version.toDouble() != kVersion) {
        return fail(
            ParameterDocument::tr("version: %1 is not supported (this DriveDesk reads version %2)")
                .arg(version.toDouble())
                .arg(kVersion));
    }

    // QJsonObject keeps only the last of two equal keys: which one the writer meant is unknown.
    if (const auto duplicate = JsonTextPlaces::firstDuplicateKey(json)) {
        const JsonTextPlaces::LineColumn at = JsonTextPlaces::lineColumn(json, duplicate->offset);
        return fail(ParameterDocument::tr("%1: appears twice in one object (line %2, column %3)")
                        .arg(duplicate->path)
                        .arg(at.line)
                        .arg(at.column));
    }

    DriveDescription drive;
    if (!readDrive(root, drive) || !readGroups(root, drive))
        return fail(located(json, fault));
    root.finish();
    if (!root.ok())
        return fail(located(json, fault));
    return drive;
}

} // namespace DriveDesk
