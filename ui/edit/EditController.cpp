#include "EditController.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"
#include "parameters/ParameterAccess.h"
#include "parameters/ParameterFormat.h"
#include "parameters/ParameterId.h"
#include "parameters/SetList.h"

#include <QUndoStack>

namespace DriveDesk {

EditController::EditController(DriveClient *client, ParameterModel *model, QUndoStack *undoStack,
                               QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_writer(new ValueWriter(client, model, this))
{
    connect(m_model, &ParameterModel::valueEdited, this, &EditController::write);
    connect(m_writer, &ValueWriter::runningCountChanged, this, &EditController::updateBusy);
}

EditController::~EditController() = default;

void EditController::write(quint16 address, quint8 setMask, qint32 raw)
{
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter) {
        emit message(tr("Not written: this drive has no parameter %1")
                         .arg(ParameterId::hexAddress(address)));
        return;
    }
    if (!parameter->isSetProgrammable())
        setMask = 0x01;
    if (setMask == 0) {
        emit message(tr("%1 not written: no set chosen").arg(idOf(address)));
        return;
    }
    m_writer->apply(address, { WriteStep { setMask, raw, false } },
                    [this, setMask, raw](const EditOutcome &outcome) {
                        changeDone(WriteValueCommand::Kind::Write, setMask, raw, outcome);
                    });
}

void EditController::resetToDefault(quint16 address, quint8 setMask)
{
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter) {
        emit message(
            tr("Not reset: this drive has no parameter %1").arg(ParameterId::hexAddress(address)));
        return;
    }
    if (!parameter->isSetProgrammable())
        setMask = 0x01;
    if (setMask == 0) {
        emit message(tr("%1 not reset: no set chosen").arg(idOf(address)));
        return;
    }
    const qint32 defaultValue = parameter->defaultValue;
    m_writer->apply(address, { WriteStep { setMask, 0, true } },
                    [this, setMask, defaultValue](const EditOutcome &outcome) {
                        changeDone(WriteValueCommand::Kind::ResetToDefault, setMask, defaultValue,
                                   outcome);
                    });
}

void EditController::changeDone(WriteValueCommand::Kind kind, quint8 setMask, qint32 raw,
                                const EditOutcome &outcome)
{
    const quint16 address = outcome.address;
    const bool reset = kind == WriteValueCommand::Kind::ResetToDefault;
    if (outcome.acknowledgedMask == 0) {
        emit message(reset ? tr("%1 not reset%2: %3")
                                 .arg(idOf(address), inSets(address, setMask), outcome.error)
                           : tr("%1 = %2 not written%3: %4")
                                 .arg(idOf(address), valueText(address, raw),
                                      inSets(address, setMask), outcome.error));
        return;
    }
    const quint8 done = outcome.acknowledgedMask;
    const ParameterDescription *parameter = m_model->parameter(address);
    // Writing the earlier value back would not undo what the drive changes itself, and for the
    // password parameter it would send a password that fails and block every older step.
    const bool undoable = !parameter || !readBackMayDiffer(*parameter);
    if (undoable) {
        const QString text = reset
            ? tr("Reset %1 to its default%2").arg(idOf(address), inSets(address, done))
            : tr("Write %1 = %2%3")
                  .arg(idOf(address), valueText(address, raw), inSets(address, done));
        m_undoStack->push(
            new WriteValueCommand(this, kind, address, done, raw, outcome.before, text));
    }

    QString result = reset
        ? tr("%1 reset to its default%2").arg(idOf(address), inSets(address, done))
        : tr("%1 = %2 written%3")
              .arg(idOf(address), valueText(address, raw), inSets(address, done));
    if (!outcome.error.isEmpty())
        result += tr("; not%1: %2").arg(inSets(address, outcome.refusedMask), outcome.error);
    if (!outcome.readBackError.isEmpty())
        result += tr("; reading it back failed: %1").arg(outcome.readBackError);
    const QString differences = readBackDifferences(address, done);
    if (!differences.isEmpty())
        result += QStringLiteral("; ") + differences;
    if (!undoable)
        result += tr("; the drive changes this value itself, so the write cannot be undone");
    emit message(result);
}

void EditController::perform(WriteValueCommand *command, Direction direction)
{
    const bool undo = direction == Direction::Undo;
    const quint16 address = command->address();
    if (undo && command->unknownBeforeMask()) {
        emit message(tr("%1%2: the value before the change is not known, so it stays as it is")
                         .arg(idOf(address), inSets(address, command->unknownBeforeMask())));
    }
    const QList<WriteStep> steps = undo ? command->undoSteps() : command->redoSteps();
    if (steps.isEmpty())
        return;
    m_writer->apply(
        address, steps,
        [this, command, alive = command->lifeToken(), direction](const EditOutcome &outcome) {
            performed(command, alive, direction, outcome);
        });
}

void EditController::performed(WriteValueCommand *command, const std::weak_ptr<const int> &alive,
                               Direction direction, const EditOutcome &outcome)
{
    const bool undo = direction == Direction::Undo;
    const QString what = alive.expired() ? idOf(outcome.address) : command->text();
    if (outcome.ok()) {
        QString result = undo ? tr("Undone: %1").arg(what) : tr("Redone: %1").arg(what);
        if (!outcome.readBackError.isEmpty())
            result += tr("; reading it back failed: %1").arg(outcome.readBackError);
        const QString differences = readBackDifferences(outcome.address, outcome.acknowledgedMask);
        if (!differences.isEmpty())
            result += QStringLiteral("; ") + differences;
        emit message(result);
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
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter || set < 0 || set >= kParameterSets)
        return {};
    const int cell = parameter->isSetProgrammable() ? set : 0;
    return m_readFailures.value(quint32(address) << 8 | quint32(cell));
}

QString EditController::idOf(quint16 address) const
{
    const QString id = m_model->indexOf(address).data().toString();
    return id.isEmpty() ? ParameterId::hexAddress(address) : id;
}

QString EditController::valueText(quint16 address, qint32 raw) const
{
    // A password is never repeated in the status bar or the undo history.
    if (address == kPasswordParameterAddress)
        return QStringLiteral("****");
    const ParameterDescription *parameter = m_model->parameter(address);
    if (!parameter)
        return QString::number(raw);
    return ParameterFormat(*parameter).text(raw);
}

QString EditController::inSets(quint16 address, quint8 setMask) const
{
    const ParameterDescription *parameter = m_model->parameter(address);
    if (parameter && !parameter->isSetProgrammable())
        return {};
    // A note in parentheses after the parameter or the value: it takes no part in the
    // sentence's grammar, so every language can append it where the sentence names them.
    return QStringLiteral(" (%1)").arg(SetList::text(setMask));
}

QString EditController::readBackDifferences(quint16 address, quint8 setMask) const
{
    QStringList differences;
    for (int set = 0; set < kParameterSets; ++set) {
        if (!(setMask & (1u << set)) || m_model->editState(address, set) != EditState::Failed)
            continue;
        const std::optional<qint32> held = m_model->value(address, set);
        if (held) {
            differences << tr("the drive holds %1%2")
                               .arg(valueText(address, *held), inSets(address, quint8(1u << set)));
        }
    }
    return differences.join(QStringLiteral(", "));
}

void EditController::updateBusy()
{
    const bool busy = m_writer->runningCount() > 0 || m_refresh || m_copy;
    if (busy == m_busy)
        return;
    m_busy = busy;
    emit busyChanged(busy);
}

} // namespace DriveDesk
