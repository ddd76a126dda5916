#include "PlantHistory.h"

#include <QSet>

namespace DriveDesk {

namespace {

// A file a commit changed: its blob before and after; an empty one where it was not there.
struct FileChange
{
    QString name;
    QByteArray before;
    QByteArray after;
};

struct Commit
{
    PlantRevision revision;
    QList<FileChange> files;
};

const char kRecord = '\x1e';
const char kField = '\x1f';

QByteArray blobOrNone(const QByteArray &id)
{
    return id.count('0') == id.size() ? QByteArray() : id;
}

// `git log --raw` in records: the header's fields, then a line a file changed,
// ":100644 100644 <before> <after> M\t<name>".
QList<Commit> parseLog(const QByteArray &log)
{
    QList<Commit> commits;
    for (const QByteArray &record : log.split(kRecord)) {
        if (record.trimmed().isEmpty())
            continue;
        const qsizetype headerEnd = record.indexOf('\n');
        const QList<QByteArray> fields = record.left(headerEnd).split(kField);
        if (fields.size() < 5)
            continue;
        Commit commit;
        commit.revision.id = QString::fromLatin1(fields[0]);
        commit.revision.time = QDateTime::fromSecsSinceEpoch(fields[1].toLongLong());
        commit.revision.author = QString::fromUtf8(fields[2]);
        commit.revision.email = QString::fromUtf8(fields[3]);
        commit.revision.subject = QString::fromUtf8(fields[4]);
        for (const QByteArray &line : record.mid(headerEnd + 1).split('\n')) {
            if (!line.startsWith(':'))
                continue;
            const qsizetype tab = line.indexOf('\t');
            const QList<QByteArray> raw = line.left(tab).split(' ');
            const QString name = QString::fromUtf8(line.mid(tab + 1));
            if (tab < 0 || raw.size() < 5 || !driveOfFile(name))
                continue;
            commit.files << FileChange{name, blobOrNone(raw[2]), blobOrNone(raw[3])};
        }
        commits << commit;
    }
    return commits;
}

void addTo(DriveFiles &files, const QString &name, const QByteArray &blob,
           const QHash<QByteArray, ReadDescription> &parsed)
{
    if (blob.isEmpty())
        return;
    const QString drive = *driveOfFile(name);
    const ReadDescription &read = parsed[blob];
    if (read.description)
        files.drives.insert(drive, *read.description);
    else
        files.unreadable.insert(drive, read.reason);
}

// Revisions whose files are read together: one run of git cat-file each.
constexpr qsizetype kBatch = 100;

// The versions the revisions from `first` on (a batch) need and that are not read yet, read.
bool readBatch(const BackupRepository &repository, const QList<Commit> &commits, qsizetype first,
               QHash<QByteArray, ReadDescription> &parsed, QString *error)
{
    QList<QByteArray> blobs;
    QSet<QByteArray> wanted;
    for (qsizetype i = first; i < std::min(commits.size(), first + kBatch); ++i) {
        for (const FileChange &file : commits[i].files) {
            for (const QByteArray &blob : {file.before, file.after}) {
                if (!blob.isEmpty() && !parsed.contains(blob) && !wanted.contains(blob)) {
                    wanted.insert(blob);
                    blobs << blob;
                }
            }
        }
    }
    const auto contents = repository.contents(blobs, error);
    if (!contents)
        return false;
    QList<QByteArray> texts;
    texts.reserve(blobs.size());
    for (const QByteArray &blob : std::as_const(blobs))
        texts << contents->value(blob);
    const QList<ReadDescription> read = readDescriptions(texts);
    for (qsizetype i = 0; i < blobs.size(); ++i)
        parsed.insert(blobs[i], read[i]);
    return true;
}

} // namespace

std::optional<QList<PlantRevision>> readPlantHistory(const BackupRepository &repository,
                                                     const HistoryFilter &filter,
                                                     QString *error)
{
    if (!repository.hasCommits())
        return QList<PlantRevision>();
    QStringList arguments{QStringLiteral("log"), QStringLiteral("--first-parent"),
                          QStringLiteral("--no-renames"), QStringLiteral("--raw"),
                          QStringLiteral("--no-abbrev"), QStringLiteral("--root"),
                          QStringLiteral("--format=%x1e%H%x1f%ct%x1f%an%x1f%ae%x1f%s"),
                          QStringLiteral("HEAD"), QStringLiteral("--")};
    arguments << (filter.drive.isEmpty() ? QStringLiteral("*.json")
                                         : filter.drive + QStringLiteral(".json"));
    const Git::Result log = repository.git().run(arguments);
    if (!log.ok) {
        *error = log.error;
        return std::nullopt;
    }
    const QList<Commit> commits = parseLog(log.out);

    // Each version is read once and dropped after the last (oldest) revision that needs it, a
    // batch of revisions at a time: a long history is never held in memory whole.
    QHash<QByteArray, qsizetype> lastUse;
    for (qsizetype i = 0; i < commits.size(); ++i) {
        for (const FileChange &file : commits[i].files) {
            for (const QByteArray &blob : {file.before, file.after}) {
                if (!blob.isEmpty())
                    lastUse.insert(blob, i);
            }
        }
    }
    QHash<QByteArray, ReadDescription> parsed;
    QList<PlantRevision> revisions;
    for (qsizetype index = 0; index < commits.size(); ++index) {
        if (index % kBatch == 0 && !readBatch(repository, commits, index, parsed, error))
            return std::nullopt;
        const Commit &commit = commits[index];
        PlantRevision revision = commit.revision;
        DriveFiles before;
        DriveFiles after;
        for (const FileChange &file : commit.files) {
            addTo(before, file.name, file.before, parsed);
            addTo(after, file.name, file.after, parsed);
        }
        for (DriveChange &change : compareRevisions(before, after)) {
            if (!filter.drive.isEmpty() && change.drive != filter.drive)
                continue;
            if (!filter.parameter.isEmpty()) {
                if (change.kind != DriveChange::Kind::Changed)
                    continue;
                change.differences.removeIf([&filter](const ParameterDifference &difference) {
                    return !sameParameterId(filter.parameter, difference.id);
                });
                if (change.differences.isEmpty())
                    continue;
            }
            revision.changes << change;
        }
        if (filter.isEmpty() || !revision.changes.isEmpty())
            revisions << revision;
        for (const FileChange &file : commit.files) {
            for (const QByteArray &blob : {file.before, file.after}) {
                if (!blob.isEmpty() && lastUse.value(blob) == index)
                    parsed.remove(blob);
            }
        }
    }
    return revisions;
}

} // namespace DriveDesk
