#pragma once

#include "BackupRepository.h"
#include "DriveChange.h"

#include <QDateTime>
#include <QList>
#include <QString>

#include <optional>

namespace DriveDesk {

// One revision of a plant's backups: a commit and what it changed, drive by drive.
struct PlantRevision
{
    QString id; // the full commit id
    QDateTime time; // when it was committed
    QString author;
    QString email;
    QString subject; // the message's first line
    QList<DriveChange> changes; // computed from the files, not read from the message

    // A commit id as the user reads it: 12 characters, short enough to read, long enough to
    // stay unique in a plant's lifetime of backups (git accepts it for --at).
    static QString shortId(const QString &id) { return id.left(12); }
};

// Which revisions and changes a history shows: one drive ("cabinet-5"), one parameter
// ("op.28"); empty: all. A revision with nothing the filter lets through is left out.
struct HistoryFilter
{
    QString drive;
    QString parameter;

    bool isEmpty() const { return drive.isEmpty() && parameter.isEmpty(); }
};

// The revisions of a plant's backup repository, newest first, along the first parents, each
// with its changes against the one before (compareRevisions). Each version of a file is read
// once, however many revisions it stays in. Nothing and *error when git fails.
std::optional<QList<PlantRevision>> readPlantHistory(const BackupRepository &repository,
                                                     const HistoryFilter &filter,
                                                     QString *error);

} // namespace DriveDesk
