#include "DownloadPlan.h"

#include "parameters/DriveIdentity.h"
#include "parameters/MetadataMatch.h"
#include "parameters/ParameterAccess.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterList.h"
#include "parameters/SetList.h"

#include <algorithm>
#include <bit>
#include <map>
#include <vector>

namespace DriveDesk {

namespace {

constexpr int kListedIds = 8; // a problem names this many parameters, then "..."

QString idOf(const DriveDescription &drive, quint16 address)
{
    for (const GroupDescription &group : drive.groups) {
        if (group.address == (address & 0xFF00))
            return parameterId(group.id, quint8(address & 0xFF));
    }
    return QStringLiteral("%1h").arg(address, 4, 16, QLatin1Char('0')).toUpper();
}

QString listed(const QStringList &ids)
{
    QStringList shown = ids.mid(0, kListedIds);
    if (ids.size() > kListedIds)
        shown << QStringLiteral("...");
    return shown.join(QStringLiteral(", "));
}

bool hasVariableLimits(const ParameterDescription &parameter)
{
    const ParameterProperties p(parameter.properties1, parameter.properties2);
    return p.lowerLimitType() != ParameterProperties::LimitType::Constant
        || p.upperLimitType() != ParameterProperties::LimitType::Constant;
}

// An identification parameter the drive has whose value was not read: its kind is unknown,
// not absent.
bool hasUnreadIdentification(const DriveDescription &drive)
{
    for (const IdentificationParameter &id : DriveIdentity::parameters()) {
        const GroupDescription *group = drive.findGroup(QString::fromLatin1(id.group));
        const ParameterDescription *parameter
            = group ? drive.find(quint16(group->address | id.number)) : nullptr;
        if (id.namesTheKind && parameter && !parameter->values[0])
            return true;
    }
    return false;
}

void checkKind(const DriveDescription &file, const DriveDescription &drive, bool selection,
               QStringList &problems)
{
    if (!file.identification.isEmpty() && !drive.identification.isEmpty()
        && file.identification != drive.identification) {
        problems << DownloadPlan::tr("the file was made for \"%1\", the drive is \"%2\"")
                        .arg(file.identification, drive.identification);
    }
    const std::optional<DriveKind> fileKind = DriveIdentity::kind(file);
    const std::optional<DriveKind> driveKind = DriveIdentity::kind(drive);
    if (!driveKind && hasUnreadIdentification(drive)) {
        problems << DownloadPlan::tr("the drive's identification could not be read, so the "
                                     "file cannot be checked against it");
        return;
    }
    if (!driveKind) {
        // A drive without the parameters that name its kind (not an F5) is the file's kind
        // when its metadata is the file's (a backup of it, or of one like it).
        const auto difference = MetadataMatch::firstDifference(
            file, drive,
            selection ? MetadataMatch::Scope::AHoldsPart : MetadataMatch::Scope::Whole);
        if (difference) {
            problems << DownloadPlan::tr("the drive has no identification, and the file's "
                                         "metadata is not the drive's: %1")
                            .arg(MetadataMatch::text(*difference));
        }
        return;
    }
    if (!fileKind) {
        problems << DownloadPlan::tr("the file does not say which kind of drive it was made "
                                     "for (its identification parameters are missing)");
        return;
    }
    if (*fileKind == *driveKind)
        return;
    const int before = int(problems.size());
    for (const KindValue &onDrive : driveKind->values) {
        const ParameterDescription *parameter = drive.find(onDrive.address);
        for (const KindValue &inFile : fileKind->values) {
            if (inFile.address != onDrive.address || inFile.value == onDrive.value || !parameter)
                continue;
            const ParameterFormat format(*parameter);
            problems << DownloadPlan::tr("the file was made for another drive: %1 %2 is %3 in "
                                         "the file, %4 on the drive")
                            .arg(idOf(drive, onDrive.address), parameter->name,
                                 format.text(inFile.value), format.text(onDrive.value));
        }
    }
    if (problems.size() == before)
        problems << DownloadPlan::tr("the file was made for another kind of drive");
}

void checkParameters(const DriveDescription &file, const DriveDescription &drive,
                     bool selection, QStringList &problems)
{
    QStringList onlyInFile;
    QStringList onlyOnDrive;
    for (const GroupDescription &group : file.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (ParameterList::holds(parameter) && !drive.find(parameter.address))
                onlyInFile << parameterId(group.id, parameter.number());
        }
    }
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            if (ParameterList::holds(parameter) && !selection && !file.find(parameter.address))
                onlyOnDrive << parameterId(group.id, parameter.number());
        }
    }
    if (!onlyInFile.isEmpty()) {
        problems << DownloadPlan::tr("%n parameter(s) of the file are not on the drive: %1",
                                     nullptr, int(onlyInFile.size()))
                        .arg(listed(onlyInFile));
    }
    if (!onlyOnDrive.isEmpty()) {
        problems << DownloadPlan::tr("%n parameter(s) of the drive are not in the file: %1",
                                     nullptr, int(onlyOnDrive.size()))
                        .arg(listed(onlyOnDrive));
    }
}

