#include "ScanState.h"

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

    std::vector<const ScanGroup *> ordered;
    for (const auto &[page, group] : groups)
        ordered.push_back(&group);
    std::stable_sort(ordered.begin(), ordered.end(), [](const ScanGroup *a, const ScanGroup *b) {
        return a->description.index < b->description.index;
    });
    for (const ScanGroup *scanned : ordered) {
        GroupDescription group = scanned->description;
        for (const auto &[number, parameter] : scanned->parameters)
            group.parameters.append(describeParameter(parameter));
        drive.groups.append(group);
    }

    drive.incompleteReason = stopReason;
    if (drive.incompleteReason.isEmpty() && !problems.isEmpty())
        drive.incompleteReason = summary(problems);
    return drive;
}

QString driveText(const QByteArray &bytes)
{
    const qsizetype end = bytes.indexOf('\0');
    return QString::fromLatin1(end < 0 ? bytes : bytes.left(end));
}

} // namespace DriveDesk
