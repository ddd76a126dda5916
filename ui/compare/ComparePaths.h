#pragma once

#include <QDir>
#include <QFileInfo>
#include <QString>

namespace DriveDesk {

// A path as the compare window names it.
inline QString shownPath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// Two paths naming the same file (the file the window shows is one side).
inline bool samePath(const QString &a, const QString &b)
{
    return !a.isEmpty() && !b.isEmpty()
        && QFileInfo(a).absoluteFilePath() == QFileInfo(b).absoluteFilePath();
}

} // namespace DriveDesk
