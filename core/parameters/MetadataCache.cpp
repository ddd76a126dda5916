#include "MetadataCache.h"

#include "ParameterDocument.h"
#include "SavedFile.h"
#include "WholeFile.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

namespace DriveDesk {

const QString MetadataCache::kFormat = QStringLiteral("drivedesk-metadata-cache");

namespace {

const QString kFormatKey = QStringLiteral("format");
const QString kVersionKey = QStringLiteral("version");
const QString kKindKey = QStringLiteral("kind");
const QString kLanguagesKey = QStringLiteral("languages");
const QString kSuffix = QStringLiteral(".json");

QString hex4(quint16 value)
{
    return QStringLiteral("%1").arg(value, 4, 16, QLatin1Char('0')).toUpper();
}

QJsonArray kindToJson(const DriveKind &kind)
{
    QJsonArray array;
    for (const KindValue &value : kind.values)
        array.append(QJsonObject{{QStringLiteral("address"), int(value.address)},
                                 {QStringLiteral("value"), value.value}});
    return array;
}

// Only what a later scan takes from the cache: metadata, not values or where they came from.
DriveDescription metadataOnly(const DriveDescription &drive)
{
    DriveDescription metadata;
    metadata.protocol = drive.protocol;
    metadata.language = drive.language;
    metadata.groups = drive.groups;
    for (GroupDescription &group : metadata.groups) {
        for (ParameterDescription &parameter : group.parameters) {
            parameter.values = {};
            parameter.error.clear();
        }
    }
    return metadata;
}

// The file's content when it is a cache file for `kind`; otherwise nothing and why.
std::optional<QJsonObject> readCacheFile(const QString &path, const DriveKind &kind,
                                         QString *reason)
{
    const std::optional<QByteArray> bytes
        = WholeFile::read(path, ParameterDocument::kMaxFileSize, reason);
    if (!bytes)
        return std::nullopt;
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(*bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *reason = MetadataCache::tr("not JSON (%1 at byte %2)")
                      .arg(parseError.errorString())
                      .arg(parseError.offset);
        return std::nullopt;
    }
    const QJsonObject root = document.object();
    if (root.value(kFormatKey).toString() != MetadataCache::kFormat) {
        *reason = MetadataCache::tr("not a DriveDesk metadata cache file");
        return std::nullopt;
    }
    if (root.value(kVersionKey).toInt(-1) != MetadataCache::kVersion) {
        *reason = MetadataCache::tr("cache version %1, this DriveDesk reads version %2")
                      .arg(root.value(kVersionKey).toVariant().toString())
                      .arg(MetadataCache::kVersion);
        return std::nullopt;
    }
    if (root.value(kKindKey).toArray() != kindToJson(kind)) {
        *reason = MetadataCache::tr("it holds another kind of drive");
        return std::nullopt;
    }
    if (!root.value(kLanguagesKey).isObject()) {
        *reason = MetadataCache::tr("it has no languages");
        return std::nullopt;
    }
    return root;
}

} // namespace

QString MetadataCache::defaultDirectory()
{
    // Shared by the window and the command line, whatever their application names.
    return QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation)
           + QStringLiteral("/DriveDesk/metadata");
}

MetadataCache::MetadataCache(QString directory) : m_directory(std::move(directory)) {}

QString MetadataCache::filePath(const DriveKind &kind) const
{
    QStringList addresses;
    QByteArray values;
    for (const KindValue &value : kind.values) {
        addresses.append(hex4(value.address));
        values += QByteArray::number(value.address) + '=' + QByteArray::number(value.value) + ';';
    }
    const QByteArray digest
        = QCryptographicHash::hash(values, QCryptographicHash::Sha1).toHex().left(16);
    return QDir(m_directory).filePath(addresses.join(QLatin1Char('-')) + QLatin1Char('.')
                                      + QString::fromLatin1(digest) + kSuffix);
}

QList<QList<quint16>> MetadataCache::probes() const
{
    QList<QList<quint16>> probes;
    const QStringList files = QDir(m_directory).entryList({QStringLiteral("*") + kSuffix},
                                                          QDir::Files, QDir::Name);
    for (const QString &file : files) {
        const QStringList parts = file.split(QLatin1Char('.'));
        if (parts.size() != 3)
            continue;
        QList<quint16> addresses;
        bool valid = true;
        for (const QString &address : parts.first().split(QLatin1Char('-'))) {
            const uint number = address.toUInt(&valid, 16);
            valid = valid && address.size() == 4 && number <= 0xFFFF;
            if (!valid)
                break;
            addresses.append(quint16(number));
        }
        if (valid && !addresses.isEmpty() && !probes.contains(addresses))
            probes.append(addresses);
    }
    return probes;
}

std::optional<DriveDescription> MetadataCache::find(const DriveKind &kind, int language,
                                                    QString *warning) const
{
    const QString path = filePath(kind);
    if (!QFile::exists(path))
        return std::nullopt;
    QString reason;
    std::optional<DriveDescription> found;
    if (const std::optional<QJsonObject> root = readCacheFile(path, kind, &reason)) {
        const QJsonValue entry = root->value(kLanguagesKey).toObject().value(
            QString::number(language));
        if (entry.isUndefined())
            return std::nullopt; // another language of this kind is cached, not this one
        found = ParameterDocument::fromJson(QJsonDocument(entry.toObject()).toJson(), &reason);
        if (found && found->language != language) {
            reason = tr("language %1 holds the texts of language %2")
                         .arg(language)
                         .arg(found->language);
            found.reset();
        }
    }
    if (!found) {
        if (warning)
            *warning = tr("metadata cache file '%1' ignored and removed: %2").arg(path, reason);
        QFile::remove(path);
        return std::nullopt;
    }
    DriveDescription metadata = metadataOnly(*found);
    metadata.metadataFromCache = true;
    return metadata;
}

bool MetadataCache::store(const DriveKind &kind, const DriveDescription &drive, QString *error)
{
    if (!QDir().mkpath(m_directory)) {
        if (error)
            *error = tr("cannot create the metadata cache folder '%1'").arg(m_directory);
        return false;
    }
    const QString path = filePath(kind);
    QJsonObject languages;
    QString ignored;
    if (QFile::exists(path)) {
        // A file that is not valid for the kind is replaced, not merged with.
        if (const std::optional<QJsonObject> root = readCacheFile(path, kind, &ignored))
            languages = root->value(kLanguagesKey).toObject();
    }
    languages.insert(QString::number(drive.language),
                     ParameterDocument::toJsonObject(metadataOnly(drive)));
    const QJsonObject root{
        {kFormatKey, kFormat},
        {kVersionKey, kVersion},
        {kKindKey, kindToJson(kind)},
        {kLanguagesKey, languages},
    };
    const QByteArray json = QJsonDocument(root).toJson(QJsonDocument::Compact);
    QString reason;
    if (!SavedFile::write(path, json, &reason)) {
        if (error)
            *error = tr("cannot write the metadata cache: %1").arg(reason);
        return false;
    }
    return true;
}

bool MetadataCache::clear(QString *error)
{
    QDir directory(m_directory);
    bool cleared = true;
    for (const QString &file : directory.entryList({QStringLiteral("*") + kSuffix}, QDir::Files)) {
        if (!directory.remove(file)) {
            cleared = false;
            if (error)
                *error = tr("cannot remove '%1'").arg(directory.filePath(file));
        }
    }
    return cleared;
}

} // namespace DriveDesk
