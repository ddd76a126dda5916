#pragma once

#include "parameters/ParameterComparison.h"

#include <QCoreApplication>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>

namespace DriveDesk {

// What changed on one drive of a plant between two revisions of its backups: the drive
// added, gone, its settings that differ (compareDescriptions: live values and whatever else is
// no setting never count), or its file unreadable at one of them.
struct DriveChange
{
    Q_DECLARE_TR_FUNCTIONS(DriveChange)
public:
    enum class Kind : quint8 { Changed, Added, Gone, Unreadable };

    QString drive; // "cabinet-5": the file's name without ".json"
    Kind kind = Kind::Changed;
    QList<ParameterDifference> differences; // Changed: a = before, b = after
    QString reason;                         // Unreadable: why

    // One line a difference, in the drive's words: "cabinet-5 op.28 set 0: 6.00 s -> 7.00 s",
    // "cabinet-7 added", "cabinet-9 gone".
    QStringList lines() const;
    static QString differenceLine(const QString &drive, const ParameterDifference &difference);
    // "changed", "added", "gone", "unreadable": fixed words for scripts.
    static QString kindKey(Kind kind);
};

// A plant's backups at one revision: each drive's description by drive name, or why its file
// could not be read.
struct DriveFiles
{
    QMap<QString, DriveDescription> drives;
    QMap<QString, QString> unreadable;

    bool has(const QString &drive) const
    {
        return drives.contains(drive) || unreadable.contains(drive);
    }
};

// What changed from `before` to `after`, drive by drive in name order; a drive whose settings
// are equal is left out. The one rule of `plant backup --commit`'s message and of
// `plant history` (and a window's history).
QList<DriveChange> compareRevisions(const DriveFiles &before, const DriveFiles &after);

// The drive of a file at the top of a backup folder: "cabinet-5.json" -> "cabinet-5"; nothing
// for a name that is no drive's parameter file.
std::optional<QString> driveOfFile(const QString &fileName);

// Whether a parameter id a user typed ("op.028", "OP.28") names `id` ("op.28").
bool sameParameterId(const QString &typed, const QString &id);

} // namespace DriveDesk
