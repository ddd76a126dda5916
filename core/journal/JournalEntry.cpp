#include "JournalEntry.h"

#include <QCoreApplication>

namespace DriveDesk {

namespace {

// The texts' context, as lupdate finds it.
class JournalEntryText
{
    Q_DECLARE_TR_FUNCTIONS(JournalEntryText)
};

} // namespace

QString journalOutcomeName(JournalOutcome outcome)
{
    switch (outcome) {
    case JournalOutcome::Written:
        return QStringLiteral("written");
    case JournalOutcome::Refused:
        return QStringLiteral("refused");
    case JournalOutcome::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

std::optional<JournalOutcome> journalOutcomeFromName(const QString &name)
{
    for (JournalOutcome outcome :
         { JournalOutcome::Unknown, JournalOutcome::Written, JournalOutcome::Refused }) {
        if (journalOutcomeName(outcome) == name)
            return outcome;
    }
    return std::nullopt;
}

QString JournalDrive::name() const
{
    if (!serialNumber.isEmpty())
        return serialNumber;
    if (address)
        return QStringLiteral("%1@%2").arg(link).arg(*address);
    return link;
}

bool JournalDrive::isSameDrive(const JournalDrive &other) const
{
    if (kind != other.kind || softwareVersion != other.softwareVersion
        || serialNumber != other.serialNumber)
        return false;
    return !serialNumber.isEmpty() || (link == other.link && address == other.address);
}

QString JournalEntry::changeText(const QDateTime &now) const
{
    const QDateTime local = time.toLocalTime();
    const QString when = local.date() == now.toLocalTime().date()
        ? local.toString(QStringLiteral("HH:mm"))
        : local.toString(QStringLiteral("yyyy-MM-dd HH:mm"));
    const QString value = readBack.text.isEmpty() ? written.text : readBack.text;
    if (before.text.isEmpty())
        return JournalEntryText::tr("%1 since %2 by %3").arg(value, when, user);
    return JournalEntryText::tr("%1 since %2 by %3, was %4").arg(value, when, user, before.text);
}

QString JournalEntry::outcomeText() const
{
    switch (outcome) {
    case JournalOutcome::Written:
        return JournalEntryText::tr("written");
    case JournalOutcome::Refused:
        return reason.isEmpty() ? JournalEntryText::tr("refused")
                                : JournalEntryText::tr("refused: %1").arg(reason);
    case JournalOutcome::Unknown:
        break;
    }
    return reason.isEmpty() ? JournalEntryText::tr("unknown")
                            : JournalEntryText::tr("unknown: %1").arg(reason);
}

} // namespace DriveDesk
