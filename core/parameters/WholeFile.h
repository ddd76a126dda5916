#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

#include <optional>

namespace DriveDesk {

// Reads a file DriveDesk is given (a parameter file, a plant file, the metadata cache) whole, at
// most `maxBytes` of it. Only a regular file is read: /dev/zero or /dev/urandom never end, and
// opening a FIFO waits for a writer that may never come, so a device, a pipe or a folder is
// refused before it is opened. A file that grows past the limit while it is read is refused
// too: the size checked before reading is not what limits the read.
class WholeFile
{
    Q_DECLARE_TR_FUNCTIONS(WholeFile)
public:
    static std::optional<QByteArray> read(const QString &path, qint64 maxBytes, QString *error);
    // Whether `path` may be opened to read: a regular file (or a link to one). Empty when it
    // may, otherwise why not.
    static QString refusal(const QString &path);
};

} // namespace DriveDesk
