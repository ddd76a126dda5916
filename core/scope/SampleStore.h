#pragma once

#include "ScopeSample.h"

#include <memory>
#include <utility>
#include <vector>

namespace DriveDesk {

// The scope's samples in time order, compactly: the time and the raw channels in columns,
// in chunks of kChunkSize samples (20 bytes a sample). A new chunk is added when the last
// is full; samples already stored never move, so appending never copies them.
//
// Single-threaded: written and read from one thread. Whoever polls hands samples over to
// that thread in batches. A store's share() may go to another thread: a full chunk is never
// written again, so the copies share them.
class SampleStore
{
public:
    static constexpr qsizetype kChunkSize = 4096;

    // Half-open [begin, end) of sample indices.
    struct IndexRange
    {
        qsizetype begin = 0;
        qsizetype end = 0;
        qsizetype count() const { return end - begin; }
        bool isEmpty() const { return end <= begin; }
        bool operator==(const IndexRange &) const = default;
    };

    SampleStore();
    ~SampleStore();
    SampleStore(SampleStore &&) noexcept;
    SampleStore &operator=(SampleStore &&) noexcept;

    // Samples must come in time order; one earlier than the last is refused (false). An equal
    // time is kept.
    bool append(const ScopeSample &sample);
    void clear();
    // The first `count` samples (at most count()) as a store of their own, for another thread
    // to read while this one grows: the full chunks shared, the one still filling copied. A
    // pointer a chunk and at most one chunk's samples: cheap for any number of samples.
    SampleStore share(qsizetype count) const;

    qsizetype count() const { return m_count; }
    bool isEmpty() const { return m_count == 0; }

    // 0 <= index < count()
    ScopeSample at(qsizetype index) const;
    qint64 time(qsizetype index) const;
    qint32 value(qsizetype index, int channel) const;
    // The lowest and highest raw value of a channel over [begin, end) (not empty), read along
    // the chunks' columns: a tight loop over contiguous values instead of a chunk lookup per
    // sample (the ends of each pixel column, MinMaxPyramid::minMax()).
    std::pair<qint32, qint32> valueRange(int channel, qsizetype begin, qsizetype end) const;

    // The samples with from <= time <= to, by binary search: O(log count()).
    IndexRange indexRange(qint64 fromMs, qint64 toMs) const;
    // The first index whose time is >= ms (count() if none).
    qsizetype lowerBound(qint64 ms) const;
    // The first index whose time is > ms (count() if none).
    qsizetype upperBound(qint64 ms) const;

    // The heap this store holds: its chunks and the table of them.
    qsizetype bytesUsed() const;

private:
    struct Chunk;
    std::vector<std::shared_ptr<Chunk>> m_chunks;
    qsizetype m_count = 0;
};

} // namespace DriveDesk