// What one parameter of the drive needs: its item, or a skip, or nothing.
class ParameterPlanner
{
public:
    ParameterPlanner(const QString &id, const ParameterDescription &onDrive,
                     const ParameterDescription &inFile, const DownloadOptions &options)
        : m_id(id)
        , m_drive(onDrive)
        , m_file(inFile)
        , m_options(options)
    { }

    void plan(DownloadPlan &plan, std::optional<PasswordLevel> level, QStringList &outside)
    {
        const bool perSet = m_drive.isSetProgrammable();
        const bool always = ParameterList::isAlwaysWritten(m_drive);
        std::map<qint32, quint8> masks; // value to write -> the sets that take it
        quint8 missing = 0;
        DownloadItem item;
        for (int set = 0; set < (perSet ? kParameterSets : 1); ++set) {
            if (perSet && !(m_options.sets & (1u << set)))
                continue;
            const auto s = std::size_t(set);
            const std::optional<qint32> wanted = m_file.values[s];
            if (!wanted) {
                missing |= quint8(1u << set);
                continue;
            }
            // A write-only value is never read to compare with, whatever the scan brought.
            const std::optional<qint32> held = ParameterList::isReadByUpload(m_drive)
                ? m_drive.values[s]
                : std::nullopt;
            if (!always && held == wanted) {
                ++plan.unchanged;
                continue;
            }
            masks[*wanted] |= quint8(1u << set);
            item.wanted[s] = wanted;
            item.before[s] = held;
        }
        const QString why = ParameterList::whyNotWritten(m_drive);
        if (!why.isEmpty()) {
            // A read-only value (a live one above all) differs as a matter of course; the
            // flags that keep a writable value out of a download are worth a line each.
            const ParameterProperties properties(m_drive.properties1, m_drive.properties2);
            if (masks.empty())
                return;
            if (properties.isReadOnly() || readBackMayDiffer(m_drive))
                ++plan.readOnlyDiffering;
            else
                skip(plan, why);
            return;
        }
        if (masks.empty() && (!missing || m_options.selection))
            return;
        if (!perSet && m_options.sets != 0xFF)
            return skip(plan, DownloadPlan::tr("one value for all sets, left out by the sets "
                                               "chosen"));
        if (level && !isWritable(m_drive, *level)) {
            const ParameterProperties properties(m_drive.properties1, m_drive.properties2);
            return skip(plan, DownloadPlan::tr("needs password level %1")
                                  .arg(passwordLevelName(properties.writeLevel())));
        }
        if (missing && !m_options.selection) {
            skip(plan, DownloadPlan::tr("%1 not in the file (not read when it was made)")
                           .arg(SetList::text(missing)));
        }
        if (masks.empty())
            return;
        const ParameterFormat format(m_drive);
        item.id = m_id;
        item.name = m_drive.name;
        item.always = always;
        item.change.address = m_drive.address;
        item.change.setProgrammable = perSet;
        // In the order of the sets (set 0 first), as the last look and the report list them.
        std::vector<std::pair<qint32, quint8>> bySet(masks.cbegin(), masks.cend());
        std::sort(bySet.begin(), bySet.end(), [](const auto &a, const auto &b) {
            return std::countr_zero(unsigned(a.second)) < std::countr_zero(unsigned(b.second));
        });
        for (const auto &[value, mask] : bySet) {
            item.change.steps << WriteStep{perSet ? mask : quint8(0x01), value, false};
            if (value < m_drive.minimum || value > m_drive.maximum) {
                outside << DownloadPlan::tr("%1 (%2) %3 is outside %4 .. %5")
                               .arg(m_id, perSet ? SetList::text(mask) : DownloadPlan::tr("value"),
                                    format.text(value), format.text(m_drive.minimum),
                                    format.text(m_drive.maximum));
            }
        }
        plan.items << item;
    }

private:
    void skip(DownloadPlan &plan, const QString &reason)
    {
        plan.skipped << DownloadSkip{m_id, m_drive.name, reason};
    }

