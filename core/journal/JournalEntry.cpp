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
