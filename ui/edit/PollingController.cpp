#include "PollingController.h"

#include "state/DriveState.h"

#include <utility>

namespace DriveDesk {

PollingController::PollingController(DriveClient *client, DriveState *state, QObject *parent)
    : QObject(parent)
    , m_state(state)
    , m_polling(client)
{
    m_polling.setReads([this] { return groupReads(); });
    connect(&m_polling, &Polling::enabledChanged, this, &PollingController::enabledChanged);
    connect(&m_polling, &Polling::reading, this, [this](const ValueReading &reading) {
        m_state->setValue(reading.read.address, reading.read.set, *reading.value);
    });
    connect(&m_polling, &Polling::roundFinished, this, &PollingController::roundDone);
    connect(&m_polling, &Polling::nothingToRead, this, [this] {
        say(tr("Nothing to poll: this drive has no readable values in group %1").arg(m_group));
    });
    connect(&m_polling, &Polling::stopped, this, [this](bool connectionLost) {
        emit message(connectionLost ? tr("Polling stopped: the connection to the drive was lost")
                                    : tr("Polling stopped: disconnected from the drive"));
    });
    auto invalidate = [this] { m_readsValid = false; };
    connect(m_state, &DriveState::reset, this, invalidate);
    connect(m_state, &DriveState::passwordLevelChanged, this, invalidate);
}

void PollingController::setGroup(const QString &groupId)
{
    if (groupId == m_group)
        return;
    m_group = groupId;
    m_readsValid = false;
    m_lastProblem.clear();
}

void PollingController::setEnabled(bool enabled)
{
    if (enabled != m_polling.isEnabled())
        say({});
    m_polling.setEnabled(enabled);
}

QList<ValueRead> PollingController::groupReads()
{
    if (m_readsValid)
        return m_reads;
    m_reads.clear();
    m_readsValid = true;
    const DriveDescription drive = m_state->description();
    if (const GroupDescription *group = drive.findGroup(m_group))
        m_reads = readableValues(*group, m_state->passwordLevel());
    return m_reads;
}

void PollingController::roundDone(const Polling::Round &round)
{
    if (!round.stopReason.isEmpty()) {
        say(tr("Polling: %1").arg(round.stopReason));
    } else if (!round.failures.isEmpty()) {
        const ValueReading &first = round.failures.constFirst();
        const QString id = m_state->editText(first.read.address).id();
        say(tr("Polling: %n value(s) could not be read (first: %1: %2)", nullptr,
               int(round.failures.size()))
                .arg(id, first.reason));
    } else {
        say({});
    }
    emit roundFinished();
}

void PollingController::say(const QString &problem)
{
    if (problem == m_lastProblem)
        return;
    const QString over = std::exchange(m_lastProblem, problem);
    if (!over.isEmpty())
        emit problemOver(over);
    if (!problem.isEmpty())
        emit message(problem);
}

} // namespace DriveDesk
