// What the plant view shows of a link or a drive, cell by cell: state, identification, last
// backup, last result and its tooltip, progress.
#include "PlantModel.h"

#include <QApplication>
#include <QDir>
#include <QLocale>
#include <QPalette>

namespace DriveDesk {

QVariant PlantModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid())
        return {};
    if (!isDrive(index))
        return linkData(index.row(), index.column(), role);
    const PlantLink *link = linkOf(index);
    if (!link)
        return {};
    const QList<int> &drives = m_rows.at(int(index.internalId() - 1)).drives;
    return index.row() < drives.size()
        ? driveData(*link, drives.at(index.row()), index.column(), role)
        : QVariant();
}

QVariant PlantModel::linkData(int row, int column, int role) const
{
    const PlantLink *plantLink = m_state->plant().link(m_rows.at(row).link);
    if (!plantLink)
        return {};
    const PlantLink &link = *plantLink;
    const PlantState::KnownLink known = m_state->link(link.name);
    const PlantState::Reach reach = m_state->linkReach(link.name);
    if (role == LinkRole)
        return link.name;
    if (role == ProgressRole)
        return column == ProgressColumn ? known.percent : QVariant();
    if (role == Qt::ToolTipRole && known.result && !known.result->reason.isEmpty())
        return known.result->reason;
    if (role != Qt::DisplayRole)
        return {};
    switch (column) {
    case NameColumn:
        return link.name;
    case StateColumn:
        if (link.protocol != Protocol::Hsp5 && link.addresses.isEmpty()
            && reach == PlantState::Reach::NotSearched)
            return tr("not searched");
        return reach == PlantState::Reach::NotSearched ? QString() : stateText(reach);
    case IdentificationColumn: {
        const QString baud = link.baudRate ? tr(", %1 baud").arg(*link.baudRate) : QString();
        return tr("%1 on %2%3").arg(protocolName(link.protocol), link.connect, baud);
    }
    case ResultColumn:
        return known.result ? resultText(*known.result) : QVariant();
    case ProgressColumn:
        return known.percent >= 0 ? progressText(known.what) : QVariant();
    default:
        return {};
    }
}

QVariant PlantModel::driveData(const PlantLink &link, int address, int column, int role) const
{
    const PlantState::KnownDrive known = m_state->drive(link.name, address);
    switch (role) {
    case LinkRole:
        return link.name;
    case AddressRole:
        return address;
    case ProgressRole:
        return column == ProgressColumn ? known.percent : QVariant();
    case OutcomeRole:
        return known.result ? QVariant(int(known.result->outcome)) : QVariant();
    case Qt::ToolTipRole:
        if (column == ResultColumn && known.result)
            return resultToolTip(*known.result);
        if (column == BackupColumn && known.backup.isValid())
            return QDir::toNativeSeparators(
                PlantRun::fileFor(m_state->backupFolder(), link, address));
        if (column == StateColumn && known.reach == PlantState::Reach::Unreachable
            && !known.why.isEmpty())
            return known.why;
        return column == NameColumn ? tr("Double-click to open the drive in the editor")
                                    : QVariant();
    case Qt::ForegroundRole:
        if (column == ResultColumn && known.result && !known.result->isGood())
            return QApplication::palette().color(QPalette::Link);
        return {};
    case Qt::DisplayRole:
        break;
    default:
        return {};
    }
    switch (column) {
    case NameColumn: {
        PlantDrive drive;
        drive.link = link.name;
        drive.address = address;
        return drive.name();
    }
    case StateColumn:
        return stateText(known.reach);
    case IdentificationColumn:
        return known.identification;
    case BackupColumn:
        return known.backup.isValid() ? QLocale().toString(known.backup, QLocale::ShortFormat)
                                      : tr("none");
    case ResultColumn:
        return known.result ? resultText(*known.result) : QVariant();
    case ProgressColumn:
        return known.percent >= 0 ? progressText(known.what) : QVariant();
    default:
        return {};
    }
}

QString PlantModel::progressText(const QString &what) const
{
    return what.isEmpty() ? tr("reading") : what;
}

QString PlantModel::resultText(const PlantDrive &drive) const
{
    if (drive.outcome == PlantDrive::Outcome::Different)
        return tr("differs from its file: %n setting(s)", nullptr, int(drive.differences.size()));
    if (drive.outcome == PlantDrive::Outcome::Saved)
        return tr("saved, %n parameter(s)", nullptr, drive.parameters);
    if (drive.reason.isEmpty() || drive.isGood())
        return PlantDrive::outcomeText(drive.outcome);
    return tr("%1: %2").arg(PlantDrive::outcomeText(drive.outcome), drive.reason);
}

QString PlantModel::resultToolTip(const PlantDrive &drive) const
{
    QStringList lines { resultText(drive) };
    for (const ParameterDifference &difference : drive.differences) {
        const QString set = difference.set < 0 ? QString() : tr(" set %1").arg(difference.set);
        if (difference.kind == ParameterDifference::Kind::Different) {
            lines << tr("%1 %2%3: file %4, drive %5")
                         .arg(difference.id, difference.name, set, difference.a, difference.b);
        } else {
            lines << tr("%1 %2: %3")
                         .arg(difference.id, difference.name,
                              difference.kind == ParameterDifference::Kind::OnlyInA
                                  ? tr("only in the file")
                                  : tr("only on the drive"));
        }
    }
    if (!drive.details.isEmpty())
        lines << drive.details;
    return lines.join(QLatin1Char('\n'));
}

QVariant PlantModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn:
        return tr("Link / drive");
    case StateColumn:
        return tr("State");
    case IdentificationColumn:
        return tr("Identification");
    case BackupColumn:
        return tr("Last backup");
    case ResultColumn:
        return tr("Last result");
    case ProgressColumn:
        return tr("Progress");
    default:
        return {};
    }
}

} // namespace DriveDesk
