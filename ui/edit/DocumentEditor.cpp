#include "DocumentEditor.h"

#include "model/ParameterModel.h"
#include "parameters/ParameterId.h"
#include "parameters/SetList.h"
#include "session/CopySet.h"

#include <QScopedValueRollback>
#include <QUndoStack>

#include <memory>
#include <utility>

namespace DriveDesk {

DocumentEditor::DocumentEditor(ParameterModel *model, QUndoStack *undoStack, QObject *parent)
    : QObject(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_files(model->state())
{
    connect(m_model, &ParameterModel::valueEdited, this, &DocumentEditor::write);
    // Both come after the command's redo() or undo() has put its values into the model.
    connect(m_undoStack, &QUndoStack::indexChanged, this, &DocumentEditor::onIndexChanged);
    m_index = m_undoStack->index();
    connect(m_undoStack, &QUndoStack::cleanChanged, this, &DocumentEditor::onCleanChanged);
}

void DocumentEditor::push(QUndoCommand *command)
{
    const QScopedValueRollback pushing(m_pushing, true);
    m_undoStack->push(command);
}

void DocumentEditor::onIndexChanged(int index)
{
    markChanges();
    const int before = std::exchange(m_index, index);
    if (m_pushing || index == before || m_undoStack->count() == 0)
        return;
    // The status bar's last word was about the change now undone or redone: replace it.
    if (index < before)
        emit message(tr("Undone in the file: %1").arg(m_undoStack->text(index)));
    else
        emit message(tr("Redone in the file: %1").arg(m_undoStack->text(index - 1)));
}

void DocumentEditor::rememberSaved(quint16 address)
{
    if (m_saved.contains(address))
        return;
    ValueCommand::Values values {};
    for (int set = 0; set < kParameterSets; ++set)
        values[std::size_t(set)] = m_model->state()->value(address, set);
    m_saved.insert(address, values);
}

void DocumentEditor::markChanges()
{
    for (auto it = m_saved.cbegin(); it != m_saved.cend(); ++it) {
        const quint16 address = it.key();
        const ParameterDescription *parameter = m_model->state()->parameter(address);
        if (!parameter)
            continue;
        const int cells = parameter->isSetProgrammable() ? kParameterSets : 1;
        quint8 changed = 0;
        quint8 unchanged = 0;
        for (int set = 0; set < cells; ++set) {
            const bool differs = m_model->state()->value(address, set) != it.value()[std::size_t(set)];
            const bool marked = m_model->state()->editState(address, set) == EditState::Changed;
            if (differs && !marked)
                changed |= quint8(1u << set);
            else if (!differs && marked)
                unchanged |= quint8(1u << set);
        }
        if (changed)
            m_model->state()->markChanged(address, changed);
        if (unchanged)
            m_model->state()->clearEditState(address, unchanged);
    }
}

void DocumentEditor::onCleanChanged(bool clean)
{
    if (!clean)
        return;
    // Saved (or undone back to what was saved): the model is what the file holds on disk.
    for (auto it = m_saved.begin(); it != m_saved.end(); ++it) {
        for (int set = 0; set < kParameterSets; ++set)
            it.value()[std::size_t(set)] = m_model->state()->value(it.key(), set);
    }
    markChanges();
}

QUndoCommand *DocumentEditor::makeChange(quint16 address, quint8 *setMask, qint32 raw,
                                         ValueCommand::Kind kind, const QString &text,
                                         QString *refusal, QUndoCommand *parent)
{
    const ParameterDescription *parameter = m_model->state()->parameter(address);
    if (!parameter) {
        *refusal = tr("the file has no parameter %1").arg(ParameterId::hexAddress(address));
        return nullptr;
    }
    *setMask = SetList::setsWritten(*parameter, *setMask);
    if (const QString refused = m_model->state()->writeRefusal(address, *setMask, raw);
        !refused.isEmpty()) {
        *refusal = refused;
        return nullptr;
    }
    bool changes = false;
    for (int set = 0; set < kParameterSets; ++set) {
        if (*setMask & (1u << set))
            changes = changes || m_model->state()->value(address, set) != raw;
    }
    if (!changes) {
        refusal->clear(); // nothing to do, and nothing wrong
        return nullptr;
    }
    rememberSaved(address);
    const bool reset = kind == ValueCommand::Kind::ResetToDefault;
    ValueCommand::Values before {};
    m_files.apply(*parameter, { WriteStep { *setMask, raw, reset } }, reset,
                  [&before](const EditOutcome &outcome) { before = outcome.before; });
    return new ValueCommand(this, kind, address, *setMask, raw, before, text, parent);
}

QString DocumentEditor::commandText(quint16 address, quint8 setMask, qint32 raw) const
{
    const EditText text = m_model->state()->editText(address);
    return tr("Change %1 to %2%3").arg(text.id(), text.value(raw), text.inSets(setMask));
}

void DocumentEditor::perform(ValueCommand *command, ValueCommand::Direction direction)
{
    const ParameterDescription *parameter = m_model->state()->parameter(command->address());
    if (!parameter)
        return;
    if (direction == ValueCommand::Direction::Undo) {
        m_files.restore(*parameter, command->setMask(), command->before());
        return;
    }
    m_files.apply(*parameter, command->redoSteps(),
                  command->kind() == ValueCommand::Kind::ResetToDefault);
}

void DocumentEditor::write(quint16 address, quint8 setMask, qint32 raw)
{
    const EditText text = m_model->state()->editText(address);
    QString refusal;
    QUndoCommand *command = makeChange(
        address, &setMask, raw, ValueCommand::Kind::Write,
        tr("Change %1 to %2%3").arg(text.id(), text.value(raw), text.inSets(setMask)), &refusal);
    if (!command) {
        if (!refusal.isEmpty()) {
            emit message(tr("%1; the file is unchanged").arg(refusal));
        }
        return;
    }
    push(command);
    emit message(tr("%1 = %2 in the file%3; save to keep it")
                     .arg(text.id(), text.value(raw), text.inSets(setMask)));
}

void DocumentEditor::resetToDefault(quint16 address, quint8 setMask)
{
    const ParameterDescription *parameter = m_model->state()->parameter(address);
    if (!parameter) {
        emit message(
            tr("Not reset: the file has no parameter %1").arg(ParameterId::hexAddress(address)));
        return;
    }
    const EditText text = m_model->state()->editText(address);
    QString refusal;
    QUndoCommand *command = makeChange(
        address, &setMask, parameter->defaultValue, ValueCommand::Kind::ResetToDefault,
        tr("Reset %1 to its default%2").arg(text.id(), text.inSets(setMask)), &refusal);
    if (!command) {
        emit message(refusal.isEmpty()
                         ? tr("%1 holds its default already%2").arg(text.id(), text.inSets(setMask))
                         : tr("%1; the file is unchanged").arg(refusal));
        return;
    }
    push(command);
    emit message(tr("%1 reset to its default in the file%2").arg(text.id(), text.inSets(setMask)));
}

void DocumentEditor::copySet(int fromSet, int toSet)
{
    const CopySetPlan plan
        = planCopySet(m_model->state()->description(), fromSet, toSet, m_model->state()->passwordLevel());
    const QString text = tr("Copy set %1 to set %2").arg(fromSet).arg(toSet);
    auto macro = std::make_unique<QUndoCommand>(text);
    QStringList notes;
    int refused = 0;
    for (const CopySetPlan::Item &item : plan.items) {
        quint8 mask = quint8(1u << toSet);
        QString refusal;
        if (!makeChange(item.address, &mask, item.raw, ValueCommand::Kind::Write,
                        commandText(item.address, mask, item.raw), &refusal, macro.get())
            && !refusal.isEmpty())
            ++refused;
    }
    const int copied = macro->childCount();
    if (copied > 0)
        push(macro.release());
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

} // namespace DriveDesk
