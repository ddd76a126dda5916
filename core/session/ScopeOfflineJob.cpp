#include "ScopeOfflineJob.h"

#include "link/ConnectionSettings.h"
#include "protocol/Codec.h"
#include "scope/ScopeRecording.h"

#include <QCoreApplication>

#include <limits>

namespace DriveDesk {

namespace {

constexpr quint8 kModeOffline = 1;

QString tr(const char *text)
{
    return QCoreApplication::translate("ScopeOfflineJob", text);
}

qint16 clip(qint32 value, bool *clipped)
{
    constexpr qint32 low = std::numeric_limits<qint16>::min();
    constexpr qint32 high = std::numeric_limits<qint16>::max();
    *clipped = *clipped || value < low || value > high;
    return qint16(std::clamp(value, low, high));
}

} // namespace

std::unique_ptr<ScopeRecording> offlineRecording(const ScopeOfflineRecords &records,
                                                 const ScopeChannels &channels,
                                                 const QString &connection)
{
    auto recording = std::make_unique<ScopeRecording>();
    recording->channels = channels;
    recording->source = tr("offline records of %1, one a millisecond assumed").arg(connection);
    recording->started = QDateTime::currentDateTimeUtc();
    for (const ScopeSample &sample : records.samples)
        recording->buffer.append(sample);
    return recording;
}

ScopeOfflineJob::ScopeOfflineJob(qint64 periodMs)
    : m_periodMs(std::max<qint64>(1, periodMs))
{
}

bool ScopeOfflineJob::isCarriedBy(const ConnectionSettings &settings)
{
    return makeCodec(settings.protocol, CodecOptions{settings.hsp5Extensions})
        ->supports(Service::ScopeRecord, Access::Read);
}

void ScopeOfflineJob::start()
{
    if (!sink().supports(Service::ScopeRecord, Access::Read)) {
        m_result.error = tr("This connection cannot read offline records (service 21 needs "
                            "DIN66019II).");
        return finish();
    }
    request(0);
}

void ScopeOfflineJob::stopping()
{
    sink().cancelPending();
}

void ScopeOfflineJob::request(quint16 index)
{
    ScopeRecordData data;
    data.mode = kModeOffline;
    data.index = index;
    sink().submit(Telegram::request(Service::ScopeRecord, Access::Read, data),
                  [this, index](const Reply &reply) { handle(index, reply); });
}

void ScopeOfflineJob::handle(quint16 index, const Reply &reply)
{
    if (isCancelled() || isStopRequested())
        return finish();
    const auto *record = reply.data<ScopeRecordData>();
    if (!record) {
        m_result.error = index == 0 && reply.status == Reply::Status::Refused
                             && reply.ack() == Ack::DataInvalid
                           ? tr("The drive holds no offline records.")
                           : tr("Record %1: %2").arg(index).arg(reply.message());
        return finish();
    }
    if (index == 0) {
        // The answer's timestamp field is the highest index there is.
        m_result.expected = qint64(record->timestamp) + 1;
        m_result.samples.reserve(m_result.expected);
        promise().setProgressRange(0, int(m_result.expected));
    }
    bool clipped = false;
    ScopeSample sample;
    sample.time = qint64(index) * m_periodMs;
    sample.wide = {record->values[0], record->values[1]};
    sample.narrow = {clip(record->values[2], &clipped), clip(record->values[3], &clipped)};
    m_result.clipped += clipped ? 1 : 0;
    m_result.samples.append(sample);
    promise().setProgressValue(int(m_result.samples.size()));
    if (qint64(index) + 1 >= m_result.expected)
        return finish();
    request(quint16(index + 1));
}

void ScopeOfflineJob::finish()
{
    if (hasEnded())
        return;
    promise().addResult(m_result);
    end();
}

} // namespace DriveDesk
