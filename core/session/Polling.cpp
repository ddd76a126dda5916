#include "Polling.h"

#include "client/DriveClient.h"

#include <algorithm>

namespace DriveDesk {

Polling::Polling(DriveClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this, &Polling::poll);
    connect(m_client, &DriveClient::stateChanged, this, &Polling::clientStateChanged);
    connect(&m_round, &QFutureWatcherBase::resultsReadyAt, this, &Polling::take);
    connect(&m_round, &QFutureWatcherBase::finished, this, &Polling::roundDone);
}

Polling::~Polling()
{
    if (m_running)
        m_round.cancel();
}

void Polling::setReads(std::function<QList<ValueRead>()> reads)
{
    m_reads = std::move(reads);
}

void Polling::setIntervalMs(int ms)
{
    m_timer.setInterval(std::clamp(ms, kMinimumIntervalMs, kMaximumIntervalMs));
}

void Polling::setEnabled(bool enabled)
{
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    if (enabled) {
        m_timer.start();
        poll();
    } else {
        m_timer.stop();
        // What is still queued is dropped; the reads on the way come back unreported.
        if (m_running)
            m_round.cancel();
    }
    emit enabledChanged(enabled);
}

void Polling::clientStateChanged()
{
    const DriveClient::State state = m_client->state();
    if (!m_enabled || state == DriveClient::State::Connected
        || state == DriveClient::State::Connecting) {
        return;
    }
    setEnabled(false);
    emit stopped(state == DriveClient::State::Lost);
}

void Polling::poll()
{
    if (!m_enabled || m_client->state() != DriveClient::State::Connected)
        return;
    if (m_running) {
        ++m_skipped;
        return;
    }
    const QList<ValueRead> reads = m_reads ? m_reads() : QList<ValueRead>{};
    if (reads.isEmpty()) {
        emit nothingToRead();
        return;
    }
    m_running = true;
    m_current = Round{};
    m_current.reads = int(reads.size());
    m_round.setFuture(
        m_client->run(std::make_shared<ReadValuesJob>(m_client->settings().protocol, reads)));
}

void Polling::take(int begin, int end)
{
    const QFuture<ValueReading> future = m_round.future();
    for (int index = begin; index < end; ++index) {
        const ValueReading reading = future.resultAt(index);
        if (reading.value)
            emit this->reading(reading);
        m_current.add(reading);
    }
}

void Polling::roundDone()
{
    if (!m_running)
        return;
    m_running = false;
    if (m_round.isCanceled())
        return;
    ++m_rounds;
    emit roundFinished(m_current);
}

} // namespace DriveDesk
