#pragma once

#include "DriveDescription.h"
#include "DriveIdentity.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// The metadata of each kind of drive a scan has read completely (groups, names per language,
// limits, defaults, properties, scaling, plaintexts), so that the next connection to a drive of
// that kind reads only its values. One JSON file per kind, named after the kind's parameter
// addresses and a digest of their values; see docs/client.md for the format.
//
// Nothing in a cache file is trusted: a file that is not a valid cache file for the kind asked
// for is reported, removed, and treated as missing, so the scan reads the drive cold.
class MetadataCache
{
    Q_DECLARE_TR_FUNCTIONS(MetadataCache)
public:
    static constexpr int kVersion = 1;
    static const QString kFormat; // "drivedesk-metadata-cache"

    // QStandardPaths' generic cache location + "/DriveDesk/metadata" (~/.cache/DriveDesk/metadata).
    static QString defaultDirectory();

    explicit MetadataCache(QString directory);

    QString directory() const { return m_directory; }

    // The address lists of the kinds cached: what a scan reads to learn whether a drive is one
    // of them. Taken from the file names alone; each list once.
    QList<QList<quint16>> probes() const;

    // The cached metadata for `kind` in `language`: a description without values, with
    // metadataFromCache set. Nothing when there is none; a file that cannot be used also sets
    // `warning` (naming the file and what is wrong with it) and is removed.
    std::optional<DriveDescription> find(const DriveKind &kind, int language,
                                         QString *warning = nullptr) const;

    // Keeps the metadata of `drive` (values dropped) for `kind` in the drive's language, next to
    // the other languages already cached for the kind. Written through QSaveFile.
    bool store(const DriveKind &kind, const DriveDescription &drive, QString *error = nullptr);

    // Removes every cache file.
    bool clear(QString *error = nullptr);

    // The file that holds `kind`.
    QString filePath(const DriveKind &kind) const;

private:
    QString m_directory;
};

} // namespace DriveDesk
