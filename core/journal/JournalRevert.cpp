#include "JournalRevert.h"

#include "parameters/PasswordLevel.h"

#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace DriveDesk {

namespace {

constexpr qint64 kMostIdsAtOnce = 10000; // within what one query may name

} // namespace

QString JournalRevertPlan::job() const
{
    if (entries.isEmpty())
        return JournalRevert::tr("revert");
    if (entries.size() == 1)
        return JournalRevert::tr("revert of entry %1").arg(entries.constFirst());
    return JournalRevert::tr("revert of entries %1..%2")
        .arg(entries.constFirst())
        .arg(entries.constLast());
}

QString JournalRevertPlan::what() const
{
    if (entries.size() == 1)
        return JournalRevert::tr("the value before entry %1").arg(entries.constFirst());
    if (entries.isEmpty())
        return JournalRevert::tr("the values before the entries");
    return JournalRevert::tr("the values before entries %1..%2")
        .arg(entries.constFirst())
        .arg(entries.constLast());
}

DriveDescription JournalRevertPlan::selection(const DriveDescription &drive) const
{
    return ChosenValues::selectionFor(drive, values);
}

JournalRevertPlan JournalRevert::ofEntries(const QList<qint64> &asked,
                                           const QList<JournalEntry> &found,
                                           const JournalDrive &connected,
                                           const DriveDescription &drive)
{
    JournalRevertPlan plan = JournalRevert::plan(found, connected, drive, Asked::ById);
    QSet<qint64> known;
    for (const JournalEntry &entry : found)
        known.insert(entry.id);
    QList<qint64> missing;
    for (const qint64 id : asked) {
        if (!known.contains(id) && !missing.contains(id))
            missing << id;
    }
    std::sort(missing.begin(), missing.end());
    for (const qint64 id : missing)
        plan.refusals.prepend(tr("entry %1: the journal has no such entry").arg(id));
    return plan;
}

JournalRevertPlan JournalRevert::since(const QList<JournalEntry> &found,
                                       const JournalDrive &connected,
                                       const DriveDescription &drive)
{
    return plan(found, connected, drive, Asked::ByTime);
}

JournalRevertPlan JournalRevert::plan(const QList<JournalEntry> &found,
                                      const JournalDrive &connected,
                                      const DriveDescription &drive, Asked asked)
{
    QList<JournalEntry> entries = found;
    std::sort(entries.begin(), entries.end(),
              [](const JournalEntry &a, const JournalEntry &b) { return a.id < b.id; });
    JournalRevertPlan plan;
    QSet<QPair<quint16, int>> taken; // parameter and set whose oldest entry is in the plan
    for (const JournalEntry &entry : entries) {
        const QString named = tr("entry %1 (%2)").arg(entry.id).arg(entry.parameterId);
        if (!entry.drive.isSameDrive(connected)) {
            if (asked == Asked::ByTime)
                continue; // another drive's: not asked for
            plan.refusals << tr("%1 was written to another drive (%2), not the one connected "
                                "(%3)")
                                 .arg(named, entry.drive.name(), connected.name());
            continue;
        }
        if (entry.password || entry.parameterAddress == kPasswordParameterAddress) {
            const QString why = tr("%1 is a password entered: the journal keeps no value of it, "
                                   "so it cannot be reverted")
                                    .arg(named);
            (asked == Asked::ByTime ? plan.leftOut : plan.refusals) << why;
            continue;
        }
        const ParameterDescription *parameter = drive.find(entry.parameterAddress);
        if (!parameter) {
            plan.refusals << tr("%1: the drive has no such parameter").arg(named);
            continue;
        }
        if (!entry.before.raw) {
            plan.refusals << tr("%1: the value before was not read, so there is none to write "
                                "back")
                                 .arg(named);
            continue;
        }
        if (!entry.set && parameter->isSetProgrammable()) {
            plan.refusals << tr("%1 was written to the active set, and the journal does not say "
                                "which set that was")
                                 .arg(named);
            continue;
        }
        plan.entries << entry.id;
        const int set = parameter->isSetProgrammable() ? entry.set.value_or(0) : 0;
        if (taken.contains({ entry.parameterAddress, set }))
            continue; // an older entry's value before wins
        taken.insert({ entry.parameterAddress, set });
        plan.values << ChosenValue { entry.parameterAddress, set, *entry.before.raw };
    }
    return plan;
}

std::optional<QList<qint64>> JournalRevert::parseIds(const QStringList &words, QString *error)
{
    static const QRegularExpression pattern(QStringLiteral("^([0-9]{1,15})(?:\\.\\.([0-9]{1,15}))?$"));
    QList<qint64> ids;
    QSet<qint64> seen;
    for (const QString &word : words) {
        const QRegularExpressionMatch match = pattern.match(word.trimmed());
        const qint64 first = match.captured(1).toLongLong();
        const qint64 last = match.captured(2).isEmpty() ? first : match.captured(2).toLongLong();
        if (!match.hasMatch() || first < 1 || last < first || last - first >= kMostIdsAtOnce) {
            *error = tr("'%1' names no entry: give an entry's number (12) or a range (12..15)")
                         .arg(word);
            return std::nullopt;
        }
        for (qint64 id = first; id <= last; ++id) {
            if (!seen.contains(id)) {
                seen.insert(id);
                ids << id;
            }
        }
    }
    return ids;
}

} // namespace DriveDesk