    const QString m_id;
    const ParameterDescription &m_drive;
    const ParameterDescription &m_file;
    const DownloadOptions &m_options;
};

std::optional<PasswordLevel> levelInForce(const DriveDescription &drive)
{
    const ParameterDescription *password = drive.find(kPasswordParameterAddress);
    if (!password || !password->values[0])
        return std::nullopt;
    return passwordLevelFromReadValue(*password->values[0]);
}

} // namespace

QStringList kindProblems(const DriveDescription &file, const DriveDescription &drive,
                         bool selection)
{
    QStringList problems;
    checkKind(file, drive, selection, problems);
    return problems;
}

DownloadPlan planDownload(const DriveDescription &file, const DriveDescription &drive,
                          const DownloadOptions &options)
{
    DownloadPlan plan;
    plan.forced = options.force;
    checkKind(file, drive, options.selection, plan.problems);
    checkParameters(file, drive, options.selection, plan.problems);
    const std::optional<PasswordLevel> level = levelInForce(drive);
    QStringList outside;
    QList<DownloadItem> late; // limits that may follow from values written before them
    for (const GroupDescription &group : drive.groups) {
        for (const ParameterDescription &parameter : group.parameters) {
            const ParameterDescription *inFile = file.find(parameter.address);
            if (!inFile || !ParameterList::holds(parameter))
                continue;
            const qsizetype before = plan.items.size();
            ParameterPlanner(parameterId(group.id, parameter.number()), parameter, *inFile, options)
                .plan(plan, level, outside);
            if (plan.items.size() == before)
                continue;
            // Seed 002 2.6.2 bit 12: a "write always" value is written by an upload too, as a
            // pointer is that selects what the values after it address (Fr.09, the set
            // pointer): no later write goes out before it is answered.
            const ParameterProperties properties(parameter.properties1, parameter.properties2);
            plan.items.last().order.beforeLater = properties.isWriteAlways();
            if (hasVariableLimits(parameter)) {
                // Its limits may follow from any value before it, and limit a later one.
                plan.items.last().order = WriteOrder{};
                late << plan.items.takeLast();
            }
        }
    }
    plan.items << late;
    if (!outside.isEmpty()) {
        plan.problems << DownloadPlan::tr("%n value(s) outside the drive's limits: %1", nullptr,
                                          int(outside.size()))
                             .arg(listed(outside));
    }
    return plan;
}

int DownloadPlan::valueCount() const
{
    int count = 0;
    for (const DownloadItem &item : items) {
        for (const WriteStep &step : item.change.steps)
            count += item.change.setProgrammable ? std::popcount(unsigned(step.setMask)) : 1;
    }
    return count;
}

QList<DownloadPlan::Line> DownloadPlan::lines(const DriveDescription &drive) const
{
    QList<Line> lines;
    for (const DownloadItem &item : items) {
        const ParameterDescription *parameter = drive.find(item.change.address);
        if (!parameter)
            continue;
        const ParameterFormat format(*parameter);
        for (const WriteStep &step : item.change.steps) {
            QStringList held;
            for (int set = 0; set < kParameterSets; ++set) {
                if (!(step.setMask & (1u << set)))
                    continue;
                const std::optional<qint32> before = item.before[std::size_t(set)];
                held << (before ? format.text(*before) : tr("not read"));
            }
            held.removeDuplicates();
            lines << Line{item.id,
                          item.name,
                          item.change.setProgrammable ? SetList::text(step.setMask) : QString(),
                          held.join(QStringLiteral(" / ")),
                          format.text(step.raw),
                          item.always};
        }
    }
    return lines;
}

QString DownloadPlan::summary() const
{
    QString summary = tr("%n value(s) to write", nullptr, valueCount()) + QStringLiteral(", ")
        + tr("%n unchanged", nullptr, unchanged) + QStringLiteral(", ")
        + tr("%n left", nullptr, int(skipped.size()));
    if (readOnlyDiffering) {
        summary += QStringLiteral("; ")
            + tr("%n read-only value(s) differ and are never written", nullptr, readOnlyDiffering);
    }
    return summary;
}

QString DownloadPlan::text(const DriveDescription &drive) const
{
    QString text;
    for (const Line &line : lines(drive)) {
        text += tr("%1  %2%3: %4 -> %5%6\n")
                    .arg(line.id, line.name,
                         line.sets.isEmpty() ? line.sets : QStringLiteral(", ") + line.sets,
                         line.now, line.then,
                         line.always ? tr("  (always written)") : QString());
    }
    return text;
}

} // namespace DriveDesk
