#include "EditController.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"
#include "parameters/ParameterAccess.h"
#include "parameters/ParameterId.h"

#include <QUndoStack>

namespace DriveDesk {

EditController::EditController(DriveClient *client, ParameterModel *model, QUndoStack *undoStack,
                               QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_edits(new ValueEdits(client, model->state(), this))
{
    connect(m_model, &ParameterModel::valueEdited, this, &EditController::write);
    connect(m_edits, &ValueEdits::runningCountChanged, this, &EditController::updateBusy);
}

EditController::~EditController() = default;

// The rule for what may be written (DriveState::writeRefusal) was applied where the write
// was asked for; the drive's own refusals come back in the outcome.
void EditController::write(quint16 address, quint8 setMask, qint32 raw)
{
    const ParameterDescription *parameter = m_model->state()->parameter(address);
    if (!parameter) {
        emit message(tr("Not written: this drive has no parameter %1")
                         .arg(ParameterId::hexAddress(address)));
        return;
    }
    if (setMask == 0) {
        emit message(tr("%1 not written: no set chosen").arg(m_model->state()->editText(address).id()));
        return;
    }
    m_edits->write(*parameter, setMask, raw,
                   [this](const EditOutcome &outcome) { changeDone(outcome); });
}

void EditController::resetToDefault(quint16 address, quint8 setMask)
{
    const ParameterDescription *parameter = m_model->state()->parameter(address);
    if (!parameter) {
        emit message(
            tr("Not reset: this drive has no parameter %1").arg(ParameterId::hexAddress(address)));
        return;
    }
    if (setMask == 0) {
        emit message(tr("%1 not reset: no set chosen").arg(m_model->state()->editText(address).id()));
        return;
    }
    m_edits->resetToDefault(*parameter, setMask,
                            [this](const EditOutcome &outcome) { changeDone(outcome); });
}

void EditController::changeDone(const EditOutcome &outcome)
{
    const quint16 address = outcome.address;
    const EditText text = m_model->state()->editText(address);
    if (!outcome.anyAcknowledged()) {
        emit message(text.outcome(outcome));
        return;
    }
    const ParameterDescription *parameter = m_model->state()->parameter(address);
    // Writing the earlier value back would not undo what the drive changes itself, and for the
    // password parameter it would send a password that fails and block every older step.
    const bool undoable = !parameter || !readBackMayDiffer(*parameter);
    if (undoable) {
        const auto kind = outcome.reset ? ValueCommand::Kind::ResetToDefault
                                        : ValueCommand::Kind::Write;
        const quint8 done = outcome.acknowledgedMask;
        const qint32 raw = outcome.steps.constFirst().raw;
        m_undoStack->push(new ValueCommand(this, kind, address, done, raw, outcome.before,
                                                commandText(kind, address, done, raw)));
    }
    QString result = text.outcome(outcome);
    if (!undoable)
        result += tr("; the drive changes this value itself, so the write cannot be undone");
    emit message(result);
}

QString EditController::commandText(ValueCommand::Kind kind, quint16 address, quint8 setMask,
                                    qint32 raw) const
{
    const EditText text = m_model->state()->editText(address);
    return kind == ValueCommand::Kind::ResetToDefault
        ? tr("Reset %1 to its default%2").arg(text.id(), text.inSets(setMask))
        : tr("Write %1 = %2%3").arg(text.id(), text.value(raw), text.inSets(setMask));
}

void EditController::perform(ValueCommand *command, ValueCommand::Direction direction)
{
    const bool undo = direction == ValueCommand::Direction::Undo;
    const quint16 address = command->address();
    const EditText text = m_model->state()->editText(address);
    if (undo && command->unknownBeforeMask()) {
        emit message(tr("%1%2: the value before the change is not known, so it stays as it is")
                         .arg(text.id(), text.inSets(command->unknownBeforeMask())));
    }
    // Nothing known to put back: no request.
    if (undo && StateEditor::restoringSteps(command->setMask(), command->before()).isEmpty())
        return;
    const ParameterDescription *parameter = m_model->state()->parameter(address);
    if (!parameter) {
        EditOutcome outcome;
        outcome.address = address;
        outcome.error = tr("this drive has no parameter %1").arg(ParameterId::hexAddress(address));
        return performed(command, command->lifeToken(), direction, outcome);
    }
    auto done = [this, command, alive = command->lifeToken(), direction](const EditOutcome &outcome) {
        performed(command, alive, direction, outcome);
    };
    if (undo) {
        m_edits->restore(*parameter, command->setMask(), command->before(), std::move(done));
        return;
    }
    m_edits->apply(*parameter, command->redoSteps(),
                   command->kind() == ValueCommand::Kind::ResetToDefault, std::move(done));
}

void EditController::performed(ValueCommand *command, const std::weak_ptr<const int> &alive,
                               ValueCommand::Direction direction, const EditOutcome &outcome)
{
    const bool undo = direction == ValueCommand::Direction::Undo;
    const QString what
        = alive.expired() ? m_model->state()->editText(outcome.address).id() : command->text();
    if (outcome.ok()) {
        const QString result = undo ? tr("Undone: %1").arg(what) : tr("Redone: %1").arg(what);
        emit message(result + m_model->state()->editText(outcome.address).readBackNotes(outcome));
        return;
    }
    emit message(undo ? tr("Undo failed: %1: %2").arg(what, outcome.error)
                      : tr("Redo failed: %1: %2").arg(what, outcome.error));
    if (alive.expired() || outcome.acknowledgedMask != 0)
        return;
    // Nothing changed on the drive: put the stack back where the drive is, so that the user
    // can try again, provided the command is still where the step left it.
    const int index = m_undoStack->index();
    if (undo && index < m_undoStack->count() && m_undoStack->command(index) == command) {
        command->skipNext();
        m_undoStack->redo();
    } else if (!undo && index > 0 && m_undoStack->command(index - 1) == command) {
        command->skipNext();
        m_undoStack->undo();
    }
}

QString EditController::readFailure(quint16 address, int set) const
{
    const ParameterDescription *parameter = m_model->state()->parameter(address);
    if (!parameter || set < 0 || set >= kParameterSets)
        return {};
    const int cell = parameter->isSetProgrammable() ? set : 0;
    return m_readFailures.value(quint32(address) << 8 | quint32(cell));
}

void EditController::updateBusy()
{
    const bool busy = m_edits->runningCount() > 0 || m_refresh || m_copy;
    if (busy == m_busy)
        return;
    m_busy = busy;
    emit busyChanged(busy);
}

} // namespace DriveDesk
