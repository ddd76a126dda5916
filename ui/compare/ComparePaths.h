#pragma once

#include "frame/FrameSupport.h"

#include <QFileInfo>
#include <QString>

namespace DriveDesk {

// Two paths naming the same file (the file the window shows is one side).
inline bool samePath(const QString &a, const QString &b)
{
    return !a.isEmpty() && !b.isEmpty()
        && QFileInfo(a).absoluteFilePath() == QFileInfo(b).absoluteFilePath();
}

} // namespace DriveDesk
