#include "DocumentEditor.h"

#include "DocumentValueCommand.h"

#include "model/ParameterModel.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterId.h"
#include "parameters/PasswordLevel.h"
#include "parameters/SetList.h"
#include "session/CopySet.h"

#include <QUndoStack>

#include <memory>

namespace DriveDesk {

DocumentEditor::DocumentEditor(ParameterModel *model, QUndoStack *undoStack, QObject *parent)
    : QObject(parent)
    , m_model(model)
    , m_undoStack(undoStack)
{
    connect(m_model, &ParameterModel::valueEdited, this, &DocumentEditor::write);
}

QUndoCommand *DocumentEditor::makeChange(quint16 address, quint8 *setMask, qint32 raw,
                                         const QString &text, QString *refusal,
                                         QUndoCommand *parent) const
{
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter) {
        *refusal = tr("the file has no parameter %1").arg(ParameterId::hexAddress(address));
        return nullptr;
    }
    if (!parameter->isSetProgrammable())
        *setMask = 0x01;
    if (*setMask == 0) {
        *refusal = tr("no set chosen");
        return nullptr;
    }
    if (!m_model->isEditable(address)) {
        *refusal = tr("%1 is read-only").arg(idOf(address));
        return nullptr;
    }
    if (const QString problem = ParameterFormat(*parameter).limitsProblem(raw);
        !problem.isEmpty()) {
        *refusal = problem;
        return nullptr;
    }
    DocumentValueCommand::Values before {};
    DocumentValueCommand::Values after {};
    bool changes = false;
    for (int set = 0; set < kParameterSets; ++set) {
        if (!(*setMask & (1u << set)))
            continue;
        before[std::size_t(set)] = m_model->value(address, set);
        after[std::size_t(set)] = raw;
        changes = changes || before[std::size_t(set)] != raw;
    }
    if (!changes) {
        refusal->clear(); // nothing to do, and nothing wrong
        return nullptr;
    }
    return new DocumentValueCommand(m_model, address, *setMask, before, after, text, parent);
}

void DocumentEditor::write(quint16 address, quint8 setMask, qint32 raw)
{
    const quint8 asked = setMask;
    QString refusal;
    QUndoCommand *command
        = makeChange(address, &setMask, raw,
                     tr("Change %1 to %2%3")
                         .arg(idOf(address), valueText(address, raw), inSets(address, setMask)),
                     &refusal);
    if (!command) {
        // The table marked the cells pending: they show the file's value again.
        m_model->clearEditState(address, asked);
        if (!refusal.isEmpty()) {
            emit message(tr("%1 = %2 not changed%3: %4")
                             .arg(idOf(address), valueText(address, raw), inSets(address, setMask),
                                  refusal));
        }
        return;
    }
    m_undoStack->push(command);
    emit message(tr("%1 = %2 in the file%3; save to keep it")
                     .arg(idOf(address), valueText(address, raw), inSets(address, setMask)));
}

void DocumentEditor::resetToDefault(quint16 address, quint8 setMask)
{
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter) {
        emit message(
            tr("Not reset: the file has no parameter %1").arg(ParameterId::hexAddress(address)));
        return;
    }
    QString refusal;
    QUndoCommand *command = makeChange(
        address, &setMask, parameter->defaultValue,
        tr("Reset %1 to its default%2").arg(idOf(address), inSets(address, setMask)), &refusal);
    if (!command) {
        emit message(
            refusal.isEmpty()
                ? tr("%1 holds its default already%2").arg(idOf(address), inSets(address, setMask))
                : tr("%1 not reset%2: %3").arg(idOf(address), inSets(address, setMask), refusal));
        return;
    }
    m_undoStack->push(command);
    emit message(
        tr("%1 reset to its default in the file%2").arg(idOf(address), inSets(address, setMask)));
}

void DocumentEditor::copySet(int fromSet, int toSet)
{
    const CopySetPlan plan
        = planCopySet(m_model->description(), fromSet, toSet, m_model->passwordLevel());
    const QString text = tr("Copy set %1 to set %2").arg(fromSet).arg(toSet);
    auto macro = std::make_unique<QUndoCommand>(text);
    QStringList notes;
    int refused = 0;
    for (const CopySetPlan::Item &item : plan.items) {
        quint8 mask = quint8(1u << toSet);
        QString refusal;
        if (!makeChange(item.address, &mask, item.raw, QString(), &refusal, macro.get())
            && !refusal.isEmpty())
            ++refused;
    }
    const int copied = macro->childCount();
    if (copied > 0)
        m_undoStack->push(macro.release());
    if (plan.locked > 0)
        notes << tr("%n value(s) read-only or locked", nullptr, plan.locked);
    if (plan.unknown > 0)
        notes << tr("%n value(s) of set %1 not known", nullptr, plan.unknown).arg(fromSet);
    if (refused > 0)
        notes << tr("%n value(s) outside the limits", nullptr, refused);
    QString result = copied > 0
        ? tr("Copied %n value(s) from set %1 to set %2 in the file", nullptr, copied)
              .arg(fromSet)
              .arg(toSet)
        : tr("Set %1 and set %2 hold the same values: nothing to copy").arg(fromSet).arg(toSet);
    if (!notes.isEmpty())
        result += tr("; left as they are: %1").arg(notes.join(QStringLiteral(", ")));
    emit message(result);
}

QString DocumentEditor::idOf(quint16 address) const
{
    const QString id = m_model->indexOf(address).data().toString();
    return id.isEmpty() ? ParameterId::hexAddress(address) : id;
}

QString DocumentEditor::valueText(quint16 address, qint32 raw) const
{
    // A password is never repeated in the status bar or the undo history.
    if (address == kPasswordParameterAddress)
        return QStringLiteral("****");
    const ParameterDescription *parameter = m_model->parameter(address);
    return parameter ? ParameterFormat(*parameter).text(raw) : QString::number(raw);
}

QString DocumentEditor::inSets(quint16 address, quint8 setMask) const
{
    const ParameterDescription *parameter = m_model->parameter(address);
    if (parameter && !parameter->isSetProgrammable())
        return {};
    // A note in parentheses after the parameter or the value: it takes no part in the
    // sentence's grammar, so every language can append it where the sentence names them.
    return QStringLiteral(" (%1)").arg(SetList::text(setMask));
}

} // namespace DriveDesk
