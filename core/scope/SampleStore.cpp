#include "SampleStore.h"

#include <algorithm>
#include <limits>

namespace DriveDesk {

// Columns rather than an array of ScopeSample: the struct pads to 24 bytes, the columns take 20.
struct SampleStore::Chunk
{
    std::array<qint64, kChunkSize> time;
    std::array<std::array<qint32, kChunkSize>, 2> wide;
    std::array<std::array<qint16, kChunkSize>, 2> narrow;
};

SampleStore::SampleStore() = default;
SampleStore::~SampleStore() = default;
SampleStore::SampleStore(SampleStore &&) noexcept = default;
SampleStore &SampleStore::operator=(SampleStore &&) noexcept = default;

bool SampleStore::append(const ScopeSample &sample)
{
    static_assert(sizeof(Chunk) == 20 * kChunkSize, "a chunk holds 20 bytes a sample, no padding");
    if (m_count > 0 && sample.time < time(m_count - 1))
        return false;
    const qsizetype offset = m_count % kChunkSize;
    if (offset == 0)
        m_chunks.push_back(std::make_shared_for_overwrite<Chunk>());
    Chunk &chunk = *m_chunks.back();
    chunk.time[offset] = sample.time;
    chunk.wide[0][offset] = sample.wide[0];
    chunk.wide[1][offset] = sample.wide[1];
    chunk.narrow[0][offset] = sample.narrow[0];
    chunk.narrow[1][offset] = sample.narrow[1];
    ++m_count;
    return true;
}

void SampleStore::clear()
{
    m_chunks.clear();
    m_chunks.shrink_to_fit();
    m_count = 0;
}

SampleStore SampleStore::share(qsizetype count) const
{
    SampleStore copy;
    copy.m_count = std::clamp<qsizetype>(count, 0, m_count);
    const qsizetype full = copy.m_count / kChunkSize;
    copy.m_chunks.assign(m_chunks.begin(), m_chunks.begin() + full);
    if (const qsizetype rest = copy.m_count % kChunkSize) {
        // This chunk may still be written to: its samples are copied, not shared.
        auto last = std::make_shared_for_overwrite<Chunk>();
        const Chunk &from = *m_chunks[full];
        std::copy_n(from.time.begin(), rest, last->time.begin());
        for (std::size_t column = 0; column < 2; ++column) {
            std::copy_n(from.wide[column].begin(), rest, last->wide[column].begin());
            std::copy_n(from.narrow[column].begin(), rest, last->narrow[column].begin());
        }
        copy.m_chunks.push_back(std::move(last));
    }
    return copy;
}

ScopeSample SampleStore::at(qsizetype index) const
{
    Q_ASSERT(index >= 0 && index < m_count);
    const Chunk &chunk = *m_chunks[index / kChunkSize];
    const qsizetype offset = index % kChunkSize;
    ScopeSample sample;
    sample.time = chunk.time[offset];
    sample.wide = {chunk.wide[0][offset], chunk.wide[1][offset]};
    sample.narrow = {chunk.narrow[0][offset], chunk.narrow[1][offset]};
    return sample;
}

qint64 SampleStore::time(qsizetype index) const
{
    Q_ASSERT(index >= 0 && index < m_count);
    return m_chunks[index / kChunkSize]->time[index % kChunkSize];
}

qint32 SampleStore::value(qsizetype index, int channel) const
{
    Q_ASSERT(index >= 0 && index < m_count);
    Q_ASSERT(channel >= 0 && channel < ScopeSample::kChannelCount);
    const Chunk &chunk = *m_chunks[index / kChunkSize];
    const qsizetype offset = index % kChunkSize;
    return channel < 2 ? chunk.wide[channel][offset] : chunk.narrow[channel - 2][offset];
}

namespace {

template<typename T>
void widen(const T *values, qsizetype count, qint32 &low, qint32 &high)
{
    for (qsizetype i = 0; i < count; ++i) {
        low = std::min<qint32>(low, values[i]);
        high = std::max<qint32>(high, values[i]);
    }
}

} // namespace

std::pair<qint32, qint32> SampleStore::valueRange(int channel, qsizetype begin,
                                                  qsizetype end) const
{
    Q_ASSERT(begin >= 0 && begin < end && end <= m_count);
    Q_ASSERT(channel >= 0 && channel < ScopeSample::kChannelCount);
    qint32 low = std::numeric_limits<qint32>::max();
    qint32 high = std::numeric_limits<qint32>::min();
    while (begin < end) {
        const Chunk &chunk = *m_chunks[begin / kChunkSize];
        const qsizetype offset = begin % kChunkSize;
        const qsizetype count = std::min(end - begin, kChunkSize - offset);
        if (channel < 2)
            widen(chunk.wide[channel].data() + offset, count, low, high);
        else
            widen(chunk.narrow[channel - 2].data() + offset, count, low, high);
        begin += count;
    }
    return {low, high};
}

qsizetype SampleStore::lowerBound(qint64 ms) const
{
    qsizetype first = 0;
    qsizetype length = m_count;
    while (length > 0) {
        const qsizetype half = length / 2;
        if (time(first + half) < ms) {
            first += half + 1;
            length -= half + 1;
        } else {
            length = half;
        }
    }
    return first;
}

qsizetype SampleStore::upperBound(qint64 ms) const
{
    qsizetype first = 0;
    qsizetype length = m_count;
    while (length > 0) {
        const qsizetype half = length / 2;
        if (time(first + half) <= ms) {
            first += half + 1;
            length -= half + 1;
        } else {
            length = half;
        }
    }
    return first;
}

SampleStore::IndexRange SampleStore::indexRange(qint64 fromMs, qint64 toMs) const
{
    if (toMs < fromMs)
        return {};
    return {lowerBound(fromMs), upperBound(toMs)};
}

qsizetype SampleStore::bytesUsed() const
{
    return qsizetype(m_chunks.size() * sizeof(Chunk)
                     + m_chunks.capacity() * sizeof(std::shared_ptr<Chunk>));
}

} // namespace DriveDesk
