#include "ValueEdits.h"

#include "client/DriveClient.h"
#include "client/ReplyCheck.h"
#include "parameters/ParameterAccess.h"
#include "parameters/ParameterId.h"
#include "parameters/SetList.h"
#include "state/DriveState.h"

#include <QFutureWatcher>

namespace DriveDesk {

ValueEdits::ValueEdits(DriveClient *client, DriveState *state, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_state(state)
{ }

ValueEdits::~ValueEdits() = default;

void ValueEdits::restore(const ParameterDescription &parameter, quint8 setMask,
                         const Values &before, Done done)
{
    apply(parameter, restoringSteps(setMask, before), false, std::move(done));
}

void ValueEdits::apply(const ParameterDescription &parameter, QList<WriteStep> steps, bool reset,
                       Done done)
{
    auto edit = std::make_shared<Edit>();
    for (WriteStep &step : steps) {
        step.setMask = SetList::setsWritten(parameter, step.setMask);
        if (step.reset)
            step.raw = parameter.defaultValue;
    }
    edit->parameter = parameter;
    edit->change.address = parameter.address;
    edit->change.setProgrammable = parameter.isSetProgrammable();
    edit->change.steps = steps;
    edit->judgeReadBack = !readBackMayDiffer(parameter);
    edit->change.readBackShowsWrite = edit->judgeReadBack;
    // A parameter known only by its address (DIN66019 has no metadata) has no limits to judge
    // a value by.
    if (!parameter.name.isEmpty()) {
        edit->change.implausible = [parameter](qint32 value) {
            return implausibleValue(parameter, value);
        };
    }
    edit->done = std::move(done);
    edit->outcome.address = parameter.address;
    edit->outcome.reset = reset;
    edit->outcome.steps = std::move(steps);
    for (const WriteStep &step : std::as_const(edit->outcome.steps)) {
        if (m_state)
            m_state->markPending(parameter.address, step.setMask, step.raw);
        emit pending(parameter.address, step.setMask, step.raw);
    }
    QList<EditPtr> &queue = m_queues[parameter.address];
    queue << edit;
    setRunning(m_running + 1);
    if (queue.size() == 1)
        begin(edit);
}

void ValueEdits::begin(const EditPtr &edit)
{
    // Taken now, not when queued: the edit before it may have changed these values.
    if (m_state) {
        for (int set = 0; set < kParameterSets; ++set)
            edit->outcome.before[std::size_t(set)] = m_state->value(edit->change.address, set);
    }
    if (m_journal && !journal(edit))
        return;
    auto *watcher = new QFutureWatcher<WriteOutcome>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, edit] {
        const QFuture<WriteOutcome> future = watcher->future();
        watcher->deleteLater();
        if (future.resultCount() > 0)
            return finish(edit, future.result());
        // The client went away before the job ran: nothing was sent.
        WriteOutcome outcome;
        outcome.address = edit->change.address;
        outcome.error = tr("the connection to the drive was closed");
        outcome.connectionFailed = true;
        outcome.connectionError = outcome.error;
        for (const WriteStep &step : std::as_const(edit->change.steps))
            outcome.refusedMask |= step.setMask;
        finish(edit, outcome);
    });
    watcher->setFuture(m_client->run(
        std::make_shared<WriteValueJob>(m_client->settings().protocol, edit->change)));
}

void ValueEdits::finish(const EditPtr &edit, const WriteOutcome &written)
{
    EditOutcome &outcome = edit->outcome;
    static_cast<WriteOutcome &>(outcome) = written;
    if (edit->judgeReadBack) {
        for (int set = 0; set < kParameterSets; ++set) {
            const std::optional<qint32> held = outcome.readBack[std::size_t(set)];
            if (held && held != outcome.asked(set))
                outcome.differingMask |= quint8(1u << set);
        }
    }
    QList<EditPtr> &queue = m_queues[outcome.address];
    outcome.superseded = queue.size() > 1;
    queue.removeOne(edit);
    const EditPtr next = queue.value(0);
    if (queue.isEmpty())
        m_queues.remove(outcome.address);
    setRunning(m_running - 1);
    if (m_journal && !edit->journaled.isEmpty())
        m_journal->complete(edit->parameter, edit->journaled, outcome);
    if (m_state)
        m_state->showOutcome(outcome, outcome.superseded);
    emit edited(outcome);
    if (edit->done)
        edit->done(outcome);
    if (next)
        begin(next);
}

bool ValueEdits::journal(const EditPtr &edit)
{
    const quint16 address = edit->change.address;
    const QString id
        = m_state ? m_state->editText(address).id() : ParameterId::hexAddress(address);
    QString error;
    const std::optional<QList<EditJournal::Entry>> entries
        = m_journal->begin(id, edit->parameter, edit->change.steps, edit->outcome.before, &error);
    if (entries) {
        edit->journaled = *entries;
        return true;
    }
    // Nothing is written that the journal could not record.
    quint8 mask = 0;
    for (const WriteStep &step : std::as_const(edit->change.steps))
        mask |= step.setMask ? step.setMask : quint8(1);
    finish(edit, EditJournal::notJournaled(address, mask, error));
    return false;
}

void ValueEdits::setRunning(int count)
{
    if (count == m_running)
        return;
    m_running = count;
    emit runningCountChanged(count);
}

} // namespace DriveDesk
