// SPDX-License-Identifier: MIT
// Google Benchmark micro-benchmarks of the thread interface's fixed costs (core/parallel.hpp; see
// bench/README.md, "Threads by default (issue 33)"): what one parallel region and one barrier cost
// on this machine, which sets the smallest step that two threads can speed up (docs/physics/
// dem-threads.md, "Performance").
//   BM_ParallelRegion/T    an empty parallelSlots region of T ranges (fork and join: the predict's
//                          and the neighbour check's region);
//   BM_RegionPlusBarrier/T an empty parallelRanges region of T parts (fork, a barrier between its
//                          two stages, join: the force stage's region);
//   BM_PredictLoop/N/T     VelocityVerlet::predict of N disks in T ranges (parallelSlots on the
//                          slot cuts, as in a step): the per-slot stage with the least work.
// Run on an idle machine: `build/bench/granulab_bench --benchmark_filter='Parallel|Barrier|Predict'`.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

#include "core/parallel.hpp"
#include "dem/integrator.hpp"
#include "model/particle_store.hpp"

namespace {

using namespace granulab;

std::vector<std::uint32_t> evenCuts(std::uint32_t n, int parts) {
    std::vector<std::uint32_t> cuts(static_cast<std::size_t>(parts) + 1);
    for (int k = 0; k <= parts; ++k)
        cuts[static_cast<std::size_t>(k)] = n * static_cast<std::uint32_t>(k) / parts;
    return cuts;
}

void BM_ParallelRegion(benchmark::State& state) {
    const int parts = static_cast<int>(state.range(0));
    const auto cuts = evenCuts(static_cast<std::uint32_t>(parts), parts);
    std::array<std::uint32_t, 64> touched{};
    for (auto _ : state) {
        parallelSlots(parts, &cuts, static_cast<std::size_t>(parts),
                      [&](std::size_t, std::size_t, std::size_t k) { touched[k] += 1; });
        benchmark::DoNotOptimize(touched.data());
    }
}
BENCHMARK(BM_ParallelRegion)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime();

void BM_RegionPlusBarrier(benchmark::State& state) {
    const int parts = static_cast<int>(state.range(0));
    const auto cuts = evenCuts(static_cast<std::uint32_t>(parts), parts);
    std::array<std::uint32_t, 64> touched{};
    for (auto _ : state) {
        parallelRanges(
            parts, cuts.data(), [&](std::size_t k, std::uint32_t, std::uint32_t) { touched[k] += 1; },
            [&](std::size_t k, std::uint32_t, std::uint32_t) { touched[k] += 2; });
        benchmark::DoNotOptimize(touched.data());
    }
}
BENCHMARK(BM_RegionPlusBarrier)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime();

void BM_PredictLoop(benchmark::State& state) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const int parts = static_cast<int>(state.range(1));
    model::ParticleStore s;
    s.reserve(n);
    for (std::uint32_t k = 0; k < n; ++k)  // forces stay 0: a uniform drift, the same work per slot
        s.add(k, {1e-3 * k, 0.0}, {1e-3, -1e-3}, 0.0, 0.1, 5e-4, 1e-6, 1e-12, 0, model::kDiskShape);
    const auto cuts = evenCuts(n, parts);
    dem::VelocityVerlet verlet;
    verlet.setThreads(parts);
    verlet.setSlotCuts(&cuts);
    for (auto _ : state) benchmark::DoNotOptimize(verlet.predict(s, 1e-6));
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * n);  // slot-steps/s
}
BENCHMARK(BM_PredictLoop)
    ->ArgsProduct({{2000, 10000, 100000}, {1, 2}})
    ->ArgNames({"n", "threads"})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
