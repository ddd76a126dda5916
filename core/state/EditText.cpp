#include "EditText.h"

#include "parameters/ParameterFormat.h"
#include "parameters/PasswordLevel.h"
#include "parameters/SetList.h"
#include "state/ValueEdits.h"

#include <QStringList>

namespace DriveDesk {

EditText::EditText(QString id, const ParameterDescription *parameter)
    : m_id(std::move(id))
    , m_parameter(parameter)
{ }

QString EditText::value(qint32 raw) const
{
    // A password is never repeated in a message or the undo history.
    if (m_parameter && m_parameter->address == kPasswordParameterAddress)
        return QStringLiteral("****");
    return m_parameter ? ParameterFormat(*m_parameter).text(raw) : QString::number(raw);
}

QString EditText::inSets(quint8 setMask) const
{
    if (setMask == 0)
        return QStringLiteral(" (%1)").arg(SetList::standardSetText(0));
    if (m_parameter && !m_parameter->isSetProgrammable())
        return {};
    return QStringLiteral(" (%1)").arg(SetList::text(setMask));
}

QString EditText::outcome(const EditOutcome &outcome) const
{
    const qint32 raw = outcome.steps.isEmpty() ? 0 : outcome.steps.constFirst().raw;
    // Sets refused, and sets whose write got no answer that reading them could not settle.
    const quint8 unknown = outcome.unknownMask();
    const quint8 refused = outcome.refusedMask & quint8(~unknown);
    if (!outcome.anyAcknowledged()) {
        const QString sets = inSets(outcome.askedMask());
        // No answer is not a refusal: without a word of the drive's, nothing says "not".
        if (outcome.anyUnknown() && refused == 0) {
            return outcome.reset
                ? tr("%1 reset%2 unknown: no answer, so whether the drive took it is unknown "
                     "(%3)").arg(m_id, sets, outcome.error)
                : tr("%1 = %2%3 unknown: no answer, so whether the drive took it is unknown "
                     "(%4)").arg(m_id, value(raw), sets, outcome.error);
        }
        const QString text = outcome.reset
            ? tr("%1 not reset%2: %3").arg(m_id, sets, outcome.error)
            : tr("%1 = %2 not written%3: %4").arg(m_id, value(raw), sets, outcome.error);
        return text + readBackNotes(outcome);
    }
    const quint8 acknowledged = outcome.acknowledgedMask;
    const QString sets = inSets(acknowledged);
    QString text = outcome.reset ? tr("%1 reset to its default%2").arg(m_id, sets)
                                 : tr("%1 = %2 written%3").arg(m_id, value(raw), sets);
    if (outcome.confirmedByReadingMask || outcome.activeSetConfirmedByReading)
        text += tr("; its answer was lost, and reading it back showed it taken");
    if (refused)
        text += tr("; not%1: %2").arg(inSets(refused), outcome.error);
    if (unknown) {
        text += tr("; whether the drive took it%1 is unknown: no answer (%2)")
                    .arg(inSets(unknown), outcome.error);
    }
    return text + readBackNotes(outcome);
}

QString EditText::readBackNotes(const EditOutcome &outcome) const
{
    QString text;
    if (!outcome.readBackError.isEmpty())
        text += tr("; reading it back failed: %1").arg(outcome.readBackError);
    QStringList held;
    for (int set = 0; set < kParameterSets; ++set) {
        const std::optional<qint32> value = outcome.readBack[std::size_t(set)];
        if (!(outcome.differingMask & (1u << set)) || !value)
            continue;
        const quint8 mask = outcome.askedMask() == 0 ? 0 : quint8(1u << set);
        held << tr("the drive holds %1%2").arg(this->value(*value), inSets(mask));
    }
    if (!held.isEmpty())
        text += QStringLiteral("; ") + held.join(QStringLiteral(", "));
    return text;
}

} // namespace DriveDesk
