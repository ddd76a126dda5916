#include "PollingController.h"

#include "client/DriveClient.h"
#include "model/ParameterModel.h"

#include <algorithm>

namespace DriveDesk {

PollingController::PollingController(DriveClient *client, ParameterModel *model, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_model(model)
{
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this, &PollingController::poll);
    connect(m_client, &DriveClient::stateChanged, this, &PollingController::clientStateChanged);
    auto invalidate = [this] { m_readsValid = false; };
    connect(m_model, &QAbstractItemModel::modelReset, this, invalidate);
    connect(m_model, &ParameterModel::passwordLevelChanged, this, invalidate);
}

void PollingController::setGroup(const QString &groupId)
{
    if (groupId == m_group)
        return;
    m_group = groupId;
    m_readsValid = false;
    m_lastProblem.clear();
}

void PollingController::setIntervalMs(int ms)
{
    m_timer.setInterval(std::clamp(ms, kMinimumIntervalMs, kMaximumIntervalMs));
}

void PollingController::setEnabled(bool enabled)
{
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    m_lastProblem.clear();
    if (enabled) {
        m_timer.start();
        poll();
    } else {
        m_timer.stop();
        if (m_round)
            m_round->cancel();
    }
    emit enabledChanged(enabled);
}

void PollingController::clientStateChanged()
{
    const DriveClient::State state = m_client->state();
    if (!m_enabled || state == DriveClient::State::Connected
        || state == DriveClient::State::Connecting) {
        return;
    }
    setEnabled(false);
    emit message(state == DriveClient::State::Lost
                     ? tr("Polling stopped: the connection to the drive was lost")
                     : tr("Polling stopped: disconnected from the drive"));
}

QList<ValueRead> PollingController::groupReads()
{
    if (m_readsValid)
        return m_reads;
    m_reads.clear();
    m_readsValid = true;
    const DriveDescription drive = m_model->description();
    const GroupDescription *group = drive.findGroup(m_group);
    if (!group)
        return m_reads;
    m_reads = readableValues(*group, m_model->passwordLevel());
    return m_reads;
}

void PollingController::poll()
{
    if (!m_enabled || m_client->state() != DriveClient::State::Connected)
        return;
    if (m_round) {
        ++m_skipped;
        return;
    }
    const QList<ValueRead> reads = groupReads();
    if (reads.isEmpty()) {
        const QString problem
            = tr("Nothing to poll: this drive has no readable values in group %1").arg(m_group);
        if (problem != m_lastProblem)
            emit message(problem);
        m_lastProblem = problem;
        return;
    }
    m_round = new ValueReadBatch(m_client, m_model, reads, this);
    connect(m_round, &ValueReadBatch::finished, this, &PollingController::roundDone);
    m_round->start();
}

void PollingController::roundDone()
{
    ValueReadBatch *round = m_round;
    m_round = nullptr;
    round->deleteLater();
    if (round->wasCancelled())
        return;
    ++m_rounds;
    QString problem;
    if (!round->stopReason().isEmpty()) {
        problem = tr("Polling: %1").arg(round->stopReason());
    } else if (!round->failures().isEmpty()) {
        const ValueReadBatch::Failure &first = round->failures().constFirst();
        const QString id = m_model->indexOf(first.address).data().toString();
        problem = tr("Polling: %n value(s) could not be read (first: %1: %2)", nullptr,
                     int(round->failures().size()))
                      .arg(id, first.reason);
    }
    if (!problem.isEmpty() && problem != m_lastProblem)
        emit message(problem);
    m_lastProblem = problem;
    emit roundFinished();
}

} // namespace DriveDesk
