#include "ValueReadBatch.h"

#include "client/DriveClient.h"
#include "state/DriveState.h"

namespace DriveDesk {

ValueReadBatch::ValueReadBatch(DriveClient *client, DriveState *state, QList<ValueRead> reads,
                               QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_state(state)
    , m_reads(std::move(reads))
{
    connect(&m_watcher, &QFutureWatcherBase::resultsReadyAt, this, &ValueReadBatch::take);
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &ValueReadBatch::jobFinished);
}

ValueReadBatch::~ValueReadBatch()
{
    if (m_running)
        m_watcher.cancel();
}

void ValueReadBatch::start()
{
    if (m_running)
        return;
    m_running = true;
    emit progress(0, total());
    const auto job = std::make_shared<ReadValuesJob>(m_client->settings().protocol, m_reads);
    m_watcher.setFuture(m_client->run(job));
}

void ValueReadBatch::cancel()
{
    if (!m_running || m_cancelled)
        return;
    m_cancelled = true;
    m_watcher.cancel();
}

void ValueReadBatch::take(int begin, int end)
{
    const QFuture<ValueReading> future = m_watcher.future();
    for (int index = begin; index < end; ++index) {
        const ValueReading reading = future.resultAt(index);
        ++m_done;
        if (reading.value)
            m_state->setValue(reading.read.address, reading.read.set, *reading.value);
        m_summary.add(reading);
    }
    emit progress(m_done, total());
}

void ValueReadBatch::jobFinished()
{
    if (!m_running)
        return;
    m_running = false;
    emit finished();
}

} // namespace DriveDesk
