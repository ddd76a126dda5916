#include "DriveChange.h"

#include <QSet>

namespace DriveDesk {

QString DriveChange::differenceLine(const QString &drive, const ParameterDifference &difference)
{
    switch (difference.kind) {
    case ParameterDifference::Kind::OnlyInA:
        return tr("%1 %2: no longer on the drive (was %3)").arg(drive, difference.id, difference.a);
    case ParameterDifference::Kind::OnlyInB:
        return tr("%1 %2: new on the drive, %3").arg(drive, difference.id, difference.b);
    case ParameterDifference::Kind::Different:
        break;
    }
    if (difference.set < 0)
        return tr("%1 %2: %3 -> %4").arg(drive, difference.id, difference.a, difference.b);
    return tr("%1 %2 set %3: %4 -> %5")
        .arg(drive, difference.id)
        .arg(difference.set)
        .arg(difference.a, difference.b);
}

QStringList DriveChange::lines() const
{
    switch (kind) {
    case Kind::Added: return {tr("%1 added").arg(drive)};
    case Kind::Gone: return {tr("%1 gone").arg(drive)};
    case Kind::Unreadable: return {tr("%1: the file cannot be read: %2").arg(drive, reason)};
    case Kind::Changed: break;
    }
    QStringList result;
    for (const ParameterDifference &difference : differences)
        result << differenceLine(drive, difference);
    return result;
}

QString DriveChange::kindKey(Kind kind)
{
    switch (kind) {
    case Kind::Changed: return QStringLiteral("changed");
    case Kind::Added: return QStringLiteral("added");
    case Kind::Gone: return QStringLiteral("gone");
    case Kind::Unreadable: return QStringLiteral("unreadable");
    }
    return {};
}

QList<DriveChange> compareRevisions(const DriveFiles &before, const DriveFiles &after)
{
    QSet<QString> names;
    for (const DriveFiles *files : {&before, &after}) {
        for (auto it = files->drives.cbegin(); it != files->drives.cend(); ++it)
            names.insert(it.key());
        for (auto it = files->unreadable.cbegin(); it != files->unreadable.cend(); ++it)
            names.insert(it.key());
    }
    QStringList sorted(names.cbegin(), names.cend());
    sorted.sort();
    QList<DriveChange> changes;
    for (const QString &name : std::as_const(sorted)) {
        DriveChange change;
        change.drive = name;
        if (!after.has(name)) {
            change.kind = DriveChange::Kind::Gone;
        } else if (!before.has(name)) {
            change.kind = DriveChange::Kind::Added;
        } else if (after.unreadable.contains(name)) {
            // An unreadable file that stayed as it was is no change of this revision.
            if (before.unreadable.value(name) == after.unreadable.value(name))
                continue;
            change.kind = DriveChange::Kind::Unreadable;
            change.reason = after.unreadable.value(name);
        } else if (before.unreadable.contains(name)) {
            change.kind = DriveChange::Kind::Added;
        } else {
            change.differences = compareDescriptions(before.drives.value(name),
                                                     after.drives.value(name))
                                     .differences;
            if (change.differences.isEmpty())
                continue;
        }
        changes << change;
    }
    return changes;
}

std::optional<QString> driveOfFile(const QString &fileName)
{
    static const QString suffix = QStringLiteral(".json");
    if (!fileName.endsWith(suffix) || fileName.size() == suffix.size()
        || fileName.contains(QLatin1Char('/')) || fileName.startsWith(QLatin1Char('.')))
        return std::nullopt;
    return fileName.chopped(suffix.size());
}

bool sameParameterId(const QString &typed, const QString &id)
{
    const auto normal = [](const QString &text) {
        const QString lower = text.trimmed().toLower();
        const qsizetype dot = lower.indexOf(QLatin1Char('.'));
        if (dot < 0)
            return lower;
        bool ok = false;
        const int number = lower.mid(dot + 1).toInt(&ok);
        return ok ? QStringLiteral("%1.%2").arg(lower.left(dot)).arg(number) : lower;
    };
    return normal(typed) == normal(id);
}

} // namespace DriveDesk
