// What a plant run says of one drive: its name in file names and reports, its outcome in
// words, and the one summary line of a run for the command line and the plant view.
#include "PlantRun.h"

#include <QStringList>

#include <algorithm>

namespace DriveDesk {

QString PlantDrive::name() const
{
    return address < 0 ? link : QStringLiteral("%1-%2").arg(link).arg(address);
}

bool PlantDrive::answered() const
{
    switch (outcome) {
    case Outcome::Found:
    case Outcome::Saved:
    case Outcome::Equal:
    case Outcome::Different:
    case Outcome::OtherKind:
    case Outcome::Written:
    case Outcome::Unchanged:
    case Outcome::Planned:
        return true;
    case Outcome::NoFile:
    case Outcome::Failed:
    case Outcome::Unreachable:
    case Outcome::Stopped:
        return false;
    }
    return false;
}

QString PlantDrive::outcomeText(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Found: return tr("found");
    case Outcome::Saved: return tr("saved");
    case Outcome::Equal: return tr("equal");
    case Outcome::Different: return tr("different");
    case Outcome::OtherKind: return tr("another kind of drive");
    case Outcome::NoFile: return tr("no file");
    case Outcome::Failed: return tr("failed");
    case Outcome::Unreachable: return tr("unreachable");
    case Outcome::Stopped: return tr("stopped");
    case Outcome::Written: return tr("written");
    case Outcome::Unchanged: return tr("already equal, nothing written");
    case Outcome::Planned: return tr("dry run");
    }
    return {};
}

QString PlantDrive::summary(const QList<PlantDrive> &drives, const QString &goodText)
{
    const qsizetype good = std::count_if(drives.cbegin(), drives.cend(),
                                         [](const PlantDrive &d) { return d.isGood(); });
    QString text = tr("%1 of %n drive(s) %2", nullptr, int(drives.size())).arg(good).arg(goodText);
    QStringList others;
    for (const PlantDrive &drive : drives) {
        if (drive.isGood())
            continue;
        const QString why = drive.reason.isEmpty() ? outcomeText(drive.outcome) : drive.reason;
        others << QStringLiteral("%1 (%2)").arg(drive.name(), why);
    }
    if (!others.isEmpty())
        text += QStringLiteral("; ") + tr("not: %1").arg(others.join(QStringLiteral(", ")));
    return text;
}

} // namespace DriveDesk
