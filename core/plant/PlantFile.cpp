#include "PlantFile.h"

#include "parameters/JsonObjectReader.h"
#include "parameters/JsonTextPlaces.h"
#include "parameters/SavedFile.h"
#include "parameters/WholeFile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <algorithm>
#include <limits>

// toJson() writes the plant file, fromJson() reads and checks it.

namespace DriveDesk {

bool PlantLink::operator==(const PlantLink &other) const
{
    // Qt 6.4 compares two empty QList<int> with memcmp on null pointers; std::equal never reads
    // an empty range.
    return name == other.name && connect == other.connect && protocol == other.protocol
        && baudRate == other.baudRate
        && std::equal(addresses.cbegin(), addresses.cend(), other.addresses.cbegin(),
                      other.addresses.cend());
}

namespace {

// A JSON string literal, escaped as QJsonDocument escapes it.
QByteArray quoted(const QString &text)
{
    const QByteArray array = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return array.mid(1, array.size() - 2);
}

QByteArray field(int indent, const char *key, const QByteArray &value)
{
    return QByteArray(indent, ' ') + '"' + key + "\": " + value;
}

QByteArray writeLink(const PlantLink &link)
{
    QList<QByteArray> fields{
        field(12, "name", quoted(link.name)),
        field(12, "connect", quoted(link.connect)),
        field(12, "protocol", quoted(protocolName(link.protocol))),
    };
    if (link.baudRate)
        fields.append(field(12, "baud", QByteArray::number(*link.baudRate)));
    if (!link.addresses.isEmpty()) {
        QList<QByteArray> addresses;
        for (int address : link.addresses)
            addresses.append(QByteArray::number(address));
        fields.append(field(12, "addresses", '[' + addresses.join(", ") + ']'));
    }
    return "        {\n" + fields.join(",\n") + "\n        }";
}

void readAddresses(JsonObjectReader &reader, PlantLink &link)
{
    const QString key = QStringLiteral("addresses");
    if (!reader.has(key))
        return;
    if (link.protocol == Protocol::Hsp5) {
        reader.value(key);
        reader.fail(reader.place(key),
                    PlantFile::tr("an HSP5 link reaches one drive: addresses are for a DIN66019 "
                                  "bus, leave them out"));
        return;
    }
    const QJsonArray addresses = reader.array(key);
    if (reader.ok() && addresses.isEmpty())
        reader.fail(reader.place(key),
                    PlantFile::tr("empty: leave addresses out to search the bus for drives"));
    for (qsizetype i = 0; i < addresses.size() && reader.ok(); ++i) {
        const QString place = JsonObjectReader::indexed(reader.place(key), i);
        const std::optional<qint64> address
            = reader.checkedInteger(addresses.at(i), place, 0,
                                   ConnectionSettings::kMaxDriveAddress);
        if (!address)
            return;
        if (link.addresses.contains(int(*address))) {
            reader.fail(place, PlantFile::tr("drive address %1 appears twice").arg(*address));
            return;
        }
        link.addresses.append(int(*address));
    }
}

PlantLink readLink(JsonObjectReader &reader, const QList<PlantLink> &before)
{
    PlantLink link;
    const QString nameKey = QStringLiteral("name");
    link.name = reader.string(nameKey);
    if (reader.ok()) {
        if (const std::optional<QString> problem = PlantFile::linkNameProblem(link.name))
            reader.fail(reader.place(nameKey), *problem);
    }
    for (qsizetype i = 0; i < before.size() && reader.ok(); ++i) {
        // Compared as a case-insensitive file system would compare the file names.
        if (before.at(i).name.compare(link.name, Qt::CaseInsensitive) == 0)
            reader.fail(reader.place(nameKey),
                        PlantFile::tr("'%1' is also the name of links[%2]: each link needs a "
                                      "name of its own")
                            .arg(link.name)
                            .arg(i));
    }
    const QString connectKey = QStringLiteral("connect");
    link.connect = reader.string(connectKey);
    if (reader.ok()) {
        ConnectionSettings target;
        QString why;
        if (!target.parseTarget(link.connect, &why))
            reader.fail(reader.place(connectKey), why);
    }
    const QString protocolKey = QStringLiteral("protocol");
    const QString protocol = reader.string(protocolKey);
    if (reader.ok()) {
        if (const std::optional<Protocol> known = protocolFromName(protocol))
            link.protocol = *known;
        else
            reader.fail(reader.place(protocolKey),
                        PlantFile::tr("unknown protocol '%1': use hsp5, din66019ii or din66019")
                            .arg(protocol));
    }
    if (reader.has(QStringLiteral("baud")))
        link.baudRate = qint32(reader.integer(QStringLiteral("baud"),
                                              ConnectionSettings::kMinimumBaudRate,
                                              ConnectionSettings::kMaximumBaudRate));
    if (reader.ok())
        readAddresses(reader, link);
    reader.finish();
    return link;
}

// The header: what the file is. Nothing else is read from a file that is not a plant file or
// comes from a newer DriveDesk.
bool readHeader(JsonObjectReader &root)
{
    const QString formatKey = QStringLiteral("format");
    const QJsonValue format = root.value(formatKey);
    if (root.ok() && format.toString() != PlantFile::kFormat)
        root.fail(formatKey,
                  PlantFile::tr("%1, expected '%2': not a DriveDesk plant file")
                      .arg(format.isString() ? QStringLiteral("'%1'").arg(format.toString())
                                             : PlantFile::tr("not a string"),
                           PlantFile::kFormat));
    if (!root.ok())
        return false;
    const QString versionKey = QStringLiteral("version");
    const qint64 version
        = root.integer(versionKey, 1, std::numeric_limits<int>::max());
    if (root.ok() && version > PlantFile::kVersion)
        root.fail(versionKey,
                  PlantFile::tr("%1 is a newer format than this DriveDesk reads (version %2); a "
                                "newer DriveDesk reads it")
                      .arg(version)
                      .arg(PlantFile::kVersion));
    return root.ok();
}

} // namespace

const QString PlantFile::kFormat = QStringLiteral("drivedesk-plant");

ConnectionSettings PlantLink::settings(int address) const
{
    ConnectionSettings result;
    result.parseTarget(connect, nullptr);
    result.protocol = protocol;
    if (protocol != Protocol::Hsp5)
        result.driveAddress = address;
    if (baudRate) {
        result.baudRate = *baudRate;
        result.simulation.baudRate = *baudRate;
    }
    result.simulation.driveAddresses
        = addresses.isEmpty() ? QList<int>{result.driveAddress} : addresses;
    return result;
}

PlantLink *Plant::link(const QString &name)
{
    for (PlantLink &candidate : links) {
        if (candidate.name == name)
            return &candidate;
    }
    return nullptr;
}

const PlantLink *Plant::link(const QString &name) const
{
    return const_cast<Plant *>(this)->link(name);
}

std::optional<QString> PlantFile::linkNameProblem(const QString &name)
{
    if (name.isEmpty())
        return tr("empty: a link needs a name");
    if (name.size() > PlantLink::kMaxNameLength)
        return tr("'%1' is longer than %2 characters").arg(name).arg(PlantLink::kMaxNameLength);
    const auto plain = [](QChar c) {
        return (c >= QLatin1Char('a') && c <= QLatin1Char('z'))
               || (c >= QLatin1Char('A') && c <= QLatin1Char('Z'))
               || (c >= QLatin1Char('0') && c <= QLatin1Char('9'));
    };
    const bool safe = plain(name.front())
                      && std::all_of(name.begin(), name.end(), [&plain](QChar c) {
                             return plain(c) || c == QLatin1Char('-') || c == QLatin1Char('_')
                                    || c == QLatin1Char('.');
                         });
    if (!safe)
        return tr("'%1' cannot be part of a file name: use letters a-z, digits, '-', '_' and "
                  "'.', starting with a letter or digit")
            .arg(name);
    // Windows opens a device for these, whatever follows the dot.
    static const QStringList devices{QStringLiteral("con"), QStringLiteral("prn"),
                                     QStringLiteral("aux"), QStringLiteral("nul")};
    const QString stem = name.section(QLatin1Char('.'), 0, 0).toLower();
    const bool numbered = stem.size() == 4
                          && (stem.startsWith(QLatin1String("com"))
                              || stem.startsWith(QLatin1String("lpt")))
                          && stem.at(3) >= QLatin1Char('1') && stem.at(3) <= QLatin1Char('9');
    if (devices.contains(stem) || numbered)
        return tr("'%1' names a device on Windows: choose another name").arg(name);
    return std::nullopt;
}

QByteArray PlantFile::toJson(const Plant &plant)
{
    QList<QByteArray> links;
    for (const PlantLink &link : plant.links)
        links.append(writeLink(link));
    const QList<QByteArray> fields{
        field(4, "format", quoted(kFormat)),
        field(4, "version", QByteArray::number(kVersion)),
        field(4, "name", quoted(plant.name)),
        field(4, "links",
              links.isEmpty() ? QByteArray("[]") : "[\n" + links.join(",\n") + "\n    ]"),
    };
    return "{\n" + fields.join(",\n") + "\n}\n";
}

std::optional<Plant> PlantFile::fromJson(const QByteArray &json, QString *error)
{
    const auto fail = [&](const QString &message, qsizetype offset) -> std::optional<Plant> {
        const JsonTextPlaces::LineColumn at = JsonTextPlaces::lineColumn(json, offset);
        if (error)
            *error = tr("%1 (line %2, column %3)").arg(message).arg(at.line).arg(at.column);
        return std::nullopt;
    };

    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(tr("not valid JSON: %1").arg(parseError.errorString()), parseError.offset);
    if (!document.isObject())
        return fail(tr("not a DriveDesk plant file: the document is not a JSON object"),
                    JsonTextPlaces::offsetOf(json, QString()));
    // QJsonObject keeps only one of two equal keys: which one the writer meant is unknown.
    if (const auto duplicate = JsonTextPlaces::firstDuplicateKey(json))
        return fail(tr("%1: appears twice in one object").arg(duplicate->path),
                    duplicate->offset);

    JsonFault fault;
    JsonObjectReader root(document.object(), QString(), &fault);
    Plant plant;
    if (readHeader(root)) {
        plant.name = root.string(QStringLiteral("name"));
        if (root.ok() && plant.name.trimmed().isEmpty())
            root.fail(QStringLiteral("name"), tr("empty: give the machine a name"));
        const QString linksKey = QStringLiteral("links");
        const QJsonArray links = root.array(linksKey);
        if (root.ok() && links.isEmpty())
            root.fail(linksKey, tr("empty: a plant has at least one link"));
        for (qsizetype i = 0; i < links.size() && root.ok(); ++i) {
            JsonObjectReader reader = root.element(linksKey, links, i);
            if (reader.ok())
                plant.links.append(readLink(reader, plant.links));
        }
        root.finish();
    }
    if (!root.ok())
        return fail(fault.text(), JsonTextPlaces::offsetOf(json, fault.place));
    return plant;
}

bool PlantFile::save(const QString &path, const Plant &plant, QString *error)
{
    return SavedFile::write(path, toJson(plant), error);
}

std::optional<Plant> PlantFile::load(const QString &path, QString *error)
{
    const std::optional<QByteArray> json = WholeFile::read(path, kMaxFileSize, error);
    if (!json)
        return std::nullopt;
    QString reason;
    std::optional<Plant> plant = fromJson(*json, &reason);
    if (!plant && error)
        *error = QStringLiteral("%1: %2").arg(path, reason);
    return plant;
}

} // namespace DriveDesk
