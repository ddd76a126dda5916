#include "ParameterDocument.h"

#include "DisplayScaling.h"
#include "ParameterId.h"
#include "ParameterProperties.h"
#include "SavedFile.h"
#include "WholeFile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace DriveDesk {

namespace {

// The file names parameters as "ru.3" (no leading zero), the way the format was specified;
// the reader takes "ru.03" as well.
QString fileId(quint16 address, const QList<GroupAddress> &groups)
{
    const QString id = ParameterId::format(address, groups);
    const qsizetype dot = id.indexOf(QLatin1Char('.'));
    return dot < 0 ? id : id.left(dot + 1) + QString::number(id.mid(dot + 1).toInt());
}


QJsonObject writeScaling(const ParameterDescription &parameter)
{
    const DisplayScalingData &scaling = parameter.scaling;
    QJsonObject object {
        { QStringLiteral("divisor"), scaling.divisor },
        { QStringLiteral("multiplier"), scaling.multiplier },
        { QStringLiteral("offset"), scaling.offset },
        { QStringLiteral("flags"), scaling.flags },
    };
    // Service 5 answers for the parameter itself; another address is kept, not assumed.
    if (scaling.address != parameter.address)
        object.insert(QStringLiteral("address"), scaling.address);
    return object;
}

QJsonObject writePlaintextIndices(const ParameterDescription &parameter)
{
    const PlaintextIndicesData &indices = parameter.plaintextIndices;
    QJsonObject object {
        { QStringLiteral("displayIndex"), indices.displayIndex },
        { QStringLiteral("displayCount"), indices.displayCount },
        { QStringLiteral("combivisIndex"), indices.combivisIndex },
        { QStringLiteral("combivisCount"), indices.combivisCount },
    };
    if (indices.address != parameter.address)
        object.insert(QStringLiteral("address"), indices.address);
    return object;
}

QJsonArray writeValues(const ParameterDescription &parameter)
{
    // One value unless the parameter is set-programmable; a description that holds values in
    // other sets anyway keeps them all rather than lose them.
    bool allSets = parameter.isSetProgrammable();
    for (int set = 1; set < kParameterSets; ++set)
        allSets = allSets || parameter.values[set].has_value();
    QJsonArray values;
    for (int set = 0; set < (allSets ? kParameterSets : 1); ++set) {
        const std::optional<qint32> &value = parameter.values[set];
        values.append(value ? QJsonValue(*value) : QJsonValue(QJsonValue::Null));
    }
    return values;
}

QJsonObject writeParameter(const ParameterDescription &parameter, const QList<GroupAddress> &groups)
{
    const DisplayScaling scaling(parameter.scaling);
    const ParameterProperties properties(parameter.properties1, parameter.properties2);

    QJsonArray definitions;
    QJsonArray plaintexts;
    for (qsizetype i = 0; i < parameter.plaintexts.size(); ++i) {
        const PlaintextDefinition &definition = parameter.plaintexts.at(i);
        definitions.append(QJsonObject {
            { QStringLiteral("mask"), qint64(definition.mask) },
            { QStringLiteral("description"), definition.description },
        });
        for (const PlaintextEntry &entry : definition.entries) {
            plaintexts.append(QJsonObject {
                { QStringLiteral("definition"), qint64(i) },
                { QStringLiteral("value"), entry.value },
                { QStringLiteral("type"), entry.type },
                { QStringLiteral("text"), entry.text },
            });
        }
    }

    QJsonObject object {
        { QStringLiteral("id"), fileId(parameter.address, groups) },
        { QStringLiteral("address"), parameter.address },
        { QStringLiteral("name"), parameter.name },
        { QStringLiteral("min"), parameter.minimum },
        { QStringLiteral("max"), parameter.maximum },
        { QStringLiteral("default"), parameter.defaultValue },
        { QStringLiteral("unit"), scaling.unitSymbol() },
        { QStringLiteral("decimals"), scaling.decimals() },
        { QStringLiteral("setProgrammable"), properties.isSetProgrammable() },
        { QStringLiteral("readOnly"), properties.isReadOnly() },
        { QStringLiteral("values"), writeValues(parameter) },
        { QStringLiteral("properties1"), qint64(parameter.properties1) },
        { QStringLiteral("properties2"), qint64(parameter.properties2) },
        { QStringLiteral("scaling"), writeScaling(parameter) },
        { QStringLiteral("plaintextIndices"), writePlaintextIndices(parameter) },
        { QStringLiteral("plaintextDefinitions"), definitions },
        { QStringLiteral("plaintexts"), plaintexts },
    };
    if (!parameter.error.isEmpty())
        object.insert(QStringLiteral("error"), parameter.error);
    return object;
}

QJsonObject writeGroup(const GroupDescription &group, const QList<GroupAddress> &groups)
{
    QJsonArray parameters;
    for (const ParameterDescription &parameter : group.parameters)
        parameters.append(writeParameter(parameter, groups));
    const QString shortcut = group.shortcut == 0 ? QString() : QString(QLatin1Char(group.shortcut));
    return QJsonObject {
        { QStringLiteral("id"), group.id },
        { QStringLiteral("index"), group.index },
        { QStringLiteral("address"), group.address },
        { QStringLiteral("name"), group.name },
        { QStringLiteral("shortcut"), shortcut },
        { QStringLiteral("properties"), group.properties },
        { QStringLiteral("highestNumber"), group.highestNumber },
        { QStringLiteral("parameterCount"), group.parameterCount },
        { QStringLiteral("parameters"), parameters },
    };
}

} // namespace

const QString ParameterDocument::kFormat = QStringLiteral("drivedesk-parameters");

QByteArray ParameterDocument::toJson(const DriveDescription &drive)
{
    return QJsonDocument(toJsonObject(drive)).toJson(QJsonDocument::Indented);
}

QJsonObject ParameterDocument::toJsonObject(const DriveDescription &drive)
{
    const QList<GroupAddress> groupAddresses = ParameterId::groupsOf(drive);
    QJsonArray groups;
    for (const GroupDescription &group : drive.groups)
        groups.append(writeGroup(group, groupAddresses));
    return QJsonObject {
        { QStringLiteral("format"), kFormat },
        { QStringLiteral("version"), kVersion },
        { QStringLiteral("drive"),
          QJsonObject {
              { QStringLiteral("protocol"), drive.protocol },
              { QStringLiteral("connection"), drive.connection },
              { QStringLiteral("address"), drive.driveAddress },
              { QStringLiteral("language"), drive.language },
              { QStringLiteral("identification"), drive.identification },
              { QStringLiteral("incompleteReason"), drive.incompleteReason },
          } },
        { QStringLiteral("groups"), groups },
    };
}

bool ParameterDocument::save(const QString &path, const DriveDescription &drive, QString *error)
{
    return SavedFile::write(path, toJson(drive), error);
}

std::optional<DriveDescription> ParameterDocument::load(const QString &path, QString *error)
{
    const std::optional<QByteArray> json = WholeFile::read(path, kMaxFileSize, error);
    if (!json)
        return std::nullopt;
    QString reason;
    std::optional<DriveDescription> drive = fromJson(*json, &reason);
    if (!drive && error)
        *error = QStringLiteral("%1: %2").arg(path, reason);
    return drive;
}

} // namespace DriveDesk
