#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

namespace DriveDesk {

// Writes a whole file through QSaveFile: on any failure (a read-only folder, a full disk) the
// file at the path stays as it was and no half-written file is left. Parameter files and CSV
// exports are saved this way.
class SavedFile
{
    Q_DECLARE_TR_FUNCTIONS(SavedFile)
public:
    static bool write(const QString &path, const QByteArray &bytes, QString *error = nullptr);
};

} // namespace DriveDesk
