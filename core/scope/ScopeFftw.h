#pragma once

#include <fftw3.h>

#include <cstddef>
#include <memory>
#include <type_traits>

// Inside core/scope: what the spectrum takes of FFTW, made cheap to ask for again (docs/scope.md,
// "The spectrum"; docs/performance.md).
namespace DriveDesk::ScopeFftw {

// A plan, shared: one put out of the cache by other sizes stays until its last transform ends.
using Plan = std::shared_ptr<std::remove_pointer_t<fftw_plan>>;

// The in-place plan for `n` real points: for an even n the complex plan of n / 2 points (the
// real bins are unpicked from it, computeScopeSpectrum()), for an odd one the real-to-complex
// plan. Kept for the last few sizes; made, if none is kept, on `values` (allocateBuffer()'d,
// n / 2 + 1 complex numbers long; FFTW_ESTIMATE leaves them alone). Any thread: the planner is
// guarded. Run it with fftw_execute_dft() / fftw_execute_dft_r2c() on any buffer of
// allocateBuffer()'s.
Plan plan(int n, double *values);

struct BufferFree
{
    void operator()(double *memory) const;
};
using Buffer = std::unique_ptr<double[], BufferFree>;

// `count` doubles in FFTW's alignment; on Linux, from 2 MiB up, in whole huge pages
// (adviseHugePages()). Null when there is not the memory.
Buffer allocateBuffer(std::size_t count);

// Fresh memory costs a page fault every 4 KiB, and on a virtual machine a fault is dear: the
// first spectrum of a million points in a program took some 3,900 of them (its 8 MB buffer,
// 4 MB of amplitudes, FFTW's plan), most of its time (docs/performance.md). Transparent huge
// pages, where the kernel gives them to memory that asks (Linux, THP "madvise" or "always"),
// take one fault for 2 MiB. The whole 2 MiB blocks inside [begin, begin + bytes) ask, before
// they are touched; elsewhere this does nothing.
void adviseHugePages(void *begin, std::size_t bytes);

} // namespace DriveDesk::ScopeFftw
