#pragma once

#include "history/PlantHistory.h"

#include <QList>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>

namespace DriveDesk {

// What the history window asks of git, each a function to run in the thread pool: core's Git
// blocks until git has ended, and the window's thread never waits on it.

// A backup folder's history as one reading found it.
struct HistoryReading
{
    QList<PlantRevision> revisions;
    bool hasCommits = false;
    QString error; // no repository of backups, or git failing
};

HistoryReading readHistory(const QString &directory, const HistoryFilter &filter);

// Revisions' files, each extracted (core's extractRevision()) into a temporary folder of its
// own; none when one of them fails.
struct RevisionFolders
{
    QList<std::shared_ptr<QTemporaryDir>> folders; // in the order asked for
    QString error;
};

RevisionFolders extractRevisions(const QString &directory, const QStringList &revisions);

} // namespace DriveDesk
