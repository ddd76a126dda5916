#include "WholeFile.h"

#include <QFile>
#include <QFileInfo>

namespace DriveDesk {

QString WholeFile::refusal(const QString &path)
{
    const QFileInfo info(path);
    if (!info.exists())
        return {}; // opening it says so in the system's words
    if (info.isDir())
        return tr("cannot read '%1': it is a folder, not a file").arg(path);
    if (!info.isFile()) {
        return tr("cannot read '%1': it is not a regular file but a device or a pipe, whose "
                  "reading may never end")
            .arg(path);
    }
    return {};
}

std::optional<QByteArray> WholeFile::read(const QString &path, qint64 maxBytes, QString *error)
{
    const auto fail = [error](const QString &message) -> std::optional<QByteArray> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    if (const QString refused = refusal(path); !refused.isEmpty())
        return fail(refused);
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(tr("cannot read '%1': %2").arg(path, file.errorString()));
    const auto tooLarge = [&](qint64 size) {
        return fail(tr("'%1' is too large (%2 bytes, at most %3)").arg(path).arg(size).arg(maxBytes));
    };
    if (file.size() > maxBytes)
        return tooLarge(file.size());
    QByteArray bytes = file.read(maxBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return fail(tr("cannot read '%1': %2").arg(path, file.errorString()));
    if (bytes.size() > maxBytes)
        return tooLarge(bytes.size());
    return bytes;
}

} // namespace DriveDesk
