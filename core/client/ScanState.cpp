#include "ScanState.h"

#include "ReplyCheck.h"

#include <QCoreApplication>

#include <algorithm>

namespace DriveDesk {

int ScanGroup::namesToAsk() const
{
    const int numbersLeft = int(description.highestNumber) + 1 - nextNumber;
    const int stillMissing = description.parameterCount - int(parameters.size()) - namesPending;
    return std::max(0, std::min(numbersLeft, stillMissing));
}

ScanParameter &ScanState::parameter(quint8 page, quint8 number)
{
    return groups.at(page).parameters.at(number);
}

void ScanState::rejectImplausibleValues()
{
    for (auto &[page, group] : groups) {
        for (auto &[number, scanned] : group.parameters) {
            if (!scanned.limitsKnown)
                continue;
            ParameterDescription &parameter = scanned.description;
            if (scanned.defaultKnown) {
                const QString why = implausibleValue(parameter, parameter.defaultValue);
                if (!why.isEmpty()) {
                    scanned.errors.append(
                        QCoreApplication::translate("DriveDesk::DriveScanner", "default value: %1")
                            .arg(why));
                    ++scanned.metadataErrors;
                    ++scanned.unanswered;
                    scanned.defaultKnown = false;
                }
            }
            for (int set = 0; set < kParameterSets; ++set) {
                const std::optional<qint32> value = parameter.values[std::size_t(set)];
                if (!value)
                    continue;
                const QString why = implausibleValue(parameter, *value);
                if (why.isEmpty())
                    continue;
                parameter.values[std::size_t(set)] = std::nullopt;
                scanned.errors.append(
                    QCoreApplication::translate("DriveDesk::DriveScanner", "value of set %1: %2")
                        .arg(set)
                        .arg(why));
                ++scanned.unanswered;
            }
        }
    }
}

namespace {

ParameterDescription describeParameter(const ScanParameter &scanned)
{
    ParameterDescription parameter = scanned.description;
    for (const ScanDefinition &definition : scanned.definitions) {
        if (!definition.definition)
            continue;
        PlaintextDefinition plaintext = *definition.definition;
        for (const std::optional<PlaintextEntry> &entry : definition.entries) {
            if (entry)
                plaintext.entries.append(*entry);
        }
        parameter.plaintexts.append(plaintext);
    }
    parameter.error = scanned.errors.join(QStringLiteral("; "));
    return parameter;
}

QString hexAddress(quint16 address)
{
    return QStringLiteral("%1h").arg(address, 4, 16, QLatin1Char('0')).toUpper().replace(
        QLatin1Char('H'), QLatin1Char('h'));
}

// A group whose numbers were walked for its count and that came up short: which addresses
// could not be settled, so that nobody takes the parameters found for all there are.
QString shortfall(const ScanGroup &group)
{
    const int found = int(group.parameters.size());
    const int count = group.description.parameterCount;
    if (!group.walked || group.namesPending > 0 || found >= count)
        return {};
    if (group.unsettled.isEmpty()) {
        return QCoreApplication::translate("DriveDesk::DriveScanner",
                                           "group %1: %2 of %3 parameters found")
            .arg(group.description.id)
            .arg(found)
            .arg(count);
    }
    QStringList addresses;
    for (quint8 number : group.unsettled)
        addresses.append(hexAddress(quint16(group.description.address | number)));
    return QCoreApplication::translate(
               "DriveDesk::DriveScanner",
               "group %1: %2 of %3 parameters found; no answer for %4 (%5)")
        .arg(group.description.id)
        .arg(found)
        .arg(count)
        .arg(addresses.join(QStringLiteral(", ")), group.unsettledReasons.constFirst());
}

// The parameters the line left unread (their own errors say what failed), named so that a read
// whose every group is whole is not taken for the drive's complete truth.
QString unreadParameters(const QStringList &ids)
{
    if (ids.isEmpty())
        return {};
    constexpr qsizetype kNamed = 5;
    QString named = ids.mid(0, kNamed).join(QStringLiteral(", "));
    if (ids.size() > kNamed)
        named += QStringLiteral(", ...");
    const int count = int(ids.size());
    return QCoreApplication::translate("DriveDesk::DriveScanner",
                                       "%n parameter(s) without a valid answer (%1)", nullptr,
                                       count)
        .arg(named);
}

QString summary(const QStringList &problems)
{
    if (problems.size() == 1)
        return problems.first();
    // A named count: lupdate hangs on a cast such as int(...) in translate()'s count argument.
    const int more = int(problems.size()) - 1;
    return QCoreApplication::translate("DriveDesk::DriveScanner", "%1 (and %n more)", nullptr, more)
        .arg(problems.first());
}

} // namespace

DriveDescription ScanState::describe(Language language, const QString &stopReason) const
{
    DriveDescription drive;
    drive.language = int(language);
    drive.identification = identification;

    QStringList shortGroups;
    QStringList unread;
    std::vector<const ScanGroup *> ordered;
    for (const auto &[page, group] : groups)
        ordered.push_back(&group);
    std::stable_sort(ordered.begin(), ordered.end(), [](const ScanGroup *a, const ScanGroup *b) {
        return a->description.index < b->description.index;
    });
    for (const ScanGroup *scanned : ordered) {
        const QString missing = shortfall(*scanned);
        if (!missing.isEmpty())
            shortGroups.append(missing);
        GroupDescription group = scanned->description;
        for (const auto &[number, parameter] : scanned->parameters) {
            group.parameters.append(describeParameter(parameter));
            if (parameter.unanswered > 0)
                unread.append(parameterId(group, group.parameters.constLast()));
        }
        drive.groups.append(group);
    }

    drive.incompleteReason = stopReason;
    // Every group that came up short names its addresses; other problems are summed up.
    QStringList reasons = shortGroups;
    if (!unread.isEmpty())
        reasons.append(unreadParameters(unread));
    if (!problems.isEmpty())
        reasons.append(summary(problems));
    if (drive.incompleteReason.isEmpty())
        drive.incompleteReason = reasons.join(QStringLiteral("; "));
    return drive;
}

QString driveText(const QByteArray &bytes)
{
    const qsizetype end = bytes.indexOf('\0');
    return QString::fromLatin1(end < 0 ? bytes : bytes.left(end));
}

} // namespace DriveDesk
