#include "SavedFile.h"

#include <QSaveFile>

namespace DriveDesk {

bool SavedFile::write(const QString &path, const QByteArray &bytes, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error)
            *error = tr("cannot write '%1': %2").arg(path, file.errorString());
        return false;
    }
    if (file.write(bytes) != bytes.size()) {
        if (error)
            *error = tr("cannot write '%1': %2").arg(path, file.errorString());
        file.cancelWriting();
        return false;
    }
    if (!file.commit()) {
        if (error)
            *error = tr("cannot save '%1': %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace DriveDesk
