#include "PlantHistoryReading.h"

#include "history/BackupRepository.h"

namespace DriveDesk {

HistoryReading readHistory(const QString &directory, const HistoryFilter &filter)
{
    HistoryReading reading;
    const auto repository = BackupRepository::open(directory, false, &reading.error);
    if (!repository)
        return reading;
    reading.hasCommits = repository->hasCommits();
    if (const auto revisions = readPlantHistory(*repository, filter, &reading.error))
        reading.revisions = *revisions;
    return reading;
}

RevisionFolders extractRevisions(const QString &directory, const QStringList &revisions)
{
    RevisionFolders result;
    for (const QString &revision : revisions) {
        QString commit;
        std::unique_ptr<QTemporaryDir> folder
            = extractRevision(directory, revision, &commit, &result.error);
        if (!folder)
            return RevisionFolders{{}, result.error};
        result.folders << std::shared_ptr<QTemporaryDir>(std::move(folder));
    }
    return result;
}

} // namespace DriveDesk
