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
#include <vector>

#if GRANULAB_HAVE_OPENMP
#include <omp.h>
#endif

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

/// Calls fn(k) once for every k in [0, count), on up to `threads` threads, each thread taking one
/// contiguous run of k (static schedule). Contiguous runs keep a thread on the same items, and so on
/// the same particles' cache lines, from stage to stage: handing items out one by one (a dynamic
/// schedule) made neighbouring tiles alternate between cores, and every step moved their cache lines
/// from one core to the other (docs/physics/dem-threads.md, "Performance"). The calls must be
/// independent and must not throw.
template <class Fn>
void parallelFor(int threads, std::size_t count, Fn&& fn) noexcept {
#if GRANULAB_HAVE_OPENMP
    if (threads > 1 && count > 1) {
        const int team = count < static_cast<std::size_t>(threads) ? static_cast<int>(count) : threads;
        const auto n = static_cast<std::int64_t>(count);
#pragma omp parallel for schedule(static) num_threads(team)
        for (std::int64_t k = 0; k < n; ++k) fn(static_cast<std::size_t>(k));
        return;
    }
#else
    (void)threads;
#endif
    for (std::size_t k = 0; k < count; ++k) fn(k);
}

/// Cuts [0, count) into `parts` contiguous ranges of nearly equal total weight: range k is
/// [cuts[k], cuts[k + 1]), cuts has parts + 1 entries, weights has count entries (>= 0). A range
/// may be empty.
void splitByWeight(const double* weights, std::size_t count, int parts, std::uint32_t* cuts) noexcept;

/// Runs first(k, begin, end) for every range k of `cuts` (parts + 1 entries) on its own thread, waits
/// for all of them, then runs second(k, begin, end) for the same ranges on the same threads: two
/// stages of one parallel region, joined by a barrier (cheaper than two regions, and a thread's
/// second stage finds its own ranges' data in its cache). parts <= 1 runs both on the caller.
template <class First, class Second>
void parallelRanges(int parts, const std::uint32_t* cuts, First&& first, Second&& second) noexcept {
#if GRANULAB_HAVE_OPENMP
    if (parts > 1) {
#pragma omp parallel num_threads(parts)
        {
            const int k = omp_get_thread_num();
            const int team = omp_get_num_threads();  // fewer than asked when the runtime says so
            for (int r = k; r < parts; r += team) first(static_cast<std::size_t>(r), cuts[r], cuts[r + 1]);
#pragma omp barrier
            for (int r = k; r < parts; r += team) second(static_cast<std::size_t>(r), cuts[r], cuts[r + 1]);
        }
        return;
    }
#endif
    for (int r = 0; r < (parts > 1 ? parts : 1); ++r)
        first(static_cast<std::size_t>(r), cuts[r], cuts[r + 1]);
    for (int r = 0; r < (parts > 1 ? parts : 1); ++r)
        second(static_cast<std::size_t>(r), cuts[r], cuts[r + 1]);
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

/// Runs fn(begin, end, part) on the contiguous slot ranges `cuts` (part k: [cuts[k], cuts[k + 1]),
/// on thread k of the team, the same thread that takes range k in parallelRanges). The force split
/// sets the cuts of a step (dem/forces.cpp splitTiles), and predict, correct, the neighbour check
/// and the world corners follow them: each thread then touches in every stage the particles of its
/// own force tiles, whose cache lines stay in its core, instead of a block that half belongs to the
/// other core (docs/physics/dem-threads.md, "Performance"). Without cuts (nullptr), or when they do
/// not cover [0, n) in threads + 1 entries, it is parallelBlocks(threads, n, fn). For elementwise
/// work and exact reductions only, as parallelBlocks.
template <class Fn>
void parallelSlots(int threads, const std::vector<std::uint32_t>* cuts, std::size_t n, Fn&& fn) noexcept {
    if (threads > 1 && cuts != nullptr && cuts->size() == static_cast<std::size_t>(threads) + 1 &&
        cuts->front() == 0 && cuts->back() == n) {
        const std::uint32_t* c = cuts->data();
#if GRANULAB_HAVE_OPENMP
#pragma omp parallel num_threads(threads)
        {
            const int team = omp_get_num_threads();
            for (int r = omp_get_thread_num(); r < threads; r += team)
                fn(std::size_t{c[r]}, std::size_t{c[r + 1]}, static_cast<std::size_t>(r));
        }
#else
        for (int r = 0; r < threads; ++r)
            fn(std::size_t{c[r]}, std::size_t{c[r + 1]}, static_cast<std::size_t>(r));
#endif
        return;
    }
    parallelBlocks(threads, n, fn);
}

/// Largest value of a NaN-propagating maximum: NaN wins, so that a blow-up is seen.
inline double maxOrNaN(double a, double b) noexcept {
    return (b > a || b != b) ? b : a;
}

/// Maximum over the ranges of parallelSlots of fn(begin, end) >= 0 (NaN wins); 0 for n = 0. The
/// maximum is exact, so the result does not depend on the ranges.
template <class Fn>
double parallelMax(int threads, const std::vector<std::uint32_t>* cuts, std::size_t n, Fn&& fn) noexcept {
    constexpr int kMaxBlocks = 64;
    const int team = threads < kMaxBlocks ? threads : kMaxBlocks;
    double partial[kMaxBlocks];
    for (double& p : partial) p = 0;
    parallelSlots(team, cuts, n, [&](std::size_t begin, std::size_t end, std::size_t block) {
        partial[block] = fn(begin, end);
    });
    double m = 0;
    for (int b = 0; b < team; ++b) m = maxOrNaN(m, partial[b]);
    return m;
}

/// Maximum over the blocks of parallelBlocks of fn(begin, end) >= 0 (NaN wins); 0 for n = 0.
template <class Fn>
double parallelMax(int threads, std::size_t n, Fn&& fn) noexcept {
    return parallelMax(threads, nullptr, n, fn);
}

}  // namespace granulab
