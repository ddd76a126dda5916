#pragma once

#include "plant/PlantState.h"

#include <QAbstractItemModel>

namespace DriveDesk {

// The plant view's tree: each link of a plant with its drives below it (a DIN link's
// addresses, an HSP5 link's one drive), showing what core's PlantState knows of each drive:
// whether it answers, its identification, its last backup, the last job's result ("differs
// from its file") and the progress of the job at work. The model only puts them in words and
// roles; of its own it keeps the rows it has announced to its views, as Qt's model/view needs.
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

    // Shows `state`, which outlives the model.
    explicit PlantModel(const PlantState *state, QObject *parent = nullptr);

    const Plant &plant() const { return m_state->plant(); }

    // The drive's index (column 0), invalid when the plant has no such drive.
    QModelIndex driveIndex(const QString &link, int address) const;
    bool isDrive(const QModelIndex &index) const;
    // The link of a row (for a drive, the link it hangs on).
    const PlantLink *linkOf(const QModelIndex &index) const;
    static QString stateText(PlantState::Reach reach);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    // A link's row and its drives' rows, as the views were last told of them.
    struct LinkRows
    {
        QString link;
        QList<int> drives; // PlantState::drivesOf()
    };

    void takeRows();
    void addDrive(const QString &link, int address);
    int linkRow(const QString &link) const;
    QVariant linkData(int row, int column, int role) const;
    QVariant driveData(const PlantLink &link, int address, int column, int role) const;
    // What the job at work does, as it says it; a job that does not say is reading.
    QString progressText(const QString &what) const;
    QString resultText(const PlantDrive &drive) const;
    QString resultToolTip(const PlantDrive &drive) const;
    void rowChanged(const QModelIndex &index);

    const PlantState *m_state;
    QList<LinkRows> m_rows;
};

} // namespace DriveDesk
