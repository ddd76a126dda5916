#pragma once

#include "PlantRun.h"

#include <QDateTime>
#include <QHash>
#include <QObject>

#include <functional>
#include <optional>
#include <utility>

namespace DriveDesk {

// What DriveDesk knows of the drives of the plant it shows, held once: per drive (its link's
// name and its address, -1 for an HSP5 link's one drive) whether it answers, its
// identification, the last job's result, the progress of the job at work and its last backup
// (the file's time in the backup folder); per link what it said of itself and its state, worked
// out from its drives'. The plant view shows it, the command line asks it whether any link
// answered; both feed it from a PlantRun by follow(), the one way a run is handed to it.
// Thread: the one that made it.
class PlantState : public QObject
{
    Q_OBJECT
public:
    // Whether a drive answers, as far as DriveDesk knows.
    enum class Reach : quint8 { NotSearched, Answering, Unreachable };

    struct KnownDrive
    {
        Reach reach = Reach::NotSearched;
        QString why;            // unreachable: the reason the result that said so gave
        QString identification; // as the last search found it
        std::optional<PlantDrive> result; // the last job's; nothing before a job reached it
        int percent = -1;                 // 0..100 while a job works on the drive, else -1
        QString what;                     // what that job does, as the job says it
        QDateTime backup;                 // invalid: no file in the backup folder
    };
    // A link's own part, apart from its drives: a DIN bus searched, or that could not be opened.
    struct KnownLink
    {
        // The last word on the link as a whole said it cannot be reached, and none of its
        // drives has answered since.
        bool unreachable = false;
        std::optional<PlantDrive> result; // address -1: the bus as a whole
        int percent = -1;
        QString what;
    };
    // How a run's results are kept: as each drive's last result, or not at all (a run into
    // files of its own, as a comparison reads two drives: only its progress shows).
    enum class Keep : quint8 { Results, ProgressOnly };
    // A drive's result as it is to be kept (the window says more of a line its editor holds).
    using Explain = std::function<PlantDrive(const PlantDrive &)>;

    explicit PlantState(QObject *parent = nullptr);

    // Another plant: nothing known of the one before stays, even where a link has its name.
    void openPlant(const Plant &plant, const QString &backupFolder);
    // The same plant edited (a link added, the addresses a search found): what is known of
    // drives of the same name stays.
    void setPlant(const Plant &plant);
    const Plant &plant() const { return m_plant; }
    // Where the backups are: each drive's last backup is its file's time there.
    void setBackupFolder(const QString &directory);
    QString backupFolder() const { return m_directory; }

    // The drives of a link, in order: a DIN link's addresses, -1 for an HSP5 link's drive.
    static QList<int> drivesOf(const PlantLink &link);
    KnownDrive drive(const QString &link, int address) const;
    KnownLink link(const QString &link) const;
    // The one rule of a link's state: unreachable once its last word said so or all its drives
    // are; answering while one of its drives does; not searched before that.
    Reach linkReach(const QString &link) const;
    // Not one link of the plant answers: each is unreachable (a plant of no links is not).
    bool noLinkAnswers() const;

    // Takes `run` from its start to its end: a new job clears every last result, each drive's
    // progress and result are kept as they come, and at the end the progress clears and the
    // backup times are read again; a search that went to the end gives the plant the drives it
    // found. Call before run->start(). A run of a plant since replaced by openPlant() is
    // ignored.
    void follow(PlantRun *run, Keep keep = Keep::Results, Explain explain = {});

signals:
    // The plant was replaced or edited: every link and drive may have changed.
    void reset();
    // A search found a drive the plant did not list; it belongs to the plant now.
    void driveAdded(const QString &link, int address);
    void driveChanged(const QString &link, int address);
    // What the link said of itself, its progress or its state (its drives') changed.
    void linkChanged(const QString &link);

private:
    using DriveKey = std::pair<QString, int>;

    void clearResults();
    void setProgress(const QString &link, int address, int percent, const QString &what);
    void keepResult(const PlantDrive &drive);
    void endJob();
    void readBackupTimes();
    // Every drive and link changed (a job started or ended, another backup folder).
    void allChanged();

    Plant m_plant;
    QString m_directory;
    QHash<DriveKey, KnownDrive> m_drives;
    QHash<QString, KnownLink> m_links;
    quint64 m_opened = 0; // how many plants were opened: a run follows the one it began on
};

} // namespace DriveDesk
