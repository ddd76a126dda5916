// Where the journal is unless a program names another: the one place every part of the window
// opens, moved for the whole run by `drivedesk --journal PATH`.
#include "Journal.h"

#include <QDir>
#include <QStandardPaths>

namespace DriveDesk {

namespace {

QString &chosenDefaultPath()
{
    static QString path;
    return path;
}

} // namespace

void Journal::setDefaultPath(const QString &path)
{
    chosenDefaultPath()
        = path.isEmpty() ? QString() : QDir::cleanPath(QDir().absoluteFilePath(path));
}

QString Journal::defaultPath()
{
    if (!chosenDefaultPath().isEmpty())
        return chosenDefaultPath();
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation)
        + QStringLiteral("/DriveDesk/journal.sqlite");
}

} // namespace DriveDesk
