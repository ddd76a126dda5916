#include "ScopeFftw.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace DriveDesk::ScopeFftw {

namespace {

// FFTW's planner keeps global state and is not thread-safe; executing a plan is, also on
// other arrays of the same alignment (fftw_execute_dft(), fftw_execute_dft_r2c()).
//
// Plans are kept by size: planning a transform of a million points costs FFTW its twiddle
// tables (sines and cosines, in fresh memory), as much as the transform or more, and a window
// that follows the view asks for the same size again and again. A plan holds its tables, so
// only the last few sizes are kept.
class PlanCache
{
public:
    static constexpr std::size_t kKept = 4;

    // ScopeFftw::plan().
    Plan plan(int n, double *values)
    {
        Plan evicted; // destroyed after the lock is let go: destroying takes it
        const std::lock_guard lock(m_mutex);
        const auto kept = std::find_if(m_entries.begin(), m_entries.end(),
                                       [n](const Entry &entry) { return entry.n == n; });
        if (kept != m_entries.end()) {
            std::rotate(m_entries.begin(), kept, kept + 1); // the most recent first
            return m_entries.front().plan;
        }
        if (m_entries.size() == kKept) {
            evicted = std::move(m_entries.back().plan);
            m_entries.pop_back();
        }
        auto *complex = reinterpret_cast<fftw_complex *>(values);
        const Plan made(n % 2 == 0
                            ? fftw_plan_dft_1d(n / 2, complex, complex, FFTW_FORWARD, FFTW_ESTIMATE)
                            : fftw_plan_dft_r2c_1d(n, values, complex, FFTW_ESTIMATE),
                        [this](fftw_plan plan) {
                            const std::lock_guard lock(m_mutex);
                            fftw_destroy_plan(plan);
                        });
        m_entries.insert(m_entries.begin(), Entry { n, made });
        return made;
    }

private:
    struct Entry
    {
        int n = 0;
        Plan plan;
    };
    std::mutex m_mutex;
    std::vector<Entry> m_entries; // the most recently used first; destroyed before the mutex
};

PlanCache &planCache()
{
    static PlanCache cache;
    return cache;
}

constexpr std::size_t kHugePage = std::size_t(2) << 20;

} // namespace

void adviseHugePages([[maybe_unused]] void *begin, [[maybe_unused]] std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const auto start = reinterpret_cast<std::uintptr_t>(begin);
    const std::uintptr_t from = (start + kHugePage - 1) & ~std::uintptr_t(kHugePage - 1);
    const std::uintptr_t to = (start + bytes) & ~std::uintptr_t(kHugePage - 1);
    if (to > from)
        madvise(reinterpret_cast<void *>(from), to - from, MADV_HUGEPAGE);
#endif
}

Buffer allocateBuffer(std::size_t count)
{
#ifdef __linux__
    // Under a huge page, small buffers in FFTW's alignment (64 bytes is more than its SIMD
    // wants): a huge page asked for is a whole 2 MiB when first touched.
    const std::size_t needed = count * sizeof(double);
    const std::size_t alignment = needed < kHugePage ? 64 : kHugePage;
    const std::size_t bytes = (needed + alignment - 1) / alignment * alignment;
    auto *memory = static_cast<double *>(std::aligned_alloc(alignment, bytes));
    if (memory && alignment == kHugePage)
        adviseHugePages(memory, bytes);
    return Buffer(memory);
#else
    return Buffer(fftw_alloc_real(count));
#endif
}

void BufferFree::operator()(double *memory) const
{
#ifdef __linux__
    std::free(memory);
#else
    fftw_free(memory);
#endif
}

Plan plan(int n, double *values)
{
    return planCache().plan(n, values);
}

} // namespace DriveDesk::ScopeFftw
