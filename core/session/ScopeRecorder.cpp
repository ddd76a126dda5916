#include "ScopeRecorder.h"

#include "client/DriveClient.h"
#include "scope/ScopeFileWriter.h"
#include "scope/ScopeRecording.h"

namespace DriveDesk {

namespace {

constexpr qint64 kRateWindowMs = 1000;
// A crash of the program loses at most this much of the file.
constexpr qint64 kFlushIntervalMs = 1000;

} // namespace

ScopeRecorder::ScopeRecorder(DriveClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    m_take.setInterval(kTakeIntervalMs);
    connect(&m_take, &QTimer::timeout, this, &ScopeRecorder::takeSamples);
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &ScopeRecorder::pollingEnded);
}

ScopeRecorder::~ScopeRecorder()
{
    if (m_job)
        m_watcher.cancel();
    closeFile();
}

void ScopeRecorder::start(ScopeRecording *recording, ScopeRecorderOptions options)
{
    if (m_recording || !recording)
        return;
    m_recording = recording;
    m_options = options;
    m_status = ScopeRecorderStatus{};
    m_status.samples = recording->buffer.count();
    m_clock.reset();
    m_rateWindow.clear();
    m_inbox = std::make_shared<ScopeInbox>();
    m_job = std::make_shared<ScopePollJob>(m_inbox, options.polling);
    m_watcher.setFuture(m_client->run(m_job));
    m_take.start();
}

void ScopeRecorder::stop()
{
    if (m_job)
        m_job->requestStop();
}

void ScopeRecorder::takeSamples()
{
    if (!m_recording)
        return;
    const QList<ScopePoll> polls = m_inbox->take(&m_status.counts);
    ScopeBuffer &buffer = m_recording->buffer;
    const qsizetype first = buffer.count();
    bool durationReached = false;
    for (const ScopePoll &poll : polls) {
        const ScopeClock::Tick tick = m_clock.unwrap(poll.timestamp, poll.hostMs);
        if (buffer.count() == 0)
            m_recording->started = QDateTime::currentDateTimeUtc();
        const qint64 firstTime = buffer.count() == 0 ? tick.time : m_recording->firstTime();
        if (m_options.durationMs > 0 && tick.time - firstTime > m_options.durationMs) {
            durationReached = true;
            break;
        }
        const ScopeSample sample{tick.time, poll.wide, poll.narrow};
        if (buffer.repeatsLast(sample))
            ++m_status.repeated;
        else if (!buffer.append(sample))
            ++m_status.discarded;
    }
    const qsizetype added = buffer.count() - first;
    m_status.samples = buffer.count();
    if (!polls.isEmpty())
        updateRate(polls.last().hostMs);
    if (added > 0) {
        writeToFile(first, added);
        emit samplesAppended(first, added);
    }
    emit statusChanged(m_status);
    if (durationReached)
        stop();
}

void ScopeRecorder::updateRate(qint64 hostMs)
{
    m_rateWindow.emplace_back(hostMs, m_status.samples);
    while (m_rateWindow.size() > 2 && hostMs - m_rateWindow[1].first >= kRateWindowMs)
        m_rateWindow.pop_front();
    const auto &[oldestMs, oldestCount] = m_rateWindow.front();
    if (hostMs > oldestMs)
        m_status.rateHz = double(m_status.samples - oldestCount) * 1000.0 / double(hostMs - oldestMs);
    const ScopeBuffer &buffer = m_recording->buffer;
    if (buffer.count() > 1) {
        const qint64 spanMs = m_recording->lastTime() - m_recording->firstTime();
        if (spanMs > 0)
            m_status.averageHz = double(buffer.count() - 1) * 1000.0 / double(spanMs);
    }
}

void ScopeRecorder::writeToFile(qsizetype first, qsizetype count)
{
    if (m_options.filePath.isEmpty() || !m_status.fileError.isEmpty())
        return;
    QString error;
    if (!m_file) {
        m_file = std::make_unique<ScopeFileWriter>();
        if (!m_file->open(m_options.filePath, ScopeFileHeader::of(*m_recording), &error)) {
            m_status.fileError = error;
            m_file.reset();
            return;
        }
        m_sinceFlush.start();
    }
    bool ok = m_file->append(m_recording->buffer.samples(), first, first + count, &error);
    if (ok && m_sinceFlush.elapsed() >= kFlushIntervalMs) {
        ok = m_file->flush(&error);
        m_sinceFlush.start();
    }
    if (!ok) {
        m_status.fileError = error;
        m_file->close();
        m_file.reset();
    }
}

void ScopeRecorder::closeFile()
{
    if (!m_file)
        return;
    QString error;
    if (!m_file->close(&error) && m_status.fileError.isEmpty())
        m_status.fileError = error;
    m_file.reset();
}

void ScopeRecorder::pollingEnded()
{
    if (!m_recording)
        return;
    takeSamples(); // the last ones the job let out
    m_take.stop();
    closeFile();
    emit statusChanged(m_status);
    ScopePollEnd end;
    const QFuture<ScopePollEnd> future = m_watcher.future();
    if (future.resultCount() > 0)
        end = future.result();
    end.counts = m_status.counts;
    m_recording = nullptr;
    m_job.reset();
    m_inbox.reset();
    emit finished(end);
}

} // namespace DriveDesk
