#pragma once

#include "DriveDescription.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QJsonObject>
#include <QString>

#include <optional>

namespace DriveDesk {

// The parameter file: a DriveDescription as JSON ("drivedesk-parameters", version 1), raw
// values and all metadata, so that loading it reproduces the description exactly.
// The format is described in docs/parameter-file.md.
class ParameterDocument
{
    Q_DECLARE_TR_FUNCTIONS(ParameterDocument)
public:
    static constexpr int kVersion = 1;
    static constexpr qint64 kMaxFileSize = 64 * 1024 * 1024;
    static const QString kFormat; // "drivedesk-parameters"

    static QByteArray toJson(const DriveDescription &drive);
    // The same document as an object, for a file that holds it inside its own (the metadata
    // cache) without writing and parsing it again.
    static QJsonObject toJsonObject(const DriveDescription &drive);
    // Nothing, with the place, the reason and the line and column ("uF.07, set 0: expected an
    // integer (line 40, column 17)"; outside a parameter "groups[2].name: ..."), for anything
    // that is not a valid version-1 parameter file.
    static std::optional<DriveDescription> fromJson(const QByteArray &json,
                                                    QString *error = nullptr);

    // Writes through QSaveFile: on failure the file at `path` is left as it was.
    static bool save(const QString &path, const DriveDescription &drive, QString *error = nullptr);
    static std::optional<DriveDescription> load(const QString &path, QString *error = nullptr);
};

} // namespace DriveDesk
