#pragma once

#include "plant/PlantRun.h"

#include <QAbstractItemModel>
#include <QDateTime>
#include <QHash>

namespace DriveDesk {

// The plant view's tree: each link of a plant with its drives below it (a DIN link's
// addresses, an HSP5 link's one drive), and what the window knows of each drive: whether it
// answers, its identification, its last backup (the file's time in the backup folder), the
// last job's result ("differs from its file") and the progress of the job at work.
// What a drive is, its file and what a result means come from core (Plant, PlantRun,
// PlantDrive); the model only keeps and shows them.
class PlantModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column {
        NameColumn,
        StateColumn,
        IdentificationColumn,
        BackupColumn,
        ResultColumn,
        ProgressColumn,
        ColumnCount
    };
    enum Role {
        LinkRole = Qt::UserRole + 1, // the link's name, on link and drive rows
        AddressRole, // a drive's address (-1 on an HSP5 link); none on a link
        ProgressRole, // 0..100 while a job works on the row, else -1
        OutcomeRole, // the last PlantDrive::Outcome, as int; none before a job
    };
    // What the window knows of whether a drive answers.
    enum class DriveState : quint8 { NotSearched, Answering, Unreachable };

    explicit PlantModel(QObject *parent = nullptr);

    // Shows `plant`; what is known of drives of the same name stays.
    void setPlant(const Plant &plant);
    // Another plant: nothing known of the one before stays, even where a link has its name.
    void openPlant(const Plant &plant, const QString &backupFolder);
    const Plant &plant() const { return m_plant; }
    // Where the backups are: the "last backup" column looks there.
    void setBackupFolder(const QString &directory);
    QString backupFolder() const { return m_directory; }

    // A job starts: every drive's last result clears.
    void startJob();
    void setProgress(const QString &link, int address, int percent, const QString &what);
    void setDriveDone(const PlantDrive &drive);
    // The job ended: no progress shown any more, backup times read again.
    void endJob();

    // The drive's index (column 0), invalid when the plant has no such drive.
    QModelIndex driveIndex(const QString &link, int address) const;
    bool isDrive(const QModelIndex &index) const;
    // The link of a row (for a drive, the link it hangs on).
    const PlantLink *linkOf(const QModelIndex &index) const;
    // The drive's last result; nothing before a job reached it.
    std::optional<PlantDrive> lastResult(const QString &link, int address) const;
    DriveState driveState(const QString &link, int address) const;
    static QString stateText(DriveState state);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    struct Known
    {
        DriveState state = DriveState::NotSearched;
        QString identification;
        std::optional<PlantDrive> result;
        int percent = -1;
        QString what;
        QDateTime backup; // invalid: no file
    };

    // The drives of a link as rows: a DIN link's addresses, -1 for an HSP5 link's drive.
    QList<int> rowsOf(const PlantLink &link) const;
    static QString key(const QString &link, int address);
    QVariant linkData(int row, int column, int role) const;
    QVariant driveData(const PlantLink &link, int address, int column, int role) const;
    QString resultText(const PlantDrive &drive) const;
    QString resultToolTip(const PlantDrive &drive) const;
    void readBackupTimes();
    // A link answers while one of its drives does; it is unreachable once all of them are.
    void updateLinkState(const PlantLink &link);
    void rowChanged(const QModelIndex &index);
    void allChanged();

    Plant m_plant;
    QString m_directory;
    QHash<QString, Known> m_known; // by drive name ("cabinet-5", "hoist")
    QHash<QString, Known> m_links; // a link's own search progress and state, by link name
};

} // namespace DriveDesk
