// SPDX-License-Identifier: MIT
// Shared-memory parallel loops behind one interface (DESIGN.md "MPI and threads each behind one
// interface"; gc2d spec section 5.4, the phases of a step on threads). OpenMP when the build has it
// (GRANULAB_HAVE_OPENMP, CMake option GRANULAB_OPENMP); a serial build runs every loop on the
// calling thread. The callers keep results independent of the thread count: a loop body writes
// only its own items, and sums are formed over pieces whose boundaries do not depend on the
// number of threads (dem's slot tiles), combined in piece order.
#pragma once
#include <cstddef>
#include <cstdint>

namespace granulab {

/// True when this build runs parallel loops on threads.
#if GRANULAB_HAVE_OPENMP
inline constexpr bool kHaveThreads = true;
#else
inline constexpr bool kHaveThreads = false;
#endif

/// Cores this process may run on (its CPU affinity mask; 1 in a serial build).
int availableCores() noexcept;
/// The default thread count of a process (run.threads = 0): availableCores(), or under mpirun
/// with several ranks on this machine (Open MPI's OMPI_COMM_WORLD_LOCAL_SIZE, MPICH's
/// MPI_LOCALNRANKS) the machine's cores divided among them, at most availableCores(): P ranks of
/// T threads then do not oversubscribe the cores, however mpirun bound them.
int defaultThreads() noexcept;

/// Calls fn(k) once for every k in [0, count), on up to `threads` threads, the items handed out
/// one by one as threads become free (dynamic schedule: uneven items balance). The calls must be
/// independent and must not throw.
template <class Fn>
void parallelFor(int threads, std::size_t count, Fn&& fn) noexcept {
#if GRANULAB_HAVE_OPENMP
    if (threads > 1 && count > 1) {
        const int team = count < static_cast<std::size_t>(threads) ? static_cast<int>(count) : threads;
        const auto n = static_cast<std::int64_t>(count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(team)
        for (std::int64_t k = 0; k < n; ++k) fn(static_cast<std::size_t>(k));
        return;
    }
#else
    (void)threads;
#endif
    for (std::size_t k = 0; k < count; ++k) fn(k);
}

/// Smallest block of parallelBlocks: below it a thread costs more than it saves.
inline constexpr std::size_t kMinParallelBlock = 2048;

/// Number of blocks parallelBlocks splits n items into on `threads` threads.
inline std::size_t blockCount(int threads, std::size_t n) noexcept {
    const std::size_t byWork = (n + kMinParallelBlock - 1) / kMinParallelBlock;
    const std::size_t t = threads > 1 ? static_cast<std::size_t>(threads) : 1;
    return byWork < t ? (byWork > 0 ? byWork : 1) : t;
}

/// Splits [0, n) into blockCount(threads, n) equal contiguous blocks and calls fn(begin, end, block)
/// for each on its own thread (static schedule: for even, memory-bound loops). The blocks depend on
/// the thread count: use it for elementwise work and exact reductions (max, min, counts) only.
template <class Fn>
void parallelBlocks(int threads, std::size_t n, Fn&& fn) noexcept {
    const std::size_t blocks = blockCount(threads, n);
    if (blocks <= 1) {
        fn(std::size_t{0}, n, std::size_t{0});
        return;
    }
    const auto run = [&](std::size_t b) { fn(n * b / blocks, n * (b + 1) / blocks, b); };
#if GRANULAB_HAVE_OPENMP
    const auto count = static_cast<std::int64_t>(blocks);
#pragma omp parallel for schedule(static, 1) num_threads(static_cast <int>(blocks))
    for (std::int64_t b = 0; b < count; ++b) run(static_cast<std::size_t>(b));
#else
    for (std::size_t b = 0; b < blocks; ++b) run(b);
#endif
}

/// Largest value of a NaN-propagating maximum: NaN wins, so that a blow-up is seen.
inline double maxOrNaN(double a, double b) noexcept {
    return (b > a || b != b) ? b : a;
}

/// Maximum over the blocks of parallelBlocks of fn(begin, end) >= 0 (NaN wins); 0 for n = 0.
template <class Fn>
double parallelMax(int threads, std::size_t n, Fn&& fn) noexcept {
    constexpr int kMaxBlocks = 64;
    const int team = threads < kMaxBlocks ? threads : kMaxBlocks;
    double partial[kMaxBlocks] = {};
    parallelBlocks(team, n, [&](std::size_t begin, std::size_t end, std::size_t block) {
        partial[block] = fn(begin, end);
    });
    double m = 0;
    for (std::size_t b = 0; b < blockCount(team, n); ++b) m = maxOrNaN(m, partial[b]);
    return m;
}

}  // namespace granulab
